// study.h - the accuracy and the time of projection methods on one map (`shpack bench`).
//
// For each spec: the projections that give its error, untimed (the first also warms the
// caches), then `repeats` timed projections of the same in-memory image, each timed alone
// with std::chrono::steady_clock (wall clock), give the median, min and max. A random method
// (uses_seed: mc, qmc, is) is one draw of a random estimate, so its error is measured over
// `seeds` draws, seeds seed, seed + 1, ...: each error is the RMS over the draws (the
// expected error, sqrt E[e^2]), with its 10th and 90th percentiles; the deterministic methods
// have one draw. Only the projection is timed (the first draw's spec): the image is read or
// made before, the errors measured after. The reference is exact (SamplingMethod::Exact) of
// the same image, with the same options.
//
// Expected errors (expected_error.h) beside the draws: for mc and is the closed form from
// their variance (sampling_variance.h, one pass over the texels per image and method, for
// every N), the RMS error "exact" and the max error's bound "bound"; for a deterministic
// rule its one error, "exact"; for qmc, which has no closed form, the RMS over draws,
// "sampled": drawn in rounds that double the draws until the 95% interval of the RMS error
// (draws.h) has a relative half-width <= target_half_width or max_draws are drawn.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "shpack/io/io_status.h"
#include "shpack/sampling_methods.h"
#include "shpack/study/accuracy.h"
#include "shpack/study/draws.h"
#include "shpack/study/expected_error.h"
#include "shpack/study/study_inputs.h"

namespace shpack::study {

struct StudySettings {
  unsigned repeats = 5;  // timed runs per spec, >= 1
  unsigned threads = 1;  // ProjectOptions::threads (0 = all cores); only exact, center, mip use it
  unsigned seeds = 16;   // draws of each random method, >= 1 (qmc: the first round)
  double target_half_width = 0.1;  // qmc: relative half-width of the RMS error's 95% interval
  // qmc: the cap on its draws. The default, the first round's, keeps `shpack bench` as fast as
  // with a fixed count (128 made it 1.6x slower on a bundled map); the interval then says how
  // wide it is, and scripts/accuracy-doc.sh asks for 128.
  unsigned max_draws = 16;
};

struct StudyRecord {
  std::string input;
  std::uint32_t width = 0, height = 0;
  MethodSpec spec;
  unsigned threads = 1;      // threads the method ran on (1 for those that ignore the option)
  unsigned repeats = 0;
  double samples = 0;        // sample_count (method_sweep.h)
  double time_ms_median = 0, time_ms_min = 0, time_ms_max = 0;
  unsigned seeds = 1;        // draws measured (StudySettings::seeds for a random method)
  AccuracyMetrics accuracy;  // over the draws as draws.h says: RMS errors, the lowest minimum
  Spread err_max_spread, err_rms_spread;  // of err_max_pct and err_rms_pct over the draws
  Interval err_max_interval, err_rms_interval;  // 95% intervals of those RMS (draws.h)
  // The expected errors and their kinds (above).
  double expected_err_rms_pct = 0, expected_err_max_pct = 0;
  ErrorKind err_rms_kind = ErrorKind::Exact, err_max_kind = ErrorKind::Exact;
  std::array<double, 3> load_average{};   // /proc/loadavg after the timing (load_average.h)
};

// Called after each spec, with the number of specs done and their total.
using StudyProgress = std::function<void(const StudyRecord&, std::size_t done, std::size_t total)>;

// Appends one record per spec to `out`. Texels are read with NonFinite::Zero (a NaN in a
// user's map must not stop the study; convert reports them) and Negative::Keep. Errors
// name the input: InvalidArgument for repeats or seeds == 0, Core for a projection that fails
// (OutOfMemory for a large mip or is buffer, or an invalid spec).
io::IoStatus run_study(const StudyImage& image, const std::vector<MethodSpec>& specs,
                       const StudySettings& settings, std::vector<StudyRecord>& out,
                       const StudyProgress& progress = {});

}  // namespace shpack::study
