// disc_map.h - equirect maps of bright discs over a smooth sky, and what the test knows of
// each disc it drew, for the light candidate tests (light_candidates.h). Texel integrals come
// from the test support's oracle (Gauss-Legendre, Legendre-recurrence basis), never from
// shpack's projection.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/light_candidates.h"
#include "shpack/sh_basis.h"
#include "support/equirect_oracle.h"
#include "support/rgb_image.h"

namespace shpack_test {

inline constexpr double kDiscDeg = std::numbers::pi / 180;
inline constexpr std::array<double, 3> kDiscLuminance = {0.2126729, 0.7151522, 0.0721750};  // Rec. 709

inline double dot3(const shpack::Dir3& a, const shpack::Dir3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double angle_deg(const shpack::Dir3& a, const shpack::Dir3& b) {
  return std::acos(std::clamp(dot3(a, b) / std::sqrt(dot3(a, a) * dot3(b, b)), -1.0, 1.0)) / kDiscDeg;
}
inline shpack::Dir3 from_angles(double elevation_deg, double lon_deg) {
  const double e = elevation_deg * kDiscDeg, l = lon_deg * kDiscDeg;
  return {std::cos(e) * std::cos(l), std::sin(e), std::cos(e) * std::sin(l)};
}
inline double luminance(const std::array<double, 3>& v) {
  return kDiscLuminance[0] * v[0] + kDiscLuminance[1] * v[1] + kDiscLuminance[2] * v[2];
}

using Sky = std::function<std::array<double, 3>(const shpack::Dir3&)>;

// Brighter and whiter upwards, as the sun tests' sky.
inline std::array<double, 3> smooth_sky(const shpack::Dir3& d) {
  const double up = std::max(0.0, d.y);
  return {0.2 + 0.3 * up, 0.3 + 0.3 * up, 0.5 + 0.3 * up};
}

// A disc of constant radiance (values a float holds exactly, as the map holds them): every
// texel whose centre is within radius_deg of `centre`.
struct Disc {
  shpack::Dir3 centre;
  double radius_deg;
  std::array<double, 3> radiance;
};

// What the test knows of a drawn disc, from the oracle's integrals over its texels t of the
// excess e_t = L - sky_t (sky_t as the map holds it, in float): the flux vectors
// m_c = sum_t e_t,c int_t w dw and the flux Phi_c = sum_t e_t,c Omega_t; d along the
// luminance-weighted m and E_c = d . m_c (light_extraction.h's definitions); the largest
// spread (max - min per channel) of the sky over the texel centres within radius + 4 degrees,
// which covers the ring the fill level is measured on (light_candidates.h, step 4: from
// r + 0.5 to r + 2.5 degrees, r = radius plus half a texel diagonal).
struct DrawnDisc {
  std::vector<shpack::LightTexel> texels;  // row-major
  std::array<shpack::Dir3, 3> flux{};
  std::array<double, 3> excess_flux{}, irradiance{}, spread{};
  shpack::Dir3 direction;
  double solid_angle = 0;
};

struct DiscMap {
  RgbImage image;
  std::vector<DrawnDisc> discs;  // in the order given
};

inline DiscMap draw_discs(std::uint32_t width, std::uint32_t height, const std::vector<Disc>& discs,
                          const Sky& sky = smooth_sky) {
  DiscMap map{RgbImage(width, height), std::vector<DrawnDisc>(discs.size())};
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x) {
      const shpack::Dir3 d = shpack::equirect_direction((x + 0.5) / width, (y + 0.5) / height);
      const std::array<double, 3> s = sky(d);
      for (int c = 0; c < 3; ++c) map.image.at(x, y, c) = static_cast<float>(s[c]);
      for (std::size_t k = 0; k < discs.size(); ++k) {
        const double angle = angle_deg(d, discs[k].centre);
        if (angle > discs[k].radius_deg + 4) continue;
        for (int c = 0; c < 3; ++c) {
          DrawnDisc& drawn = map.discs[k];
          drawn.spread[c] = std::max(drawn.spread[c], std::fabs(s[c] - sky(discs[k].centre)[c]) * 2);
        }
        if (angle > discs[k].radius_deg) continue;
        DrawnDisc& drawn = map.discs[k];
        drawn.texels.push_back({x, y});
        // int_t Y_i: Y_0 = k0, (Y_3, Y_1, Y_2) = k1 (x, y, z), so Omega_t and int_t w dw.
        const std::array<double, 9> b = texel_basis_integral(x, y, width, height);
        const double omega = b[0] / shpack::kY0;
        const shpack::Dir3 w = {b[3] / shpack::kY1, b[1] / shpack::kY1, b[2] / shpack::kY1};
        drawn.solid_angle += omega;
        for (int c = 0; c < 3; ++c) {
          const double e = discs[k].radiance[c] - static_cast<double>(map.image.at(x, y, c));
          drawn.flux[c] = {drawn.flux[c].x + e * w.x, drawn.flux[c].y + e * w.y, drawn.flux[c].z + e * w.z};
          drawn.excess_flux[c] += e * omega;
          map.image.at(x, y, c) = static_cast<float>(discs[k].radiance[c]);
        }
      }
    }
  for (DrawnDisc& drawn : map.discs) {
    shpack::Dir3 m{};
    for (int c = 0; c < 3; ++c)
      m = {m.x + kDiscLuminance[c] * drawn.flux[c].x, m.y + kDiscLuminance[c] * drawn.flux[c].y,
           m.z + kDiscLuminance[c] * drawn.flux[c].z};
    const double length = std::sqrt(dot3(m, m));
    drawn.direction = {m.x / length, m.y / length, m.z / length};
    for (int c = 0; c < 3; ++c) drawn.irradiance[c] = dot3(drawn.direction, drawn.flux[c]);
  }
  return map;
}

}  // namespace shpack_test
