// gauss_legendre.h - Gauss-Legendre quadrature for the test oracle, with its error bound.
//
// The q-point rule on [a, b] integrates polynomials of degree <= 2q - 1 exactly. For a smooth
// f the remainder is (Abramowitz & Stegun 25.4.30)
//
//   R_q = (b - a)^(2q+1) (q!)^4 / ((2q + 1) ((2q)!)^3) * f^(2q)(xi),   a < xi < b.
//
// Every integrand of the oracle is a trigonometric polynomial in the variable of
// integration (theta or the longitude) of frequency <= nu, so |f^(2q)| <= A nu^(2q) with
// A the sum of its |coefficients|, and
//
//   |R_q| <= (b - a) A * gl_relative_bound(b - a, nu, q),
//   gl_relative_bound = ((b - a) nu)^(2q) (q!)^4 / ((2q + 1) ((2q)!)^3).
#pragma once

#include <span>

namespace shpack_test {

inline constexpr int kMaxGaussOrder = 64;

// Nodes on [-1, 1], ascending, and their weights (sum 2), for 1 <= q <= kMaxGaussOrder.
// Newton's iteration on P_q, accurate to a few ulp.
struct GaussRule {
  std::span<const double> nodes, weights;
};
GaussRule gauss_legendre(int q);

// The bound above divided by (b - a) A.
double gl_relative_bound(double length, double nu, int q);

// The smallest q in [1, kMaxGaussOrder] with gl_relative_bound(length, nu, q) <= target.
int gl_order_for(double length, double nu, double target);

}  // namespace shpack_test
