// exr_decoder.h (private) - OpenEXR files read with OpenEXR's own C++ library: scanline and
// tiled parts (level 0 of a tiled part), every compression OpenEXR has, multi-part files, half,
// float and uint channels, decoded by OpenEXR's global thread pool.
//
// Values arrive as OpenImageIO gave them when it read .exr for shpack: half and float
// exactly, uint as value / (2^32 - 1). Deep parts are described (ImagePart::problem says so)
// but never read; a subsampled channel fails when it is read.
//
// OpenEXR allocates what a header declares: open_exr is to be called only after
// image_open.h's walk of the header has checked it against the file and the budget.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "image_decoder.h"

namespace shpack::io::detail {

// The decoder of `path`, or null with OpenEXR's reason in `error`.
std::unique_ptr<ImageDecoder> open_exr(const std::filesystem::path& path, std::string& error);

}  // namespace shpack::io::detail
