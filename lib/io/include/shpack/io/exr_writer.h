// exr_writer.h - an RGB float image as an OpenEXR file (`shpack irradiance`): 32-bit float
// R, G, B, ZIP compression, scanlines top to bottom, encoded in memory by OpenEXR and written
// whole by write_file_atomically (atomic_write.h: never half a file, never a planted link).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shpack/io/io_status.h"

namespace shpack::io {

// A float image of any channels, named as `channels` ("R", "G", "B", "A"), interleaved in
// `pixels` (width x height x channels.size() floats, row 0 at the top): lightmaps.
IoStatus write_exr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                   const std::vector<std::string>& channels, const std::vector<float>& pixels);

// `rgb` holds width x height packed RGB floats, row 0 at the top. Errors: InvalidArgument for a
// size that does not match, WriteFailed (OpenEXR's or the file's problem), naming the file.
IoStatus write_exr_rgb(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                       const std::vector<float>& rgb);

}  // namespace shpack::io
