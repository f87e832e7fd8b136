// exr_writer.h - an RGB float image as an OpenEXR file (`shpack irradiance`): 32-bit float
// R, G, B, ZIP compression, scanlines top to bottom, encoded in memory by OpenEXR and written
// whole by write_file_atomically (atomic_write.h: never half a file, never a planted link).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "shpack/io/io_status.h"

namespace shpack::io {

// `rgb` holds width x height packed RGB floats, row 0 at the top. Errors: InvalidArgument for a
// size that does not match, WriteFailed (OpenEXR's or the file's problem), naming the file.
IoStatus write_exr_rgb(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                       const std::vector<float>& rgb);

}  // namespace shpack::io
