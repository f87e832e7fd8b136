#include "sampling/sampling_points.h"

#include <cmath>
#include "common/angles.h"

namespace shpack::detail {
namespace {

// 2^64 / phi rounded to an integer (phi = (1 + sqrt 5)/2): frac(k / phi) = (k * this
// mod 2^64) / 2^64, exactly up to the constant's rounding (< 2^-64 k).
constexpr std::uint64_t kInverseGoldenFixed64 = 0x9E3779B97F4A7C15ull;

// Direction at height y in [-1, 1] and longitude lon. sqrt((1 - y)(1 + y)) instead of
// sqrt(1 - y^2): no cancellation near the poles.
Dir3 point_at(double y, double lon) noexcept {
  const double r = std::sqrt((1.0 - y) * (1.0 + y));
  return {r * std::cos(lon), y, r * std::sin(lon)};
}

}  // namespace

Dir3 sphere_point(double u1, double u2) noexcept {
  return point_at(1.0 - 2.0 * u1, 2.0 * kPi * u2);
}

SobolPoint sobol_point(std::uint32_t k, std::uint32_t shift1, std::uint32_t shift2) noexcept {
  std::uint32_t radical = 0, sobol = 0, v = 1u << 31;
  for (std::uint32_t bits = k, bit = 1u << 31; bits != 0; bits >>= 1, bit >>= 1, v ^= v >> 1) {
    if (bits & 1u) {
      radical ^= bit;
      sobol ^= v;
    }
  }
  return {radical ^ shift1, sobol ^ shift2};
}

Dir3 fibonacci_point(std::uint64_t k, std::uint64_t n) noexcept {
  const double y = 1.0 - (2.0 * static_cast<double>(k) + 1.0) / static_cast<double>(n);
  const double frac = static_cast<double>((k * kInverseGoldenFixed64) >> 11) * 0x1p-53;
  return point_at(y, 2.0 * kPi * frac);
}

}  // namespace shpack::detail
