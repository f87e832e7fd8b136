#include "projection/cube_moments.h"

#include <cmath>

namespace shpack::detail {

CubeCorner exact_corner(double a, const CornerRow& row) noexcept {
  const double s_sq = 1.0 + a * a, s = std::sqrt(s_sq), r = std::sqrt(row.q + a * a);
  return {a, s_sq, s, r, a * row.b / r, std::atan(row.b / s)};
}

CubeCorner solid_angle_corner(double a, const CornerRow& row) noexcept {
  const double r = std::sqrt(row.q + a * a);
  return {a, 0.0, 0.0, r, a * row.b / r, 0.0};
}

namespace {

// rho = a1/r1 - a0/r0. If a0, a1 have the same sign the two terms nearly cancel; then
// a1 r0 - a0 r1 = (a1^2 r0^2 - a0^2 r1^2) / (a1 r0 + a0 r1) and
// a1^2 (q + a0^2) - a0^2 (q + a1^2) = q h sigma, a product of like-signed terms
// (h = a1 - a0, sigma = a1 + a0). Otherwise the direct form adds like-signed terms.
double a_over_r_difference(const CubeCorner& c0, const CubeCorner& c1, double q) noexcept {
  const double a0 = c0.a, a1 = c1.a, r0 = c0.r, r1 = c1.r;
  return a0 * a1 > 0.0 ? q * (a1 - a0) * (a1 + a0) / (r0 * r1 * (a1 * r0 + a0 * r1)) : a1 / r1 - a0 / r0;
}

// k = 0, T = atan(X), X = ab/r: atan X1 - atan X0 = atan2(X1 - X0, 1 + X0 X1), valid as
// |X| < 1 on the face (|ab| <= 1 < r), with X1 - X0 = b rho.
double solid_angle_difference(const CubeCorner& c0, const CubeCorner& c1, const CornerRow& row, double rho) noexcept {
  return std::atan2(row.b * rho, 1.0 + c0.x * c1.x);
}

}  // namespace

CubeMoments edge_differences(const CubeCorner& c0, const CubeCorner& c1, const CornerRow& row) noexcept {
  // Notation: q = 1 + b^2 = s_b^2, r_i = sqrt(q + a_i^2), s_i = sqrt(1 + a_i^2),
  // h = a1 - a0, sigma = a1 + a0 (so a1^2 - a0^2 = h sigma, without cancellation).
  const double b = row.b, q = row.q, sb = row.sb;
  const double a0 = c0.a, a1 = c1.a, s0 = c0.s, s1 = c1.s, s0_sq = c0.s_sq, s1_sq = c1.s_sq;
  const double r0 = c0.r, r1 = c1.r;
  const double h = a1 - a0, sigma = a1 + a0;
  const double rho = a_over_r_difference(c0, c1, q);
  const double d_solid = solid_angle_difference(c0, c1, row, rho);

  // k = 1, F_1 = -g(s)/2 with g(s) = atan(b/s)/s. g1 - g0 = delta/s1 - atan(b/s0) ds/(s0 s1)
  // with ds = s1 - s0 = h sigma / (s0 + s1) and delta = atan(b/s1) - atan(b/s0)
  // = atan2(-b ds, s0 s1 + b^2); the two terms have the same sign (both have the sign of
  // -b ds), so they add without cancellation.
  const double ds = h * sigma / (s0 + s1);
  const double t0 = c0.atan_b_over_s;
  const double delta = std::atan2(-b * ds, s0 * s1 + b * b);
  const double d_g = delta / s1 - t0 * ds / (s0 * s1);
  const double d1 = -0.5 * d_g;

  // k = 2, F_2 = -atan(a/s_b)/(2 s_b): atan(a1/s_b) - atan(a0/s_b) = atan2(h s_b, q + a0 a1),
  // and q + a0 a1 >= b^2 >= 0 as |a0 a1| <= 1.
  const double d2 = -std::atan2(h * sb, q + a0 * a1) / (2.0 * sb);

  // k = 3, F_3 = -(a F_1 + b F_2): a1 F_1(a1) - a0 F_1(a0) = a1 dF_1 + h F_1(a0). Every term
  // is O(h); any cancellation between them is bounded, not growing with N.
  const double f1_at_a0 = -0.5 * t0 / s0;
  const double d3 = -(a1 * d1 + h * f1_at_a0) - b * d2;

  // 1/r1 - 1/r0 = (r0 - r1)/(r0 r1) = -h sigma / (r0 r1 (r0 + r1)).
  const double d_inv_r = -h * sigma / (r0 * r1 * (r0 + r1));
  // 1/(s1^2 r1) - 1/(s0^2 r0) = (s0^2 r0 - s1^2 r1) / (s0^2 s1^2 r0 r1), and
  // s0^2 r0 - s1^2 r1 = s0^2 (r0 - r1) + (s0^2 - s1^2) r1 = -h sigma (s0^2/(r0 + r1) + r1).
  const double d_inv_s2r = -h * sigma * (s0_sq / (r0 + r1) + r1) / (s0_sq * s1_sq * r0 * r1);
  // a1/(s1^2 r1) - a0/(s0^2 r0) = a1 [1/(s1^2 r1) - 1/(s0^2 r0)] + h/(s0^2 r0).
  const double d_a_s2r = a1 * d_inv_s2r + h / (s0_sq * r0);

  return {
      d_solid,                                           // 0: atan(ab/r)
      d1,                                                // 1: -atan(b/s_a)/(2 s_a)
      d2,                                                // 2: -atan(a/s_b)/(2 s_b)
      d3,                                                // 3: -(a F_1 + b F_2)
      d_inv_r / 3.0,                                     // 4: 1/(3r)
      -(b / 3.0) * d_inv_s2r,                            // 5: -b/(3 s_a^2 r)
      -rho / (3.0 * q),                                  // 6: -a/(3 s_b^2 r)
      -(b / 3.0) * (2.0 * d_a_s2r + rho / q),            // 7: -(b/3)(2a/(s_a^2 r) + a/(s_b^2 r))
      -(b / 3.0) * (d_a_s2r + 2.0 * rho / q),            // 8: -(b/3)(a/(s_a^2 r) + 2a/(s_b^2 r))
  };
}

double solid_angle_edge_difference(const CubeCorner& c0, const CubeCorner& c1, const CornerRow& row) noexcept {
  return solid_angle_difference(c0, c1, row, a_over_r_difference(c0, c1, row.q));
}

CubeMoments edge_terms(bool exact, std::uint32_t x, std::uint32_t n, const CornerRow& row) noexcept {
  const bool mirrored = x >= first_mirrored_edge(n);
  const std::uint32_t e = mirrored ? n - 1 - x : x;
  const double a0 = cube_corner_coordinate(e, n), a1 = cube_corner_coordinate(e + 1, n);
  CubeMoments d{};
  if (exact) {
    d = edge_differences(exact_corner(a0, row), exact_corner(a1, row), row);
  } else {
    d[0] = solid_angle_edge_difference(solid_angle_corner(a0, row), solid_angle_corner(a1, row), row);
  }
  if (mirrored)
    for (int k = 0; k < kCubeMoments; ++k) d[k] *= kMirrorEdgeSign[k];
  return d;
}

CubeMoments center_moments(double omega, double a, double b) noexcept {
  // The centre direction has local components (a, b, 1)/r; the moments are omega times the
  // direction polynomials of the table in cube_moments.h.
  const double inv_r2 = 1.0 / (1.0 + a * a + b * b), inv_r = std::sqrt(inv_r2);
  const double w1 = omega * inv_r, w2 = omega * inv_r2;
  return {omega,     w1 * a,     w1 * b,     w1, w2 * (a * b), w2 * a, w2 * b,
          w2 * (a * a - 1.0), w2 * (b * b - 1.0)};
}

std::array<double, kShCount> face_basis_integrals(const FaceMap& map, const CubeMoments& m) noexcept {
  // Moment of d_l (l = a, b, n), of d_l d_k (l != k), and Q(l) = moment of d_l^2 - d_n^2.
  auto linear = [&](int l) noexcept { return m[1 + l]; };
  auto product = [&](int l, int k) noexcept {
    const int sum = l + k;  // {a,b} = 1, {a,n} = 2, {b,n} = 3
    return m[3 + sum];
  };
  auto square = [&](int l) noexcept { return l == 2 ? 0.0 : m[7 + l]; };
  const int lx = map.local[0], ly = map.local[1], lz = map.local[2];
  const double sx = map.sign[0], sy = map.sign[1], sz = map.sign[2];
  return {
      m[0],
      sy * linear(ly),
      sz * linear(lz),
      sx * linear(lx),
      sx * sy * product(lx, ly),
      sy * sz * product(ly, lz),
      2.0 * square(lz) - square(lx) - square(ly),
      sx * sz * product(lx, lz),
      square(lx) - square(ly),
  };
}

}  // namespace shpack::detail
