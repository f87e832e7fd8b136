// study_report.h - what `shpack bench` prints: a markdown report, or JSON records.
#pragma once

#include <string>
#include <vector>

#include "shpack/study/pareto_front.h"
#include "shpack/study/study.h"

namespace shpack::study {

// One spec over every input it ran on: the summary row and the plotted point.
struct SpecSummary {
  MethodSpec spec;
  int inputs = 0;
  double time_ms = 0;       // median over the inputs of time_ms_median
  double err_max_pct = 0;   // worst input
  double err_rms_pct = 0;   // median over the inputs
  double expected_err_rms_pct = 0;  // median over the inputs (study.h)
  std::string err_rms_kind;         // its kind on the first input (the same on every one)
  double coef_err_max = 0;  // worst input
  double samples = 0;       // median over the inputs (they differ only for mip and exact)
  unsigned seeds = 1;       // draws per input (study.h)
  Spread err_max_spread;    // the draws' spread of err_max_pct on the worst input
  // The median over the inputs of each end of the draws' 95% interval of err_rms_pct: for a
  // sampled expected error (qmc) it brackets the median expected error whenever every input's
  // interval holds that input's (the median is monotone in each value).
  Interval err_rms_interval;
};

// In the order the specs first appear in `records`. NaN errors (black maps) are left out
// of the worst and the median; a spec with only NaN errors has NaN.
std::vector<SpecSummary> summarize(const std::vector<StudyRecord>& records);

// The convergence rate of one method on one input: the least-squares slope of
// log(expected_err_rms_pct) against log(samples) over its runs with a positive error (study.h:
// the closed form for mc and is, the RMS over draws for qmc, the one error of the others),
// so the fit reads the rate, not the scatter of single draws. -0.5 is Monte Carlo's N^-1/2;
// -1 is an O(h^2) rule on a 2-D grid (samples ~ h^-2).
struct ConvergenceFit {
  std::string input;
  SamplingMethod method = SamplingMethod::Exact;
  double slope = 0;
  int points = 0;  // >= 3: fewer runs give no fit
};
std::vector<ConvergenceFit> convergence_fits(const std::vector<StudyRecord>& records);

// The Pareto front (pareto_front.h) over summarize's time and expected RMS error: of every
// input's median when `records` hold several, of the one input's records otherwise. The
// report's front and the plot's.
std::vector<FrontPoint> expected_error_front(const std::vector<StudyRecord>& records);

// Markdown: a summary over the inputs (when there are several), the convergence slopes
// (per input and their median, of the expected errors), the Pareto front over time and
// expected RMS error (pareto_front.h) of all inputs and of each, then one table per input,
// each headed by the load average while it was timed.
std::string markdown_report(const std::vector<StudyRecord>& records);

// A JSON array, one object per record, with the keys input, width, height, method (the
// name without parameter), param (null for exact and center), spec (method_name), seed
// (null for the methods that ignore it; the first of the draws' seeds), seeds (the number of
// draws), threads, repeats, samples, time_ms_median, time_ms_min, time_ms_max, err_max_pct,
// err_max_pct_p10, err_max_pct_p90, err_rms_pct, err_rms_pct_p10, err_rms_pct_p90,
// coef_err_max, min_e_over_pi, load_average (1, 5, 15 minutes), expected_err_rms_pct,
// expected_err_max_pct, error_kind (of expected_err_rms_pct: "exact", "bound" or "sampled",
// expected_error.h), err_max_kind (of expected_err_max_pct), err_rms_pct_ci95 and
// err_max_pct_ci95 (the draws' 95% intervals, [low, high]) (NaN is null). Ends with a line
// break.
std::string json_report(const std::vector<StudyRecord>& records);

}  // namespace shpack::study
