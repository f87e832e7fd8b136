// equirect_weights.h (private) - the separable weights of an equirect texel.
//
// Every L2 basis polynomial factors into a function of theta times a function of the
// longitude lon (conventions.h: x = s cos lon, y = mu, z = s sin lon, s = sin theta,
// mu = cos theta), and dw = sin theta dtheta dlon. So the integral of P_i over texel
// (i, j) is (theta integral of row j) x (lon integral of column i), and over a whole row
// it is a sum of five column sums of the row's radiance L:
//
//   S0 = sum L,  Sc = sum L cos lon_m,  Ss = sum L sin lon_m,
//   Sc2 = sum L cos 2lon_m,  Ss2 = sum L sin 2lon_m        (lon_m: column centre)
//
// because each column integral is a combination of 1, cos lon_m, sin lon_m, cos 2lon_m,
// sin 2lon_m with coefficients that are the same for every column (only five of the six
// longitude functions 1, cos, sin, cos^2, sin^2, sin cos are independent). RowWeights
// holds, per row, the coefficient of each column sum in each basis integral
//
//   I0 = k0 S0             I1 = k1 S0            I2 = kx Ss        I3 = kx Sc
//   I4 = kxy Sc            I5 = kxy Ss           I6 = k6_s0 S0 + k6_c2 Sc2
//   I7 = k7 Ss2            I8 = k8_s0 S0 + k8_c2 Sc2
//
// with I_i = integral of P_i (no k_i) over the row.
#pragma once

#include <cstdint>

namespace shpack::detail {

struct RowWeights {
  double k0, k1, kx, kxy, k6_s0, k6_c2, k7, k8_s0, k8_c2;
};

// Closed-form integrals over row j of H rows in an image of W columns (SamplingMethod::Exact).
RowWeights exact_row_weights(std::uint32_t j, std::uint32_t height, std::uint32_t width) noexcept;

// Basis at the texel centre times the exact texel solid angle (SamplingMethod::Center).
RowWeights center_row_weights(std::uint32_t j, std::uint32_t height, std::uint32_t width) noexcept;

// The longitude functions at column i's centre lon_m = (0.5 - (i + 0.5)/W) 2 pi.
struct ColumnTrig {
  double cos1, sin1, cos2, sin2;
};
ColumnTrig column_trig(std::uint32_t i, std::uint32_t width) noexcept;

// x - sin x without cancellation for |x| <= pi (Taylor series, 16 terms, error < 1e-17 x).
double x_minus_sin(double x) noexcept;

}  // namespace shpack::detail
