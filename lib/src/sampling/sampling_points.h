// sampling_points.h (private) - point sets on the unit sphere for the sampling methods.
//
// All of them map the unit square to the sphere by the equal-area map
//   y = 1 - 2 u1,  lon = 2 pi u2,  (x, z) = sqrt(1 - y^2) (cos lon, sin lon)
// (Archimedes: y is uniform on [-1, 1] for a uniform direction), so uniform or
// low-discrepancy points in the square give uniform or low-discrepancy directions.
#pragma once

#include <cstdint>
#include <random>

#include "shpack/conventions.h"

namespace shpack::detail {

// The equal-area map above, for u1, u2 in [0, 1].
Dir3 sphere_point(double u1, double u2) noexcept;

// A double uniform in [0, 1) from the top 53 bits of one 64-bit output.
inline double uniform01(std::mt19937_64& rng) noexcept {
  return static_cast<double>(rng() >> 11) * 0x1p-53;
}

// The 2-D Sobol sequence in 32-bit fixed point: dimension 0 is van der Corput (k with its
// bits reversed), dimension 1 Sobol's second dimension (direction numbers v_1 = 2^31,
// v_{j+1} = v_j ^ (v_j >> 1), from the primitive polynomial x + 1), each XORed with a
// 32-bit digital shift. Every block of 2^m consecutive points starting at a multiple of 2^m
// is a (0, m, 2)-net in base 2, with or without the shift. Valid for k < 2^32.
struct SobolPoint {
  std::uint32_t u1, u2;
};
SobolPoint sobol_point(std::uint32_t k, std::uint32_t shift1, std::uint32_t shift2) noexcept;

// Point k of the N spherical Fibonacci points: y = 1 - (2k + 1)/N, lon = 2 pi frac(k / phi),
// with frac(k / phi) taken from k * 2^64/phi in exact 64-bit wrap-around arithmetic.
Dir3 fibonacci_point(std::uint64_t k, std::uint64_t n) noexcept;

}  // namespace shpack::detail
