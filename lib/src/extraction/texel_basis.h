// texel_basis.h (private) - int_t Y_i dw over one equirect texel, i = 0..8, in closed form:
// the projector's row weights (equirect_weights.h) against the texel's own column instead of
// a row's column sums, so that a light's removed SH and the projection of the map are the same
// integrals (project.h, SamplingMethod::Exact).
#pragma once

#include <array>
#include <cstdint>

#include "projection/equirect_weights.h"
#include "shpack/sh_basis.h"

namespace shpack::detail {

// The integrals over the texels of one row, column by column.
class RowBasis {
 public:
  RowBasis(std::uint32_t y, std::uint32_t width, std::uint32_t height)
      : w_(exact_row_weights(y, height, width)), width_(width) {}

  // I_i = k_i int_t P_i with P_i = 1, y, z, x, xy, yz, 3z^2 - 1, xz, x^2 - y^2 (sh_basis.h):
  // z and yz go with sin lon, x and xy with cos lon, the rest with 1, cos 2lon, sin 2lon.
  std::array<double, kShCount> texel(std::uint32_t x) const {
    const ColumnTrig t = column_trig(x, width_);
    const std::array<double, kShCount> p = {w_.k0,
                                            w_.k1,
                                            w_.kx * t.sin1,
                                            w_.kx * t.cos1,
                                            w_.kxy * t.cos1,
                                            w_.kxy * t.sin1,
                                            w_.k6_s0 + w_.k6_c2 * t.cos2,
                                            w_.k7 * t.sin2,
                                            w_.k8_s0 + w_.k8_c2 * t.cos2};
    std::array<double, kShCount> out;
    for (int i = 0; i < kShCount; ++i) out[i] = kBasisScale[i] * p[i];
    return out;
  }

 private:
  RowWeights w_;
  std::uint32_t width_;
};

}  // namespace shpack::detail
