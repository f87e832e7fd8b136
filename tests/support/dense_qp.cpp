#include "support/dense_qp.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace shpack_test {
namespace {

// m mu at the last centring. Below about 1e-11 rounding in the Newton step, whose Hessian's
// condition grows as 1/mu, keeps the gradient from reaching m mu.
constexpr double kGapTarget = 1e-10;
constexpr double kConverged = 1e-9;  // the certified gap that counts as converged
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Barrier {
  const std::vector<double>& w;
  const std::vector<double>& target;
  const std::vector<double>& rows;
  std::size_t n, m;

  double slack(const std::vector<double>& x, std::size_t k) const {
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += rows[k * n + i] * x[i];
    return s;
  }
  double objective(const std::vector<double>& x) const {
    double f = 0;
    for (std::size_t i = 0; i < n; ++i) f += w[i] * (x[i] - target[i]) * (x[i] - target[i]);
    return f;
  }
  // f(x) - mu sum log(g . x), or +infinity outside the constraints.
  double value(const std::vector<double>& x, double mu) const {
    double f = objective(x);
    for (std::size_t k = 0; k < m; ++k) {
      const double s = slack(x, k);
      if (!(s > 0)) return kInfinity;
      f -= mu * std::log(s);
    }
    return f;
  }
};

// Solves H d = -g in place (H symmetric positive definite, n x n) by Cholesky.
bool cholesky_solve(std::vector<double> h, std::vector<double>& rhs, std::size_t n) {
  for (std::size_t j = 0; j < n; ++j) {
    double d = h[j * n + j];
    for (std::size_t k = 0; k < j; ++k) d -= h[j * n + k] * h[j * n + k];
    if (!(d > 0)) return false;
    h[j * n + j] = std::sqrt(d);
    for (std::size_t i = j + 1; i < n; ++i) {
      double s = h[i * n + j];
      for (std::size_t k = 0; k < j; ++k) s -= h[i * n + k] * h[j * n + k];
      h[i * n + j] = s / h[j * n + j];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {  // L y = rhs
    for (std::size_t k = 0; k < i; ++k) rhs[i] -= h[i * n + k] * rhs[k];
    rhs[i] /= h[i * n + i];
  }
  for (std::size_t i = n; i-- > 0;) {  // L^T x = y
    for (std::size_t k = i + 1; k < n; ++k) rhs[i] -= h[k * n + i] * rhs[k];
    rhs[i] /= h[i * n + i];
  }
  return true;
}

// Newton's method on the barrier at mu from x. The duality gap at x (duality_gap) is
// m mu + sum_i grad_i^2 / (4 w_i) (expand f(x) - q(mu / s) with v = 2W(x - target) - grad),
// so centring stops once the gradient's part is below m mu. Damped steps (backtracking,
// alpha = 0.25, beta = 0.5) while the Newton decrement lambda is > 0.2, then full steps:
// for a self-concordant function a step with lambda < 1 stays inside the domain and
// converges quadratically (ibid. 9.6.4), where comparing barrier values would be lost in
// their rounding.
void centre(const Barrier& b, double mu, std::vector<double>& x) {
  const std::size_t n = b.n;
  for (int step = 0; step < 200; ++step) {
    std::vector<double> grad(n), hess(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      grad[i] = 2 * b.w[i] * (x[i] - b.target[i]);
      hess[i * n + i] = 2 * b.w[i];
    }
    std::vector<double> q(n);  // g_k / (g_k . x)
    for (std::size_t k = 0; k < b.m; ++k) {
      const double s = b.slack(x, k);
      for (std::size_t i = 0; i < n; ++i) q[i] = b.rows[k * n + i] / s;
      for (std::size_t i = 0; i < n; ++i) {
        grad[i] -= mu * q[i];
        for (std::size_t j = i; j < n; ++j) hess[i * n + j] += mu * q[i] * q[j];
      }
    }
    double excess = 0;
    for (std::size_t i = 0; i < n; ++i) excess += grad[i] * grad[i] / (4 * b.w[i]);
    if (excess <= static_cast<double>(b.m) * mu) return;
    for (std::size_t i = 0; i < n; ++i)  // the lower triangle, which cholesky_solve reads
      for (std::size_t j = 0; j < i; ++j) hess[i * n + j] = hess[j * n + i];
    std::vector<double> dir(n);
    for (std::size_t i = 0; i < n; ++i) dir[i] = -grad[i];
    if (!cholesky_solve(hess, dir, n)) return;
    double decrement = 0;  // lambda^2 = -grad . dir
    for (std::size_t i = 0; i < n; ++i) decrement -= grad[i] * dir[i];
    double t = 1;
    std::vector<double> next(n);
    const double here = decrement > 0.04 ? b.value(x, mu) : 0.0;
    for (;; t /= 2) {
      if (t < 1e-20) return;  // no descent left in double precision
      for (std::size_t i = 0; i < n; ++i) next[i] = x[i] + t * dir[i];
      const double there = b.value(next, mu);
      if (decrement > 0.04 ? there <= here - 0.25 * t * decrement : there < kInfinity) break;
    }
    x = next;
  }
}

// f(x) - q(lambda) for lambda_k = mu / (g_k . x) (dense_qp.h), plus its own rounding: its
// three parts are sums of at most m + n terms, each within (m + n) u of its magnitude.
double duality_gap(const Barrier& b, double mu, const std::vector<double>& x) {
  std::vector<double> v(b.n, 0.0);
  for (std::size_t k = 0; k < b.m; ++k) {
    const double lambda = mu / b.slack(x, k);
    for (std::size_t i = 0; i < b.n; ++i) v[i] += lambda * b.rows[k * b.n + i];
  }
  double vt = 0, vv = 0;
  for (std::size_t i = 0; i < b.n; ++i) vt += v[i] * b.target[i], vv += v[i] * v[i] / (4 * b.w[i]);
  const double f = b.objective(x);
  const double rounding = 4 * static_cast<double>(b.m + b.n) * std::numeric_limits<double>::epsilon() *
                          (f + std::fabs(vt) + vv);
  return std::max(0.0, f + vt + vv) + rounding;
}

}  // namespace

DenseQpResult dense_nearest_in_cone(const std::vector<double>& weights, const std::vector<double>& target,
                                    const std::vector<double>& rows, const std::vector<double>& interior) {
  const std::size_t n = weights.size();
  const Barrier b{weights, target, rows, n, rows.size() / n};
  DenseQpResult out;
  out.x = interior;
  double mu = 1.0 / static_cast<double>(b.m);
  for (;; mu /= 10) {
    centre(b, mu, out.x);
    if (static_cast<double>(b.m) * mu <= kGapTarget) break;
  }
  out.gap = duality_gap(b, mu, out.x);
  out.converged = out.gap <= kConverged;
  return out;
}

}  // namespace shpack_test
