// band_limited.h - random band-limited (L2) radiance for property tests.
#pragma once

#include <array>
#include <random>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"
#include "support/equirect_oracle.h"

namespace shpack_test {

// f_c(w) = sum_i coefficients.c[c][i] Y_i(w), Y from the Legendre route: its radiance
// coefficients are exactly `coefficients` (orthonormality).
struct BandLimitedRadiance {
  shpack::ShL2 coefficients;

  std::array<double, 3> operator()(const shpack::Dir3& d) const;
  RadianceFunction function() const;  // a copy usable as RadianceFunction
};

// Random weights: L00 = 2 sqrt(pi) * (mean in [2, 3]) per channel, and every other
// coefficient +-[0.15, 0.6] with a random sign, independently per channel - so every slot
// differs (a swapped index, axis or channel changes the result) and the function is
// asymmetric in x, y and z. |sum_{i>0} L_i Y_i| <= 8 * 0.6 * 0.63 < 3.1 while the mean is
// >= 2, so it is mostly but not necessarily everywhere positive.
BandLimitedRadiance random_band_limited(std::mt19937_64& rng);

}  // namespace shpack_test
