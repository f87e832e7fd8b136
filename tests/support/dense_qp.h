// dense_qp.h - a slow, general oracle for the nearest non-negative fit
// (lib/src/sh/nonnegative_fit.h): the convex QP over finitely many linear constraints
//
//   minimise f(x) = sum_i w_i (x_i - target_i)^2   subject to   g_k . x >= 0, k = 1..m,
//
// by a primal log-barrier interior-point method [S. Boyd, L. Vandenberghe, "Convex
// Optimization", 2004, sec. 11.3]: for mu = 1/m, mu/10, ..., Newton's method with a
// line search minimises f(x) - mu sum_k log(g_k . x) from the last centre. A
// different algorithm from the library's (cutting planes over an active-set NNLS): it never
// identifies an active set, it stays strictly inside the constraints, and its accuracy is a
// duality gap.
//
// Accuracy, certified by weak duality rather than assumed from the centring: at the end,
// lambda_k = mu / (g_k . x) >= 0 is a dual point, and the dual function of this QP is, with
// v = sum_k lambda_k g_k, q(lambda) = min_x f(x) - v . x = -v . target - sum_i v_i^2 / (4 w_i)
// (the minimiser is x = target + v / (2w)); so f(x) - f* <= f(x) - q(lambda) = gap (m mu at
// an exact centre, ibid. 11.2.2). Since f is a quadratic with Hessian 2W, f(y) - f* >=
// ||y - x*||_W^2 for every feasible y, so x is within sqrt(gap) of the optimum in the W-norm.
#pragma once

#include <vector>

namespace shpack_test {

struct DenseQpResult {
  std::vector<double> x;   // strictly feasible: g_k . x > 0 for every k
  double gap = 0;          // f(x) - f* <= gap (duality, above), rounding included
  bool converged = false;  // gap <= 1e-9
};

// `rows` holds the m constraint vectors g_k, each of weights.size() numbers, one after the
// other. `interior` must be strictly feasible. Objective scale: f(0) should be about 1 (mu
// runs down to 1e-10 / m, so the gap is about 2e-10).
DenseQpResult dense_nearest_in_cone(const std::vector<double>& weights, const std::vector<double>& target,
                                    const std::vector<double>& rows, const std::vector<double>& interior);

}  // namespace shpack_test
