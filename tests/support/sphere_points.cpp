#include "support/sphere_points.h"

#include <cmath>
#include <numbers>

namespace shpack_test {

std::vector<shpack::Dir3> fibonacci_sphere(int n) {
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::vector<shpack::Dir3> out;
  out.reserve(n);
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n;
    const double r = std::sqrt((1.0 - z) * (1.0 + z));
    const double phi = golden_angle * k;
    out.push_back({r * std::cos(phi), r * std::sin(phi), z});
  }
  return out;
}

shpack::Dir3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  for (;;) {
    const double x = g(rng), y = g(rng), z = g(rng);
    const double len = std::sqrt(x * x + y * y + z * z);
    if (len > 1e-3) return {x / len, y / len, z / len};
  }
}

}  // namespace shpack_test
