// plot.h - the error-against-time picture of a study, drawn by gnuplot.
//
// What the report's front ranks: one point per spec (summarize: median time and median
// expected RMS error of E/pi over the inputs, study.h), on log axes, one line per method
// through its parameters. mc and is are their closed form (slope exactly -0.5); qmc, which
// has none, the RMS over its draws, dashed, in a see-through band of its 95% interval; the
// deterministic rules their one error. Open points of a random method's colour are its
// draws' RMS error, a check of the line. The Pareto front is the report's
// (expected_error_front), a grey staircase behind them, and exact, whose error is 0 and
// cannot sit on a log axis, a vertical line at its time. gnuplot (docs/dependencies.md)
// writes the PNG with its cairo terminal and the SVG with its svg terminal.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "shpack/io/io_status.h"
#include "shpack/study/study.h"

namespace shpack::study {

// The gnuplot commands that draw `records` into `png` and then into `svg`.
std::string plot_script(const std::vector<StudyRecord>& records, const std::filesystem::path& png,
                        const std::filesystem::path& svg);

// Writes PREFIX.png and PREFIX.svg (gnuplot.h: drawn under temporary names, renamed once
// gnuplot succeeded). Errors: InvalidArgument when no method has an expected error to plot, and
// run_gnuplot's.
io::IoStatus write_plot(const std::vector<StudyRecord>& records, const std::string& prefix);

}  // namespace shpack::study
