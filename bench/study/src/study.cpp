#include "shpack/study/study.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <thread>

#include "shpack/study/draws.h"
#include "shpack/study/load_average.h"
#include "shpack/study/method_sweep.h"
#include "shpack/sampling_variance.h"

namespace shpack::study {
namespace {

bool uses_threads(SamplingMethod m) noexcept {
  return m == SamplingMethod::Exact || m == SamplingMethod::Center || m == SamplingMethod::Mip;
}

// True once the RMS error over the draws is known to `target` (relative half-width of its
// 95% interval, draws.h).
bool narrow(const std::vector<AccuracyMetrics>& draws, double target) {
  std::vector<double> err_rms;
  for (const AccuracyMetrics& d : draws) err_rms.push_back(d.err_rms_pct);
  return relative_half_width(rms_interval(err_rms), rms(err_rms)) <= target;
}

// The expected errors of study.h: from the per-term variance of a closed-form method, else
// the measured error, exact for one draw and sampled for several.
void set_expected_errors(StudyRecord& r, const ShL2* variance, const ShL2& reference) {
  if (variance != nullptr) {
    r.expected_err_rms_pct = expected_rms_pct(*variance, r.spec.param, reference);
    r.expected_err_max_pct = kMaxOverRmsBound * r.expected_err_rms_pct;
    r.err_rms_kind = ErrorKind::Exact;
    r.err_max_kind = ErrorKind::Bound;
    return;
  }
  r.expected_err_rms_pct = r.accuracy.err_rms_pct;
  r.expected_err_max_pct = r.accuracy.err_max_pct;
  r.err_rms_kind = r.err_max_kind = r.seeds > 1 ? ErrorKind::Sampled : ErrorKind::Exact;
}

}  // namespace

io::IoStatus run_study(const StudyImage& image, const std::vector<MethodSpec>& specs,
                       const StudySettings& settings, std::vector<StudyRecord>& out,
                       const StudyProgress& progress) {
  if (settings.repeats == 0 || settings.seeds == 0)
    return io::IoStatus::error(io::IoErrc::InvalidArgument, image.name, "repeats and seeds must be >= 1");
  ProjectOptions options;
  options.nonfinite = NonFinite::Zero;
  options.negative = Negative::Keep;
  options.threads = settings.threads;
  const unsigned all_threads =
      settings.threads != 0 ? settings.threads : std::max(1u, std::thread::hardware_concurrency());

  ShL2 reference;
  if (Status st = project_with_method(image.view(), MethodSpec{}, options, reference); !st.ok())
    return io::IoStatus::error(io::IoErrc::Core, image.name, std::string("exact: ") + st.what);
  const AccuracyMeter meter(reference);

  std::vector<StudyRecord> records;
  std::map<SamplingMethod, ShL2> variances;  // of one term, per closed-form method (expected_error.h)
  for (const MethodSpec& spec : specs) {
    const std::string name(method_name(spec).view());
    // The draws, untimed; the first is also the timing's warm-up.
    std::vector<AccuracyMetrics> draws;
    auto draw_until = [&](unsigned count) -> Status {
      for (auto k = static_cast<unsigned>(draws.size()); k < count; ++k) {
        MethodSpec draw = spec;
        draw.seed += k;
        ShL2 radiance;
        if (Status st = project_with_method(image.view(), draw, options, radiance); !st.ok()) return st;
        draws.push_back(meter.measure(radiance));
      }
      return Status::success();
    };
    Status drawn = draw_until(uses_seed(spec.method) ? settings.seeds : 1);
    if (spec.method == SamplingMethod::QuasiMonteCarlo) {
      while (drawn.ok() && draws.size() < settings.max_draws && !narrow(draws, settings.target_half_width))
        drawn = draw_until(std::min<unsigned>(settings.max_draws, 2 * static_cast<unsigned>(draws.size())));
    }
    if (!drawn.ok()) return io::IoStatus::error(io::IoErrc::Core, image.name, name + ": " + drawn.what);
    const bool closed_form = spec.method == SamplingMethod::MonteCarlo || spec.method == SamplingMethod::Importance;
    if (closed_form && !variances.contains(spec.method)) {
      if (Status st = sample_variance(image.view(), spec.method, options, variances[spec.method]); !st.ok())
        return io::IoStatus::error(io::IoErrc::Core, image.name, name + " variance: " + st.what);
    }
    std::vector<double> ms;
    for (unsigned r = 0; r < settings.repeats; ++r) {
      ShL2 timed;
      const auto start = std::chrono::steady_clock::now();
      const Status st = project_with_method(image.view(), spec, options, timed);
      const auto stop = std::chrono::steady_clock::now();
      // The same call succeeded just before; a failure now (memory) is still an error.
      if (!st.ok()) return io::IoStatus::error(io::IoErrc::Core, image.name, name + ": " + st.what);
      ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    }
    StudyRecord record;
    record.input = image.name;
    record.width = image.width;
    record.height = image.height;
    record.spec = spec;
    record.threads = uses_threads(spec.method) ? all_threads : 1;
    record.repeats = settings.repeats;
    record.samples = sample_count(spec, image.width, image.height);
    record.time_ms_median = median(ms);
    record.time_ms_min = *std::min_element(ms.begin(), ms.end());
    record.time_ms_max = *std::max_element(ms.begin(), ms.end());
    record.seeds = static_cast<unsigned>(draws.size());
    const DrawSummary summary = summarize_draws(draws);
    record.accuracy = summary.accuracy;
    record.err_max_spread = summary.err_max;
    record.err_rms_spread = summary.err_rms;
    record.err_max_interval = summary.err_max_interval;
    record.err_rms_interval = summary.err_rms_interval;
    set_expected_errors(record, closed_form ? &variances[spec.method] : nullptr, reference);
    record.load_average = read_load_average();
    records.push_back(record);
    if (progress) progress(record, records.size(), specs.size());
  }
  out.insert(out.end(), records.begin(), records.end());
  return io::IoStatus::success();
}

}  // namespace shpack::study
