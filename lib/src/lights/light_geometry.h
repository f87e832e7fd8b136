// light_geometry.h (private) - vectors, parameter checks and moments -> SH for lights_*.cpp.
#pragma once

#include <array>
#include <cmath>

#include "shpack/lights.h"
#include "shpack/vec3.h"

namespace shpack::detail {

inline double length(Vec3 a) noexcept { return std::hypot(a.x, a.y, a.z); }
constexpr Vec3 vec(Point3 p) noexcept { return {p.x, p.y, p.z}; }

inline bool finite(Vec3 a) noexcept {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

// A colour must be finite and >= 0 in every channel.
inline bool valid_colour(const Rgb& c) noexcept {
  for (const double v : c)
    if (!(std::isfinite(v) && v >= 0)) return false;
  return true;
}

// Unit vector along d; false for a zero, overflowing or non-finite d.
inline bool normalised(Vec3 d, Vec3& unit) noexcept {
  if (!finite(d)) return false;
  const double len = length(d);
  if (!(len > 0) || !std::isfinite(len)) return false;
  unit = (1.0 / len) * d;
  return true;
}

// Adds scale[c] * g_l * Y_i(d) (a zonal function about d, rotated there [1] of lights.h):
// g holds the per-band factors g_0, g_1, g_2.
inline void add_zonal(Vec3 d, const Rgb& scale, const std::array<double, 3>& g, ShL2& out) noexcept {
  const std::array<double, kShCount> y = eval_basis(d.x, d.y, d.z);
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) out.c[c][i] += scale[c] * g[kBand[i]] * y[i];
}

// The moments of a region A of the sphere: solid angle, int_A w dw and the symmetric
// int_A w w^T dw (m2[r][s]).
struct SphereMoments {
  double solid_angle = 0;
  Vec3 first;
  std::array<std::array<double, 3>, 3> second{};
};

// L_i = L int_A Y_i dw from the moments: Y_i = k_i P_i with P_i of degree <= 2 (sh_basis.h),
// and 3z^2 - 1 integrates to 3 M_zz - Omega.
inline void add_moments(const SphereMoments& m, const Rgb& radiance, ShL2& out) noexcept {
  const auto& s = m.second;
  const std::array<double, kShCount> p = {m.solid_angle, m.first.y, m.first.z, m.first.x, s[0][1],
                                          s[1][2], 3.0 * s[2][2] - m.solid_angle, s[0][2],
                                          s[0][0] - s[1][1]};
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) out.c[c][i] += radiance[c] * kBasisScale[i] * p[i];
}

}  // namespace shpack::detail
