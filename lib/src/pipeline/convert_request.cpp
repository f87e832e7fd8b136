// convert_request.cpp - the user-level options of a conversion into the pipeline's options
// (convert_request.h). The values the command line's parser checks before this runs (the
// method and window texts, the numbers' domains) are checked here too, with the parser's
// words, so that every caller refuses the same requests in the same terms.
#include "shpack/convert_request.h"

#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>

#include "shpack/sampling_methods.h"
#include "shpack/window.h"

namespace shpack {
namespace {

// The shortest text that reads back to `value` ("-1", "0.5", "inf", "nan").
std::string number_text(double value) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return error == std::errc() ? std::string(text, end) : std::string("?");
}

// "--OPTION: 'VALUE' is not WHAT", as the command line's validators say it.
std::string not_a(std::string_view option, std::string_view value, std::string_view what) {
  std::string line(option);
  line.append(": '").append(value).append("' is not ").append(what);
  return line;
}

}  // namespace

std::string to_convert_options(const ConvertRequest& request, ConvertOptions& out) {
  ConvertOptions options;
  if (Status st = parse_method(request.method, options.method); !st.ok()) {
    std::string line("--method: '");
    return line.append(request.method).append("': ").append(st.what);
  }
  if (request.seed) {
    // "mc:N:SEED" and --seed both name a seed; taking either silently could surprise.
    if (request.method.find(':') != request.method.rfind(':')) return "give the seed once, in --method or with --seed";
    options.method.seed = *request.seed;
  }
  if (!std::isfinite(request.intensity) || request.intensity < 0)
    return not_a("--intensity", number_text(request.intensity), "a finite number >= 0");
  if (!std::isfinite(request.exposure)) return not_a("--exposure", number_text(request.exposure), "a finite number");
  if (!std::isfinite(request.rotate_deg)) return not_a("--rotate", number_text(request.rotate_deg), "a finite number");
  if (Status st = parse_window(request.window, options.finish.window); !st.ok())
    return std::string("--window: ").append(st.what);
  if (request.extract_lights > kMaxExtractedLights) {
    return not_a("--extract-lights", std::to_string(request.extract_lights),
                 std::string("an integer from 0 to ").append(std::to_string(kMaxExtractedLights)));
  }
  const double factor = request.intensity * std::exp2(request.exposure);
  if (!std::isfinite(factor)) return "--intensity times 2^--exposure is not a finite number";
  options.nonfinite = request.nonfinite;
  options.negative = request.negative;
  options.threads = request.threads;
  options.extract_sun = request.extract_sun;
  options.extract_lights = request.extract_lights;
  options.finish.intensity = factor;
  options.finish.rotate_deg = request.rotate_deg;
  options.finish.l1 = request.l1;
  out = options;
  return {};
}

}  // namespace shpack
