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
  explicit Rng(std::uint64_t key) noexcept : state_(mix(key)) {}
  static std::uint64_t mix(std::uint64_t z) noexcept {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1), 53 random bits.
  double uniform() noexcept {
    state_ += 0x9E3779B97F4A7C15ull;
    return static_cast<double>(mix(state_) >> 11) * 0x1p-53;
  }

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

// Strata of the sphere: rows of equal height in y (equal area, Archimedes) times columns
// of equal azimuth; count = rows * columns >= wanted. One jittered direction per stratum,
// each of weight 4 pi / count.
struct SphereStrata {
  int rows = 1, columns = 1;
  explicit SphereStrata(int wanted) noexcept {
    rows = std::max(1, static_cast<int>(std::lround(std::sqrt(wanted / 2.0))));
    columns = std::max(1, (wanted + rows - 1) / rows);
  }
  int count() const noexcept { return rows * columns; }
  double weight() const noexcept { return 4.0 * std::numbers::pi / count(); }
  Vec3d direction(int k, Rng& rng) const noexcept {
    const int row = k / columns, column = k % columns;
    const double y = -1.0 + 2.0 * (row + rng.uniform()) / rows;
    const double phi = 2.0 * std::numbers::pi * (column + rng.uniform()) / columns;
    const double s = std::sqrt(std::fmax(0.0, (1.0 - y) * (1.0 + y)));
    return {s * std::cos(phi), y, s * std::sin(phi)};
  }
};

// A cosine-weighted direction about the unit normal n (Malley's method): pdf cos / pi.
inline Vec3d cosine_direction(Vec3d n, Rng& rng) noexcept {
  const double u1 = rng.uniform(), u2 = rng.uniform();
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
