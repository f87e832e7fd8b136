// pixel_encoding.h (private) - undoing the transfer function of integer sRGB pixels.
#pragma once

#include <span>

namespace shpack::io::detail {

// Decodes sRGB-encoded values in place (srgb.h).
void decode_srgb(std::span<float> values) noexcept;

}  // namespace shpack::io::detail
