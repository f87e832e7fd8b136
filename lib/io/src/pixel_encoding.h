// pixel_encoding.h (private) - which transfer function an image's pixels carry.
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <span>
#include <string_view>

namespace shpack::io::detail {

enum class Transfer : std::uint8_t { Linear, Srgb };

// Floating-point pixels (EXR, Radiance .hdr, PFM, float TIFF) are linear radiance and are
// never transformed, whatever colour space the file claims. Integer pixels are sRGB-encoded
// when OpenImageIO says so ("oiio:ColorSpace" = "sRGB"), or when the file is a PNG or JPEG
// that says nothing: both formats are sRGB unless tagged otherwise.
Transfer pixel_transfer(const OIIO::ImageSpec& spec, std::string_view format_name);

// Decodes sRGB-encoded values in place (srgb.h).
void decode_srgb(std::span<float> values) noexcept;

}  // namespace shpack::io::detail
