// removed_flux.h (private) - what taking texels out of a map removes, as a light
// (light_extraction.h): the flux vectors m_c = sum_t e_t,c int_t w dw of the removed excess
// e_t = L_t - fill (exact texel integrals, equirect_integrals.h), and from them the light's
// direction d (unit, along the luminance-weighted m) and irradiance E_c = d . m_c.
#pragma once

#include <array>
#include <cmath>

#include "extraction/equirect_texels.h"
#include "projection/equirect_integrals.h"
#include "shpack/conventions.h"
#include "shpack/light_extraction.h"

namespace shpack::detail {

class RemovedFlux {
 public:
  // Adds one texel's patch with its excess over the fill level, per channel.
  void add(const ThetaIntegrals& row, const LonIntegrals& column, const std::array<double, 3>& excess) {
    const Dir3 w = direction_integral(row, column);
    for (int c = 0; c < 3; ++c)
      flux_[c] = {flux_[c].x + excess[c] * w.x, flux_[c].y + excess[c] * w.y, flux_[c].z + excess[c] * w.z};
    solid_angle_ += row.solid * column.length;
  }

  // The light's direction, irradiance and solid angle; `fallback` is the direction when the
  // luminance-weighted flux vector is 0.
  void finish(const std::array<double, 3>& luminance, const Dir3& fallback, SunLight& light) const {
    Dir3 m{};
    for (int c = 0; c < 3; ++c)
      m = {m.x + luminance[c] * flux_[c].x, m.y + luminance[c] * flux_[c].y, m.z + luminance[c] * flux_[c].z};
    const double length = std::sqrt(dot(m, m));
    light.direction = length > 0 ? Dir3{m.x / length, m.y / length, m.z / length} : fallback;
    for (int c = 0; c < 3; ++c) light.irradiance[c] = dot(light.direction, flux_[c]);
    light.solid_angle = solid_angle_;
  }

 private:
  std::array<Dir3, 3> flux_{};
  double solid_angle_ = 0;
};

}  // namespace shpack::detail
