// cube_moments.h (private) - exact integrals of the L2 basis over cube-map texels.
//
// Geometry (conventions.h, kCubeFaceAxes). On a face with axes U, V and normal N, the point
// p = N + a U + b V, (a, b) in [-1, 1]^2, has the direction d = p / r, r = sqrt(1 + a^2 + b^2).
// Its solid-angle element is dw = da db / r^3: the area da db, foreshortened by cos = 1/r,
// over the squared distance r^2. Texel (x, y) of an N x N face covers [a_x, a_x+1] x
// [b_y, b_y+1] with the corner coordinates a_i = b_i = (2i - N)/N.
//
//            a = -1          a = +1
//   b = -1    +-----+-----+-----+     row y = 0 at the top, column x = 0 at the left.
//             |     |     |     |     The local components of d are d_a = a/r, d_b = b/r,
//             +-----+-----+-----+     d_n = 1/r, and the world direction is
//             |     | x,y |     |     d_a U + d_b V + d_n N. U, V, N are signed coordinate
//             +-----+-----+-----+     axes, so each world coordinate is one local
//             |     |     |     |     component with a sign (FaceMap below).
//   b = +1    +-----+-----+-----+
//
// Homogenisation. A basis polynomial of degree l is a homogeneous polynomial on the unit
// sphere once its constant is written as |d|^2 = 1 (3z^2 - 1 = 2z^2 - x^2 - y^2). Then
// P(d) = P(p) / r^l and   int_texel P dw = int int P(a, b, 1) / r^(3 + l) da db.
// Nine local moments span all that the L2 basis needs on any face:
//
//   k  integrand       local meaning      antiderivative F_k(a, b), d2F_k/(da db) = integrand
//   0  1/r^3           1 (solid angle)    T = atan(ab / r)
//   1  a/r^4           d_a                -atan(b/s_a) / (2 s_a)          s_a = sqrt(1 + a^2)
//   2  b/r^4           d_b                -atan(a/s_b) / (2 s_b)          s_b = sqrt(1 + b^2)
//   3  1/r^4           d_n                -(a F_1 + b F_2)
//   4  ab/r^5          d_a d_b            1 / (3r)
//   5  a/r^5           d_a d_n            -b / (3 s_a^2 r)
//   6  b/r^5           d_b d_n            -a / (3 s_b^2 r)
//   7  (a^2 - 1)/r^5   d_a^2 - d_n^2      -(ab / 3r) (2/s_a^2 + 1/s_b^2)
//   8  (b^2 - 1)/r^5   d_b^2 - d_n^2      -(ab / 3r) (1/s_a^2 + 2/s_b^2)
//
// and a texel's moment is F(a1,b1) - F(a0,b1) - F(a1,b0) + F(a0,b0). Derivations (inner
// integral over a at fixed b, c^2 = 1 + b^2, so r^2 = c^2 + a^2; then over b):
//  0: the corner formula of conventions.md. With X = ab/r, dX/da = b c^2 / r^3 and
//     r^2 + a^2 b^2 = s_a^2 c^2, so dT/da = b / (s_a^2 r), and d/db of that is
//     (r^2 - b^2) / (s_a^2 r^3) = 1/r^3.
//  1: int a r^-4 da = -1/(2 r^2) = -1/(2 (s_a^2 + b^2)); int db = -atan(b/s_a)/(2 s_a).
//  2: the same with a and b exchanged.
//  3: int (c^2 + a^2)^-2 da = a / (2 c^2 r^2) + atan(a/c) / (2 c^3). Over b, the first term
//     by partial fractions, 1/((1+b^2)(s_a^2 + b^2)) = (1/a^2)(1/(1+b^2) - 1/(s_a^2 + b^2)),
//     the second by parts with d/db (b/c) = 1/c^3; the atan(b) terms cancel and leave
//     (1/2)[(b/s_b) atan(a/s_b) + (a/s_a) atan(b/s_a)] = -(a F_1 + b F_2).
//  4: int ab r^-5 da = -b / (3 r^3); int db = 1/(3r).
//  5: int a r^-5 da = -1/(3 r^3); int (s_a^2 + b^2)^(-3/2) db = b / (s_a^2 r), so -b/(3 s_a^2 r).
//  6: the same with a and b exchanged.
//  7, 8: int r^-5 da = a (2a^2 + 3c^2) / (3 c^4 r^3) and int a^2 r^-5 da = a^3 / (3 c^2 r^3);
//     over b these give int int a^2/r^5 = (T - E_a)/3, int int b^2/r^5 = (T - E_b)/3 and
//     int int 1/r^5 = (T + E_a + E_b)/3 with E_a = ab/(s_a^2 r), E_b = ab/(s_b^2 r) (their sum
//     is T, the antiderivative of 1/r^3, as a^2 + b^2 + 1 = r^2). In every traceless
//     combination - all that band 2 needs - the atan cancels: (a^2 - 1)/r^5 <-> -(2E_a + E_b)/3.
// Each d2F/(da db) was checked symbolically (sympy, zero residual), and every texel integral
// is checked against tensor Gauss-Legendre quadrature in tests/projection/project_cube_test.cpp.
//
// Cancellation, and how it is avoided. The corner values F are O(1) but a texel's moment is
// O(h^2) with h = 2/N, so differencing rounded corner values costs a relative error of
// about 4 u |F| / (h^2 |f|) (u = 2^-53). Measured against quadrature, in units of the
// texel's solid angle: 2.4e-14 at N = 16, 3.8e-10 at N = 1024, 1.2e-9 at N = 4096 - too
// much for "exact". Instead each edge difference D_k(b) = F_k(a1, b) - F_k(a0, b) along a
// row of corners is evaluated in a form without cancellation (edge_differences below), and
// a texel's moment is D_k(b1) - D_k(b0): D is O(h) and accurate to a few u of its size, so
// the one remaining subtraction costs about u |D| / |dD| ~ u / h. Measured: 1.6e-16 at
// N = 1, 3.6e-15 at N = 16, 3.2e-13 at N = 1024, 9.7e-13 at N = 4096; per basis function
// (in units of k_i Omega) at most ~10 u/h, 1.6e-12 at N = 4096
// (tests/projection/project_cube_test.cpp pins this with a 32 u/h bound). The D_k are shared by
// the two texel rows on either side of a corner row and by all six faces.
// Summed over a column the b-differences telescope, so sums over many texels (4 pi) are
// accurate to a few u whatever N.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"

