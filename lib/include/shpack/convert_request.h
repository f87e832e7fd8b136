// convert_request.h - a conversion as a user asks for it, in the words of `shpack convert`'s
// options (README.md's table), and its translation into the pipeline's ConvertOptions
// (pipeline.h): the one place where the user-level options become stage options, for the
// command line (cli/convert_command.cpp) and the Python module (python/shpack_module.cpp).
//
// What the translation decides: the method text and an optional seed become one MethodSpec
// (a seed given twice is refused rather than one silently winning); the window text becomes
// a Window; intensity and exposure become one linear factor, intensity * 2^exposure, which
// is what the finish stage applies and the document records. The options of stage 1 (layout,
// layer, colour space, cube frame) are the source's, not the request's.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "shpack/pipeline.h"
#include "shpack/project.h"

namespace shpack {

struct ConvertRequest {
  std::string method = "exact";        // --method (parse_method)
  std::optional<std::uint64_t> seed;   // --seed: for mc, qmc and is
  NonFinite nonfinite = NonFinite::Error;  // --nonfinite
  Negative negative = Negative::Keep;      // --negative
  double intensity = 1.0;   // --intensity: a linear factor, finite and >= 0
  double exposure = 0.0;    // --exposure: EV, a further factor 2^exposure
  double rotate_deg = 0.0;  // --rotate: yaw about +Y in degrees (rotate.h)
  std::string window = "none";  // --window (parse_window)
  bool l1 = false;              // --l1
  bool extract_sun = false;     // --extract-sun
  unsigned extract_lights = 0;  // --extract-lights N, 0 <= N <= kMaxExtractedLights
  unsigned threads = 0;         // --threads: 0 = all cores
};

// The ConvertOptions of `request` into `out`, and "" on success; otherwise `out` is left as
// it was and the result is the problem as one line naming the option, e.g. "--method: 'fast':
// unknown method name" or "--intensity times 2^--exposure is not a finite number" (the
// command line reports it after "convert: " or, for the values its parser checks first, as
// its parser does). The checks that need the layout (check_convert_options) come later,
// where the layout is known.
std::string to_convert_options(const ConvertRequest& request, ConvertOptions& out);

}  // namespace shpack
