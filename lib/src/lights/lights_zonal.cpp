// Lights that are zonal about +Y: ambient, hemisphere and the gradient sky (lights.h).
#include <cmath>

#include "common/angles.h"
#include "lights/light_geometry.h"
#include "shpack/lights.h"

namespace shpack {
namespace {

// Adds the zonal function about +Y with moments m_k = 2 pi int_{-1}^{1} f(y) y^k dy, k = 0..2
// (per channel): L_0 = k0 m_0, L_1 = k1 m_1, and, since z^2 and x^2 average to (1 - y^2)/2
// over the azimuth, int f (3z^2 - 1) = int f (x^2 - y^2) = -(1/2)(3 m_2 - m_0).
void add_zonal_y(const std::array<Rgb, 3>& m, ShL2& out) noexcept {
  for (int c = 0; c < kChannelCount; ++c) {
    const double band2 = -0.5 * (3.0 * m[2][c] - m[0][c]);
    out.c[c][0] += kY0 * m[0][c];
    out.c[c][1] += kY1 * m[1][c];
    out.c[c][6] += kY20 * band2;
    out.c[c][8] += kY22 * band2;
  }
}

}  // namespace

Status add_ambient_light(const Rgb& radiance, ShL2& out) noexcept {
  if (!detail::valid_colour(radiance))
    return Status::error(Errc::InvalidArgument, "ambient light: radiance must be finite and >= 0");
  for (int c = 0; c < kChannelCount; ++c) out.c[c][0] += 4.0 * kPi * kY0 * radiance[c];
  return Status::success();
}

Status add_hemisphere_light(const Rgb& sky, const Rgb& ground, ShL2& radiance) noexcept {
  if (!detail::valid_colour(sky) || !detail::valid_colour(ground))
    return Status::error(Errc::InvalidArgument, "hemisphere light: colours must be finite and >= 0");
  // f = sky on (0, 1], ground on [-1, 0): m_0 = 2 pi (sky + ground), m_1 = pi (sky - ground),
  // m_2 = (2 pi / 3)(sky + ground), so 3 m_2 - m_0 = 0 and band 2 vanishes.
  std::array<Rgb, 3> m;
  for (int c = 0; c < kChannelCount; ++c) {
    m[0][c] = 2.0 * kPi * (sky[c] + ground[c]);
    m[1][c] = kPi * (sky[c] - ground[c]);
    m[2][c] = m[0][c] / 3.0;
  }
  add_zonal_y(m, radiance);
  return Status::success();
}

Status add_gradient_sky(const Rgb& zenith, const Rgb& horizon, const Rgb& ground,
                        ShL2& radiance) noexcept {
  if (!detail::valid_colour(zenith) || !detail::valid_colour(horizon) || !detail::valid_colour(ground))
    return Status::error(Errc::InvalidArgument, "gradient sky: colours must be finite and >= 0");
  // f = H + (Z - H) y on [0, 1], G on [-1, 0): int_0^1 y^k dy = 1/(k+1),
  // int_{-1}^0 y^k dy = (-1)^k/(k+1).
  std::array<Rgb, 3> m;
  for (int c = 0; c < kChannelCount; ++c) {
    const double h = horizon[c], slope = zenith[c] - horizon[c], g = ground[c];
    m[0][c] = 2.0 * kPi * (h + slope / 2.0 + g);
    m[1][c] = 2.0 * kPi * (h / 2.0 + slope / 3.0 - g / 2.0);
    m[2][c] = 2.0 * kPi * (h / 3.0 + slope / 4.0 + g / 3.0);
  }
  add_zonal_y(m, radiance);
  return Status::success();
}

}  // namespace shpack
