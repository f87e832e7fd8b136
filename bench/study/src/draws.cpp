#include "shpack/study/draws.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace shpack::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool any_nan(const std::vector<double>& values) {
  return std::any_of(values.begin(), values.end(), [](double v) { return std::isnan(v); });
}

}  // namespace

double rms(const std::vector<double>& values) {
  if (values.empty() || any_nan(values)) return kNaN;
  double sum = 0;
  for (const double v : values) sum += v * v;
  return std::sqrt(sum / static_cast<double>(values.size()));
}

double quantile(std::vector<double> values, double p) {
  if (values.empty() || any_nan(values)) return kNaN;
  std::sort(values.begin(), values.end());
  const double h = static_cast<double>(values.size() - 1) * p;
  const auto below = static_cast<std::size_t>(std::floor(h));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (h - static_cast<double>(below)) * (values[above] - values[below]);
}

double median(std::vector<double> values) { return quantile(std::move(values), 0.5); }

Interval rms_interval(const std::vector<double>& values) {
  if (values.size() < 2 || any_nan(values)) return {kNaN, kNaN};
  const double n = static_cast<double>(values.size());
  double mean = 0;
  for (const double v : values) mean += v * v;
  mean /= n;
  double ss = 0;
  for (const double v : values) ss += (v * v - mean) * (v * v - mean);
  const double half = 1.96 * std::sqrt(ss / (n - 1) / n);
  return {std::sqrt(std::max(0.0, mean - half)), std::sqrt(mean + half)};
}

double relative_half_width(const Interval& interval, double rms_value) {
  return (interval.high - interval.low) / (2.0 * rms_value);
}

DrawSummary summarize_draws(const std::vector<AccuracyMetrics>& draws) {
  if (draws.size() == 1) {  // a deterministic method: its one draw, as measured
    const AccuracyMetrics& d = draws.front();
    return {d, {d.err_max_pct, d.err_max_pct}, {d.err_rms_pct, d.err_rms_pct},
            {d.err_max_pct, d.err_max_pct}, {d.err_rms_pct, d.err_rms_pct}};
  }
  std::vector<double> err_max, err_rms, coef;
  double lowest_minimum = std::numeric_limits<double>::infinity();
  for (const AccuracyMetrics& d : draws) {
    err_max.push_back(d.err_max_pct);
    err_rms.push_back(d.err_rms_pct);
    coef.push_back(d.coef_err_max);
    lowest_minimum = std::min(lowest_minimum, d.min_e_over_pi);
  }
  DrawSummary out;
  out.accuracy = {rms(err_max), rms(err_rms), rms(coef), draws.empty() ? kNaN : lowest_minimum};
  out.err_max = {quantile(err_max, 0.1), quantile(err_max, 0.9)};
  out.err_rms = {quantile(err_rms, 0.1), quantile(err_rms, 0.9)};
  out.err_max_interval = rms_interval(err_max);
  out.err_rms_interval = rms_interval(err_rms);
  return out;
}

}  // namespace shpack::study
