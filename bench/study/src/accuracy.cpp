#include "shpack/study/accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "shpack/convolution.h"
#include "shpack/sh_minimum.h"

namespace shpack::study {

std::vector<Dir3> fibonacci_normals(int n) {
  // 2 pi / phi^2 = pi (3 - sqrt 5): the golden angle.
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  std::vector<Dir3> normals;
  normals.reserve(static_cast<std::size_t>(std::max(n, 0)));
  for (int k = 0; k < n; ++k) {
    const double y = 1.0 - (2.0 * k + 1.0) / n;
    const double r = std::sqrt((1.0 - y) * (1.0 + y));  // no cancellation near the poles
    const double lon = golden_angle * k;
    normals.push_back({r * std::cos(lon), y, r * std::sin(lon)});
  }
  return normals;
}

AccuracyMeter::AccuracyMeter(const ShL2& reference_radiance, int normal_count)
    : reference_(reference_radiance) {
  for (const Dir3& n : fibonacci_normals(normal_count)) {
    std::array<double, kShCount> row = basis_polynomials(n.x, n.y, n.z);
    for (int i = 0; i < kShCount; ++i) row[i] *= kUnityScale[i];
    basis_.push_back(row);
  }
}

AccuracyMetrics AccuracyMeter::measure(const ShL2& radiance) const {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  AccuracyMetrics m;
  bool any_channel = false;
  m.min_e_over_pi = std::numeric_limits<double>::infinity();
  const ShL2 unity_form = radiance_to_unity_form(radiance);
  for (int c = 0; c < kChannelCount; ++c) {
    m.min_e_over_pi = std::min(m.min_e_over_pi, minimum_on_sphere(unity_form, c).value);
    const double l00 = reference_.c[c][0];
    const double mean = kUnityScale[0] * l00;
    if (!(mean > 0)) continue;
    any_channel = true;
    std::array<double, kShCount> delta{};
    for (int i = 0; i < kShCount; ++i) {
      delta[i] = radiance.c[c][i] - reference_.c[c][i];
      m.coef_err_max = std::max(m.coef_err_max, std::abs(delta[i]) / l00);
    }
    double max_abs = 0, sum_sq = 0;
    for (const auto& row : basis_) {
      double e = 0;
      for (int i = 0; i < kShCount; ++i) e += row[i] * delta[i];
      max_abs = std::max(max_abs, std::abs(e));
      sum_sq += e * e;
    }
    m.err_max_pct = std::max(m.err_max_pct, 100.0 * max_abs / mean);
    m.err_rms_pct = std::max(m.err_rms_pct, 100.0 * std::sqrt(sum_sq / basis_.size()) / mean);
  }
  if (!any_channel) m.err_max_pct = m.err_rms_pct = m.coef_err_max = kNaN;
  return m;
}

}  // namespace shpack::study
