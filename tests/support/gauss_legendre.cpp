#include "support/gauss_legendre.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace shpack_test {
namespace {

struct Table {
  std::array<std::vector<double>, kMaxGaussOrder + 1> nodes, weights;

  Table() {
    for (int q = 1; q <= kMaxGaussOrder; ++q) {
      std::vector<double>& x = nodes[q];
      std::vector<double>& w = weights[q];
      x.resize(q);
      w.resize(q);
      for (int k = 0; k < q; ++k) {
        // Root k of P_q, from the largest, by Newton from Tricomi's first guess.
        double t = std::cos(std::numbers::pi * (k + 0.75) / (q + 0.5));
        double dp = 0;
        for (int it = 0; it < 100; ++it) {
          double p0 = 1, p1 = t;  // P_0, P_1; three-term recurrence to P_q
          for (int n = 2; n <= q; ++n) {
            const double p2 = ((2.0 * n - 1.0) * t * p1 - (n - 1.0) * p0) / n;
            p0 = p1;
            p1 = p2;
          }
          const double pq = q == 1 ? t : p1, pq1 = q == 1 ? 1.0 : p0;
          dp = q * (t * pq - pq1) / (t * t - 1.0);
          const double step = pq / dp;
          t -= step;
          if (std::fabs(step) <= 1e-17) break;
        }
        // Recompute the derivative at the converged root for the weight.
        double p0 = 1, p1 = t;
        for (int n = 2; n <= q; ++n) {
          const double p2 = ((2.0 * n - 1.0) * t * p1 - (n - 1.0) * p0) / n;
          p0 = p1;
          p1 = p2;
        }
        const double pq = q == 1 ? t : p1, pq1 = q == 1 ? 1.0 : p0;
        dp = q * (t * pq - pq1) / (t * t - 1.0);
        x[q - 1 - k] = t;
        w[q - 1 - k] = 2.0 / ((1.0 - t * t) * dp * dp);
      }
    }
  }
};

const Table& table() {
  static const Table t;  // thread-safe static initialisation
  return t;
}

}  // namespace

GaussRule gauss_legendre(int q) {
  if (q < 1 || q > kMaxGaussOrder) throw std::out_of_range("gauss_legendre: order");
  const Table& t = table();
  return {t.nodes[q], t.weights[q]};
}

double gl_relative_bound(double length, double nu, int q) {
  // In logarithms: (2q) log(L nu) + 4 lgamma(q+1) - log(2q+1) - 3 lgamma(2q+1).
  const double log_bound = 2.0 * q * std::log(length * nu) + 4.0 * std::lgamma(q + 1.0) -
                           std::log(2.0 * q + 1.0) - 3.0 * std::lgamma(2.0 * q + 1.0);
  return std::exp(log_bound);
}

int gl_order_for(double length, double nu, double target) {
  for (int q = 1; q <= kMaxGaussOrder; ++q)
    if (gl_relative_bound(length, nu, q) <= target) return q;
  throw std::runtime_error("gl_order_for: no order reaches the target");
}

}  // namespace shpack_test
