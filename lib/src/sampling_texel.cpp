#include "sampling_texel.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "shpack/sampling_methods.h"

namespace shpack {
namespace {

// floor(v) as an index in [0, n - 1]; NaN gives 0.
std::uint32_t clamp_index(double v, std::uint32_t n) noexcept {
  const double f = std::floor(v);
  if (!(f > 0.0)) return 0;
  if (f >= static_cast<double>(n - 1)) return n - 1;
  return static_cast<std::uint32_t>(f);
}

}  // namespace

EquirectTexel equirect_texel(const Dir3& d, std::uint32_t width, std::uint32_t height) noexcept {
  // Inverse of conventions.h: lon = (0.5 - u) 2 pi  =>  u = 0.5 - lon / (2 pi);
  // theta = pi t  =>  t = theta / pi. atan2 returns lon in [-pi, pi], theta in [0, pi].
  constexpr double kPi = std::numbers::pi;
  const double lon = std::atan2(d.z, d.x);
  const double theta = std::atan2(std::hypot(d.x, d.z), d.y);
  const double u = 0.5 - lon / (2.0 * kPi);
  const double t = theta / kPi;
  return {clamp_index(u * width, width), clamp_index(t * height, height)};
}

namespace detail {
namespace {

float load_value(const std::byte* p, PixelType type) noexcept {
  if (type == PixelType::F32) {
    float f;
    std::memcpy(&f, p, sizeof f);
    return f;
  }
  std::uint16_t h;
  std::memcpy(&h, p, sizeof h);
  return half_to_float(h);
}

}  // namespace

bool TexelReader::read(std::uint32_t x, std::uint32_t y, std::array<double, 3>& rgb) noexcept {
  const std::byte* p = image_.pixel(x, y);
  const std::int64_t step = pixel_type_size(image_.type);
  const bool colour = image_.channels >= 3;
  bool nonfinite = false, negative = false;
  for (int c = 0; c < 3; ++c) {
    float v = load_value(p + (colour ? c * step : 0), image_.type);
    if (!std::isfinite(v)) {
      nonfinite = true;
      v = 0.0f;
    } else if (v < 0.0f) {
      negative = true;
      if (options_.negative == Negative::Clamp) v = 0.0f;
    }
    counts_.max_value = std::max(counts_.max_value, static_cast<double>(v));
    rgb[c] = v;
  }
  counts_.negative += negative ? 1 : 0;
  if (nonfinite) {
    if (counts_.nonfinite++ == 0) {
      counts_.first_nonfinite_x = x;
      counts_.first_nonfinite_y = y;
    }
    return options_.nonfinite != NonFinite::Error;
  }
  return true;
}

bool TexelReader::read(const Dir3& d, std::array<double, 3>& rgb) noexcept {
  const EquirectTexel t = equirect_texel(d, image_.width, image_.height);
  return read(t.x, t.y, rgb);
}

}  // namespace detail
}  // namespace shpack
