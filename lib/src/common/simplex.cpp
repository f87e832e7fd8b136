#include "common/simplex.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shpack {
namespace {

// x_basic[i] = beta[i] - sum_j d[i][j] x_nonbasic[j];  z = const + sum_j gamma[j] x_nonbasic[j].
// Variables are numbered 0..n-1 (the x of the problem) and n..n+m-1 (the slacks of the rows).
struct Dictionary {
  std::size_t m, n;
  std::vector<double> d, beta, gamma;
  std::vector<std::size_t> basic, nonbasic;

  explicit Dictionary(const LinearProgram& lp)
      : m(lp.rows), n(lp.cols), d(lp.a), beta(lp.b), gamma(lp.c), basic(m), nonbasic(n) {
    for (std::size_t j = 0; j < n; ++j) nonbasic[j] = j;
    for (std::size_t i = 0; i < m; ++i) basic[i] = n + i;
  }

  // Bland: the improving non-basic variable of smallest index, or n when none improves.
  std::size_t entering(double tolerance) const {
    std::size_t best = n;
    for (std::size_t j = 0; j < n; ++j)
      if (gamma[j] > tolerance && (best == n || nonbasic[j] < nonbasic[best])) best = j;
    return best;
  }

  // The ratio test on column s: the row bounding x_s first, ties to the smallest basic index;
  // m when no row bounds it (unbounded).
  std::size_t leaving(std::size_t s, double tolerance) const {
    std::size_t best = m;
    double best_ratio = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m; ++i) {
      const double a = d[i * n + s];
      if (a <= tolerance) continue;
      const double ratio = beta[i] / a;
      if (ratio < best_ratio || (ratio == best_ratio && basic[i] < basic[best])) best = i, best_ratio = ratio;
    }
    return best;
  }

  // x_s enters, the basic variable of row r leaves (the substitution of Chvatal ch. 2).
  void pivot(std::size_t r, std::size_t s) {
    double* row = &d[r * n];
    const double p = 1.0 / row[s];
    for (std::size_t j = 0; j < n; ++j) row[j] *= p;
    row[s] = p;
    beta[r] *= p;
    for (std::size_t i = 0; i < m; ++i) {
      if (i == r) continue;
      double* other = &d[i * n];
      const double f = other[s];
      if (f == 0) continue;
      for (std::size_t j = 0; j < n; ++j) other[j] -= f * row[j];
      other[s] = -f * p;
      beta[i] = std::max(0.0, beta[i] - f * beta[r]);
    }
    const double g = gamma[s];
    for (std::size_t j = 0; j < n; ++j) gamma[j] -= g * row[j];
    gamma[s] = -g * p;
    std::swap(basic[r], nonbasic[s]);
  }
};

double largest_magnitude(const std::vector<double>& values) {
  double most = 0;
  for (double v : values) most = std::max(most, std::abs(v));
  return most;
}

}  // namespace

LpSolution maximize(const LinearProgram& lp) {
  Dictionary dict(lp);
  const double pivot_tolerance = kSimplexTolerance * std::max(largest_magnitude(lp.a), 1e-300);
  const double cost_tolerance = kSimplexTolerance * std::max(largest_magnitude(lp.c), 1e-300);
  LpSolution out;
  for (;;) {
    const std::size_t s = dict.entering(cost_tolerance);
    if (s == dict.n) break;
    const std::size_t r = dict.leaving(s, pivot_tolerance);
    if (r == dict.m) {
      out.outcome = LpOutcome::Unbounded;
      break;
    }
    if (out.pivots == kMaxSimplexPivots) {
      out.outcome = LpOutcome::PivotLimit;
      break;
    }
    dict.pivot(r, s);
    ++out.pivots;
  }
  out.x.assign(lp.cols, 0.0);
  for (std::size_t i = 0; i < dict.m; ++i)
    if (dict.basic[i] < lp.cols) out.x[dict.basic[i]] = dict.beta[i];
  for (std::size_t j = 0; j < lp.cols; ++j) out.value += lp.c[j] * out.x[j];
  return out;
}

}  // namespace shpack
