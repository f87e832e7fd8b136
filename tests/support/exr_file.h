// exr_file.h - float RGB EXR files through OpenImageIO, for tests (independent of shpack_io).
#pragma once

#include <filesystem>
#include <string>

#include "support/rgb_image.h"

namespace shpack_test {

// Reads channels R, G, B of subimage 0 as float. Returns false with `error` set on failure
// (missing file, fewer than 3 channels, ...).
bool read_exr_rgb(const std::filesystem::path& path, RgbImage& out, std::string& error);

// Writes a 32-bit float RGB EXR with lossless ZIP compression.
bool write_exr_rgb(const std::filesystem::path& path, const RgbImage& image, std::string& error);

}  // namespace shpack_test
