#include "support/band_limited.h"

#include <cmath>
#include <numbers>

#include "support/sh_oracle.h"

namespace shpack_test {

std::array<double, 3> BandLimitedRadiance::operator()(const shpack::Dir3& d) const {
  const std::array<double, 9> y = unity_basis_slow(d.x, d.y, d.z);
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) out[c] += coefficients.c[c][i] * y[i];
  return out;
}

RadianceFunction BandLimitedRadiance::function() const {
  return [copy = *this](const shpack::Dir3& d) { return copy(d); };
}

BandLimitedRadiance random_band_limited(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mean(2.0, 3.0), mag(0.15, 0.6);
  std::bernoulli_distribution sign(0.5);
  BandLimitedRadiance f;
  for (int c = 0; c < 3; ++c) {
    f.coefficients.c[c][0] = 2.0 * std::sqrt(std::numbers::pi) * mean(rng);
    for (int i = 1; i < 9; ++i) f.coefficients.c[c][i] = (sign(rng) ? 1.0 : -1.0) * mag(rng);
  }
  return f;
}

}  // namespace shpack_test
