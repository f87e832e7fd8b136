// importance_density.h (private) - the luminance that is:N samples by (sampling_methods.h),
// shared by the sampler (sampling_importance.cpp) and its variance (sampling_variance.cpp).
#pragma once

#include <array>

namespace shpack::detail {

// Rec. ITU-R BT.709 luminance of linear RGB.
inline double luminance(const std::array<double, 3>& rgb) noexcept {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

}  // namespace shpack::detail
