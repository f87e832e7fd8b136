#include "shpack/study/study.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "shpack/study/load_average.h"
#include "shpack/study/method_sweep.h"

namespace shpack::study {
namespace {

bool uses_threads(SamplingMethod m) noexcept {
  return m == SamplingMethod::Exact || m == SamplingMethod::Center || m == SamplingMethod::Mip;
}

// The median of an odd count is its middle; of an even count, the mean of the two middles.
double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
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
  for (const MethodSpec& spec : specs) {
    const std::string name(method_name(spec).view());
    // The draws, untimed; the first is also the timing's warm-up.
    const unsigned seeds = uses_seed(spec.method) ? settings.seeds : 1;
    std::vector<AccuracyMetrics> draws;
    for (unsigned k = 0; k < seeds; ++k) {
      MethodSpec draw = spec;
      draw.seed += k;
      ShL2 radiance;
      if (Status st = project_with_method(image.view(), draw, options, radiance); !st.ok())
        return io::IoStatus::error(io::IoErrc::Core, image.name, name + ": " + st.what);
      draws.push_back(meter.measure(radiance));
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
    record.seeds = seeds;
    const DrawSummary summary = summarize_draws(draws);
    record.accuracy = summary.accuracy;
    record.err_max_spread = summary.err_max;
    record.err_rms_spread = summary.err_rms;
    record.load_average = read_load_average();
    records.push_back(record);
    if (progress) progress(record, records.size(), specs.size());
  }
  out.insert(out.end(), records.begin(), records.end());
  return io::IoStatus::success();
}

}  // namespace shpack::study
