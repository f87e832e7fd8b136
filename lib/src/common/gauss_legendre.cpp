#include "common/gauss_legendre.h"

#include <array>
#include <cmath>
#include <numbers>

namespace shpack::detail {
namespace {

constexpr int kTableSize = kMaxGaussOrder * (kMaxGaussOrder + 1) / 2;  // rules 1..64 back to back

struct Table {
  std::array<double, kTableSize> nodes{}, weights{};

  static constexpr int offset(int q) noexcept { return (q - 1) * q / 2; }

  // P_q(t) and P_{q-1}(t) by the three-term recurrence (A&S 22.7.10).
  static void legendre(int q, double t, double& pq, double& pq1) noexcept {
    double p0 = 1.0, p1 = t;
    for (int k = 2; k <= q; ++k) {
      const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    pq = q == 1 ? t : p1;
    pq1 = q == 1 ? 1.0 : p0;
  }

  Table() noexcept {
    for (int q = 1; q <= kMaxGaussOrder; ++q) {
      for (int k = 0; k < q; ++k) {
        // Root k of P_q from the largest, by Newton from Tricomi's first guess; the weight
        // is 2 / ((1 - t^2) P_q'(t)^2) (A&S 25.4.29) at the converged root.
        double t = std::cos(std::numbers::pi * (k + 0.75) / (q + 0.5));
        double pq = 0, pq1 = 0;
        for (int it = 0; it < 100; ++it) {
          legendre(q, t, pq, pq1);
          const double step = pq / (q * (t * pq - pq1) / (t * t - 1.0));
          t -= step;
          if (std::fabs(step) <= 1e-17) break;
        }
        legendre(q, t, pq, pq1);
        const double dp = q * (t * pq - pq1) / (t * t - 1.0);
        nodes[offset(q) + q - 1 - k] = t;
        weights[offset(q) + q - 1 - k] = 2.0 / ((1.0 - t * t) * dp * dp);
      }
    }
  }
};

const Table& table() noexcept {
  static const Table t;  // built once, thread-safe (a function-local static)
  return t;
}

}  // namespace

GaussRule gauss_legendre(int q) noexcept {
  const Table& t = table();
  const int o = Table::offset(q);
  return {std::span<const double>(t.nodes.data() + o, q), std::span<const double>(t.weights.data() + o, q)};
}

int gauss_order_for_type(double length, double nu) noexcept {
  // log of ((b - a) nu)^(2q) (q!)^4 / ((2q + 1) ((2q)!)^3), with lgamma for the factorials.
  const double log_x = std::log(std::fmax(length * nu, 1e-300));
  const double log_target = std::log(kQuadratureTarget);
  for (int q = 1; q < kMaxGaussOrder; ++q) {
    const double log_bound = 2.0 * q * log_x + 4.0 * std::lgamma(q + 1.0) - std::log(2.0 * q + 1.0) -
                             3.0 * std::lgamma(2.0 * q + 1.0);
    if (log_bound <= log_target) return q;
  }
  return kMaxGaussOrder;
}

int gauss_order_for_ellipse(double r) noexcept {
  // (64/15) r^(-2q) / (r^2 - 1) <= target  <=>  2q log r >= log(64/15 / ((r^2 - 1) target)).
  const double need = std::log(64.0 / 15.0 / ((r * r - 1.0) * kQuadratureTarget));
  const double q = std::ceil(need / (2.0 * std::log(r)));
  return q < 1 ? 1 : q > kMaxGaussOrder ? kMaxGaussOrder : static_cast<int>(q);
}

double ellipse_for_real_gap(double gap, double half_length) noexcept {
  const double a = 1.0 + gap / half_length;
  return a + std::sqrt((a - 1.0) * (a + 1.0));
}

}  // namespace shpack::detail
