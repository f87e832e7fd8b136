// sampling.h (private) - random streams and point sets of the bake engine.
//
// Streams are keyed, not shared: stream(seed, effect, probe, light) always yields the same
// numbers whichever thread asks, so the bake is deterministic for any thread count.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "shpack/sh_basis.h"
#include "tracer.h"

namespace shpack::bake {

// SplitMix64 (Steele, Lea, Flood, "Fast Splittable Pseudorandom Number Generators",
// OOPSLA 2014): a 64-bit state advanced by the golden-ratio increment and finalised by a
// bijective mix; passes BigCrush, and cheap to key per probe.
class Rng {
 public:
  Rng() noexcept : Rng(0) {}
  explicit Rng(std::uint64_t key) noexcept : state_(mix(key)) {}
  static std::uint64_t mix(std::uint64_t z) noexcept {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t bits() noexcept {
    state_ += 0x9E3779B97F4A7C15ull;
    return mix(state_);
  }
  // Uniform in [0, 1), 53 random bits.
  double uniform() noexcept { return static_cast<double>(bits() >> 11) * 0x1p-53; }

 private:
  std::uint64_t state_;
};

// The stream of one (effect, probe, light) under the scene's seed.
inline Rng stream(std::uint64_t seed, std::uint64_t effect, std::uint64_t probe, std::uint64_t light) noexcept {
  std::uint64_t key = Rng::mix(seed ^ 0x5eedull);
  key = Rng::mix(key ^ (effect + 1));
  key = Rng::mix(key ^ (probe + 0x100000000ull));
  return Rng(key ^ (light * 0x9E3779B97F4A7C15ull));
}

inline double norm(Vec3d a) noexcept { return std::sqrt(dot(a, a)); }
inline Vec3d vec(Point3 p) noexcept { return {p.x, p.y, p.z}; }
inline Vec3d vec(Dir3 d) noexcept { return {d.x, d.y, d.z}; }

// e1, e2 with (e1, e2, n) right-handed orthonormal, n unit (Duff et al., JCGT 2017).
inline void basis_of(Vec3d n, Vec3d& e1, Vec3d& e2) noexcept {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
  e1 = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  e2 = {b, sign + n.y * n.y * a, -n.y};
}

// The point (u1, u2) of [0, 1)^2 as a direction uniform on the sphere: y = 1 - 2 u1 (equal
// areas in y, Archimedes), phi = 2 pi u2; density kUniformPdf = 1 / (4 pi).
inline constexpr double kUniformPdf = 0.25 / std::numbers::pi;
inline Vec3d uniform_sphere(double u1, double u2) noexcept {
  const double y = 1.0 - 2.0 * u1, phi = 2.0 * std::numbers::pi * u2;
  const double s = std::sqrt(std::fmax(0.0, (1.0 - y) * (1.0 + y)));
  return {s * std::cos(phi), y, s * std::sin(phi)};
}

// Multiple importance sampling of two strategies, one sample from each, by the power
// heuristic (exponent 2; Veach and Guibas, SIGGRAPH 1995): the sample drawn with density
// p_own, where the other strategy has density p_other, weighs w = p_own^2 / (p_own^2 +
// p_other^2). It keeps a rare sample of the broad strategy (a uniform direction that happens
// to hit a small emitter) from adding variance that the narrow one has already removed.
inline double mis_weight(double p_own, double p_other) noexcept {
  return p_own > 0 ? p_own * p_own / (p_own * p_own + p_other * p_other) : 0.0;
}
// w / p_own: what the sample's integrand value is multiplied by.
inline double mis_factor(double p_own, double p_other) noexcept {
  return p_own > 0 ? p_own / (p_own * p_own + p_other * p_other) : 0.0;
}

// A cosine-weighted direction about the unit normal n (Malley's method): pdf cos / pi.
inline Vec3d cosine_direction(Vec3d n, double u1, double u2) noexcept {
  const double r = std::sqrt(u1), phi = 2.0 * std::numbers::pi * u2;
  Vec3d e1, e2;
  basis_of(n, e1, e2);
  return (r * std::cos(phi)) * e1 + (r * std::sin(phi)) * e2 + std::sqrt(1.0 - u1) * n;
}

// acc.c[c][i] += w[c] * Y_i(d).
inline void add_basis(ShL2& acc, Vec3d d, const std::array<double, 3>& w) noexcept {
  const std::array<double, kShCount> y = eval_basis(d.x, d.y, d.z);
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) acc.c[c][i] += w[c] * y[i];
}

}  // namespace shpack::bake
