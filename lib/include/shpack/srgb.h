// srgb.h - the sRGB transfer function, for integer images that store sRGB-encoded colour.
//
// SH data is linear radiance (conventions.md section 7): an 8-bit sRGB texel must be
// decoded before projection, and an HDR texel must never be. The decision of which images
// are sRGB-encoded lives in lib/io (map_source.h); this is only the function.
#pragma once

#include <cmath>

namespace shpack {

// The exact sRGB EOTF of IEC 61966-2-1, encoded value in [0, 1] -> linear value in [0, 1]:
// c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055)^2.4. Not the 2.2 power approximation,
// which is up to 10% off in the darks.
inline double srgb_to_linear(double encoded) noexcept {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

// Its inverse, the sRGB encoding of IEC 61966-2-1, linear value in [0, 1] -> encoded value:
// v <= 0.0031308 ? 12.92 v : 1.055 v^(1/2.4) - 0.055 (shpack preview writes sRGB images).
inline double linear_to_srgb(double linear) noexcept {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace shpack
