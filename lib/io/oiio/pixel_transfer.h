// pixel_transfer.h (OpenImageIO module) - whether an image's integer pixels are sRGB-encoded.
#pragma once

#include <OpenImageIO/imageio.h>

#include <string_view>

namespace shpack::io::detail {

// Floating-point pixels (Radiance .hdr, PFM, float TIFF) are linear radiance and are never
// transformed, whatever colour space the file claims. Integer pixels are sRGB-encoded when
// OpenImageIO says so ("oiio:ColorSpace" = "sRGB"), or when the file is a PNG or JPEG that
// says nothing: both formats are sRGB unless tagged otherwise.
bool srgb_encoded(const OIIO::ImageSpec& spec, std::string_view format_name);

}  // namespace shpack::io::detail
