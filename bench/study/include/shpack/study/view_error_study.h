// view_error_study.h - what Unity shows past the L2 floor (`shpack bench --view-error`): per
// map, the error of ShadeSH9 plus the extracted lights against the exact E/pi of the map
// (view_error.h), and the time of the whole conversion, for plain SH, --extract-sun,
// --extract-lights 1 to 4, each window, and --extract-lights 4 with the optimal window.
//
// Each configuration runs convert_map (pipeline.h, stages 2 to 4: the extraction, the exact
// projection, the finish, the view error) on a fresh copy of the map, untimed once (its
// result), then `repeats` times, each timed alone (steady_clock, wall); the copy is made
// before each timing starts. One thread, so that times compare across machines' core counts.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "shpack/io/io_status.h"
#include "shpack/pipeline.h"
#include "shpack/study/study_inputs.h"

namespace shpack::study {

// A configuration of the study: its label (the convert flags it stands for) and its options.
struct ViewErrorConfig {
  std::string label;
  ConvertOptions options;
};

// plain, extract-sun, extract-lights 1..4, the windows hanning:4, lanczos:4, unity, sloan,
// optimal, and extract-lights 4 with optimal: the last is the goal's (docs/accuracy.md).
std::vector<ViewErrorConfig> view_error_configs();

struct ViewErrorRecord {
  std::string input;
  std::string config;
  ViewError error;
  double min_e_over_pi_pct = 0;  // the lowest E/pi Unity shows, over channels, in % of the channel's mean
  std::size_t lights = 0;        // lights extracted (the sun counts as one)
  double time_ms_median = 0, time_ms_min = 0, time_ms_max = 0;
};

// Appends one record per configuration to `out`. Texels are read with NonFinite::Zero and
// Negative::Keep, as run_study reads them. Errors name the input: InvalidArgument for
// repeats == 0 or a map that is not RGB equirect, Core for a conversion that fails.
io::IoStatus run_view_error_study(const StudyImage& image, unsigned repeats, std::vector<ViewErrorRecord>& out);

// Markdown: per input a row of max errors (lights in brackets), then the worst input and the
// median time of each configuration; a second table of RMS errors; and how many inputs
// meet the goal (at most 5 % max error, E/pi never negative, with extract-lights 4 + optimal).
std::string view_error_markdown(const std::vector<ViewErrorRecord>& records);

// A JSON array, one object per record: input, config, max_pct, rms_pct, bound_pct,
// min_e_over_pi_pct, lights, time_ms_median, time_ms_min, time_ms_max.
std::string view_error_json(const std::vector<ViewErrorRecord>& records);

// PREFIX.png and PREFIX.svg: the max error of each configuration, one line per input, the
// 5 % goal as a dashed line. Errors: InvalidArgument for no records, and run_gnuplot's.
io::IoStatus write_view_error_plot(const std::vector<ViewErrorRecord>& records, const std::string& prefix);

}  // namespace shpack::study
