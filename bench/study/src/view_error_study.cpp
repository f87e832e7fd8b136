#include "shpack/study/view_error_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "shpack/study/draws.h"

namespace shpack::study {
namespace {

ViewErrorConfig config(std::string label, unsigned lights, bool sun, std::string_view window) {
  ConvertOptions options;
  options.nonfinite = NonFinite::Zero;
  options.threads = 1;
  options.extract_lights = lights;
  options.extract_sun = sun;
  (void)parse_window(window, options.finish.window);  // the names below all parse
  return {std::move(label), options};
}

// The lowest E/pi of the SH (the lights add none below it: max(0, n . l) >= 0) in % of the
// channel's mean, the SH's L0 term sh0 (unity_pack.h: E/pi's mean over the sphere is sh0).
double lowest_pct(const FinishedSh& sh) {
  double lowest = std::numeric_limits<double>::infinity();
  for (int c = 0; c < kChannelCount; ++c) {
    const double mean = sh.unity_form.c[c][0];
    if (mean > 0) lowest = std::min(lowest, 100 * sh.min_e_over_pi[c].value / mean);
  }
  return std::isfinite(lowest) ? lowest : 0.0;  // a black map: 0
}

}  // namespace

std::vector<ViewErrorConfig> view_error_configs() {
  std::vector<ViewErrorConfig> configs = {config("plain", 0, false, "none"), config("extract-sun", 0, true, "none")};
  for (unsigned n = 1; n <= 4; ++n) configs.push_back(config("extract-lights " + std::to_string(n), n, false, "none"));
  for (const char* window : {"hanning:4", "lanczos:4", "unity", "sloan", "optimal"})
    configs.push_back(config(std::string("window ") + window, 0, false, window));
  configs.push_back(config("extract-lights 4, window optimal", 4, false, "optimal"));
  return configs;
}

io::IoStatus run_view_error_study(const StudyImage& image, unsigned repeats, std::vector<ViewErrorRecord>& out) {
  if (repeats == 0) return io::IoStatus::error(io::IoErrc::InvalidArgument, image.name, "repeats must be >= 1");
  std::vector<ViewErrorRecord> records;
  for (const ViewErrorConfig& c : view_error_configs()) {
    std::vector<double> ms;
    Conversion conversion;
    for (unsigned r = 0; r <= repeats; ++r) {  // run 0: the result, and the warm-up
      std::vector<float> pixels = image.pixels;
      MapImage map;
      map.image = make_view(pixels.data(), image.width, image.height, image.channels);
      map.writable = pixels.data();
      const auto start = std::chrono::steady_clock::now();
      const Status st = convert_map(map, c.options, conversion);
      const auto stop = std::chrono::steady_clock::now();
      if (!st.ok()) return io::IoStatus::error(io::IoErrc::Core, image.name, c.label + ": " + st.what);
      if (r > 0) ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    }
    ViewErrorRecord record{image.name, c.label, conversion.view_error.value_or(ViewError{}),
                           lowest_pct(conversion.sh), conversion.lights.size() + (conversion.sun ? 1 : 0),
                           median(ms), *std::min_element(ms.begin(), ms.end()), *std::max_element(ms.begin(), ms.end())};
    records.push_back(std::move(record));
  }
  out.insert(out.end(), records.begin(), records.end());
  return io::IoStatus::success();
}

}  // namespace shpack::study
