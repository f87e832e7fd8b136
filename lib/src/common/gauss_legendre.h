// gauss_legendre.h (private) - Gauss-Legendre rules and the orders that reach double
// precision, for the texel integrals of the sphere maps (project_sphere_map.h).
//
// The q-point rule on [a, b] integrates polynomials of degree <= 2q - 1 exactly. Two
// bounds choose q:
//  - an integrand of exponential type nu (|f^(k)| <= nu^k max|f| on the real line, which
//    Bernstein's inequality gives for products of sin, cos of frequencies summing to nu):
//    the remainder of Abramowitz & Stegun 25.4.30,
//      |R_q| <= (b - a) max|f| ((b - a) nu)^(2q) (q!)^4 / ((2q + 1) ((2q)!)^3);
//  - an integrand analytic inside the Bernstein ellipse E_r of [a, b] (foci a, b, sum of
//    semi-axes r (b - a)/2), bounded there by M (L. N. Trefethen, "Approximation Theory
//    and Approximation Practice", SIAM 2013, theorem 19.3):
//      |R_q| <= (64/15) M r^(-2q) / (r^2 - 1)   (times (b - a)/2).
// Both are used with the target kQuadratureTarget of the integrand's scale; rounding then
// dominates.
#pragma once

#include <span>

namespace shpack::detail {

inline constexpr int kMaxGaussOrder = 64;
inline constexpr double kQuadratureTarget = 1e-20;

// Nodes on [-1, 1], ascending, and weights (sum 2), for 1 <= q <= kMaxGaussOrder,
// computed once by Newton's iteration on the three-term recurrence (a few ulp).
struct GaussRule {
  std::span<const double> nodes, weights;
};
GaussRule gauss_legendre(int q) noexcept;

// The smallest q (clamped to [1, kMaxGaussOrder]) whose exponential-type bound above, for an
// interval of length `length` and type `nu`, is below kQuadratureTarget.
int gauss_order_for_type(double length, double nu) noexcept;

// The smallest q (clamped likewise) whose ellipse bound, for an integrand analytic inside
// E_r and bounded there by its scale, is below kQuadratureTarget. r > 1.
int gauss_order_for_ellipse(double r) noexcept;

// The ellipse parameter r of an interval of half-length h whose integrand is analytic up to
// a distance `gap` beyond one of its ends along the real line: the ellipse through that
// point, a = 1 + gap/h, r = a + sqrt(a^2 - 1).
double ellipse_for_real_gap(double gap, double half_length) noexcept;

}  // namespace shpack::detail
