// draws.h - the errors of a random method over several draws (seeds), as `shpack bench`
// reports them.
//
// One draw of a Monte Carlo estimate has an error that scatters by its own size from seed
// to seed, so a curve of single draws goes up and down and hides the rate. What a user can
// expect is the RMS over draws, sqrt(mean_k e_k^2): the root of the mean squared error, the
// quantity whose N^-1/2 law (for an unbiased estimator) the convergence fit reads. The
// spread is the 10th and 90th percentiles of the draws.
#pragma once

#include <vector>

#include "shpack/study/accuracy.h"

namespace shpack::study {

struct Spread {
  double p10 = 0, p90 = 0;
};

// sqrt(mean of v^2); NaN if any value is NaN (a black map has no relative error) or there
// are none.
double rms(const std::vector<double>& values);

// The p-quantile (0 <= p <= 1) by linear interpolation between order statistics: at rank
// h = (n - 1) p, x_floor(h) + (h - floor(h)) (x_floor(h)+1 - x_floor(h)) (Hyndman and Fan's
// type 7, R's and NumPy's default). NaN if any value is NaN or there are none.
double quantile(std::vector<double> values, double p);

// The median: quantile(values, 0.5), the middle of an odd count and the mean of the two
// middles of an even one. NaN if any value is NaN or there are none.
double median(std::vector<double> values);

// The 95% confidence interval of the RMS over draws as an estimate of sqrt(E[e^2]): the mean
// of e^2 over n draws is asymptotically normal with standard error sd(e^2)/sqrt(n) (central
// limit theorem; sd the sample standard deviation), so E[e^2] lies in
// mean +- 1.96 sd / sqrt(n) and its square root in the square roots of those ends (the
// lower clamped at 0). NaN ends for fewer than two draws or any NaN.
struct Interval {
  double low = 0, high = 0;
};
Interval rms_interval(const std::vector<double>& values);

// The interval's half-width relative to the RMS: (high - low) / (2 rms); NaN as above.
double relative_half_width(const Interval& interval, double rms_value);

// What the draws' metrics come to: err_max_pct, err_rms_pct and coef_err_max are each the
// RMS over the draws; min_e_over_pi is the lowest draw's (the worst ringing a user may get).
// One draw (a deterministic method) is its own summary, both percentiles and both ends of
// each interval its value.
struct DrawSummary {
  AccuracyMetrics accuracy;
  Spread err_max, err_rms;
  Interval err_max_interval, err_rms_interval;  // rms_interval of err_max_pct, err_rms_pct
};
DrawSummary summarize_draws(const std::vector<AccuracyMetrics>& draws);

}  // namespace shpack::study