namespace shpack::detail {

inline constexpr int kCubeMoments = 9;
using CubeMoments = std::array<double, kCubeMoments>;

// Corner coordinate i of an N x N face: (2i - N)/N, correctly rounded, so a_(N-i) = -a_i.
inline double cube_corner_coordinate(std::uint32_t i, std::uint32_t n) noexcept {
  return (2.0 * i - static_cast<double>(n)) / n;
}

// What a row of corners at height b shares: q = 1 + b^2 = s_b^2.
struct CornerRow {
  double b, q, sb;
};
inline CornerRow corner_row(double b) noexcept {
  const double q = 1.0 + b * b;
  return {b, q, std::sqrt(q)};
}

// What the two edges meeting at corner (a, b) share: s^2 = 1 + a^2, s, r, X = ab/r, and
// (Exact only) atan(b/s). Computed the same way wherever a corner is needed, so a texel's
// weights do not depend on whether its corners were cached.
struct CubeCorner {
  double a, s_sq, s, r, x, atan_b_over_s;
};
CubeCorner exact_corner(double a, const CornerRow& row) noexcept;
CubeCorner solid_angle_corner(double a, const CornerRow& row) noexcept;  // a, r, x only

// The nine edge differences D_k(b) = F_k(a1, b) - F_k(a0, b) between corners c0 (a0) and
// c1 (a1) of an exact_corner row, without cancellation.
CubeMoments edge_differences(const CubeCorner& c0, const CubeCorner& c1, const CornerRow& row) noexcept;

// Only D_0 (the solid-angle antiderivative), for SamplingMethod::Center; the same arithmetic as
// D_0 of edge_differences, so both methods give a texel the same solid angle.
double solid_angle_edge_difference(const CubeCorner& c0, const CubeCorner& c1, const CornerRow& row) noexcept;

// Mirror symmetry a -> -a. Corner coordinates are exactly antisymmetric (a_(N-i) = -a_i),
// so edge N-1-x is edge x mirrored, and as F_k(-a, b) = p_k F_k(a, b) its difference is
// D_k(N-1-x) = F_k(-a_x) - F_k(-a_(x+1)) = -p_k D_k(x). F_0, F_2, F_3, F_6, F_7, F_8 are
// odd in a (p = -1), F_1, F_4, F_5 even (p = +1). Only edges x < (N+1)/2 are evaluated.
inline constexpr CubeMoments kMirrorEdgeSign = {1, -1, 1, 1, -1, -1, 1, 1, 1};
inline std::uint32_t first_mirrored_edge(std::uint32_t n) noexcept { return (n + 1) / 2; }

// Edge x (corners x, x + 1) of an N-edge row: evaluated for x < first_mirrored_edge(n),
// mirrored from edge n-1-x otherwise. Exact: the nine D_k; Center: D_0 in element 0.
CubeMoments edge_terms(bool exact, std::uint32_t x, std::uint32_t n, const CornerRow& row) noexcept;

// SamplingMethod::Center: the local moments of a texel of exact solid angle `omega` whose centre
// is (a, b): omega times the integrand's direction polynomial at the centre.
CubeMoments center_moments(double omega, double a, double b) noexcept;

// Which local component (0 = a, 1 = b, 2 = n) and sign give each world coordinate
// x, y, z on a face: world_j = sign_j * d_(local_j).
struct FaceMap {
  std::array<int, 3> local;
  std::array<double, 3> sign;
};

constexpr FaceMap face_map(const CubeFaceAxes& f) noexcept {
  FaceMap m{};
  const Dir3 axes[3] = {f.u_axis, f.v_axis, f.normal};
  for (int j = 0; j < 3; ++j) {
    for (int l = 0; l < 3; ++l) {
      const double c = j == 0 ? axes[l].x : j == 1 ? axes[l].y : axes[l].z;
      if (c != 0.0) {
        m.local[j] = l;
        m.sign[j] = c;
      }
    }
  }
  return m;
}

// The integrals of the nine basis polynomials P_i (sh_basis.h, without k_i) over a region
// of face `map` whose local moments are `m`. With world_j = s_j d_(l_j):
//   P1 = y, P2 = z, P3 = x          -> s_j * moment of d_(l_j)            (k = 1, 2, 3)
//   P4 = xy, P5 = yz, P7 = xz       -> s_j s_k * moment of d_(l_j) d_(l_k) (k = 4, 5, 6)
//   P6 = 2z^2 - x^2 - y^2, P8 = x^2 - y^2: traceless, so with Q(l) = moment of
//   d_l^2 - d_n^2 (k = 7, 8, and 0 for l = n): P6 -> 2Q(l_z) - Q(l_x) - Q(l_y),
//   P8 -> Q(l_x) - Q(l_y).
std::array<double, kShCount> face_basis_integrals(const FaceMap& map, const CubeMoments& m) noexcept;

}  // namespace shpack::detail
