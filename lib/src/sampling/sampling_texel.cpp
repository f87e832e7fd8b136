#include "sampling/sampling_texel.h"

#include <cmath>

#include "common/angles.h"
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
  const double lon = std::atan2(d.z, d.x);
  const double theta = std::atan2(std::hypot(d.x, d.z), d.y);
  const double u = 0.5 - lon / (2.0 * kPi);
  const double t = theta / kPi;
  return {clamp_index(u * width, width), clamp_index(t * height, height)};
}

namespace detail {

bool TexelReader::read(std::uint32_t x, std::uint32_t y, std::array<double, 3>& rgb) noexcept {
  ImageView texel = image_;
  texel.data = image_.pixel(x, y);
  texel.width = 1;
  texel.height = 1;
  float planes[3];
  TexelCounts one;
  load_row_planes(texel, y, options_, planes, one);
  one.first_nonfinite_x = x;  // the loader numbers texels within the row it is given
  counts_.merge_after(one);
  rgb = {planes[0], planes[1], planes[2]};
  return one.nonfinite == 0 || options_.nonfinite != NonFinite::Error;
}

bool TexelReader::read(const Dir3& d, std::array<double, 3>& rgb) noexcept {
  const EquirectTexel t = equirect_texel(d, image_.width, image_.height);
  return read(t.x, t.y, rgb);
}

}  // namespace detail
}  // namespace shpack
