// plot.h - the error-against-time picture of a study, drawn by gnuplot.
//
// One point per spec (summarize: median time, worst max error over the inputs), on log
// axes, one line per method through its parameters; a random method's (mc, qmc, is) line is
// its expected error over the draws, in a see-through band from their 10th to their 90th
// percentile (draws.h). The Pareto front (the specs that no faster spec beats in error) is
// a grey staircase behind them, and exact, whose error is 0 and cannot sit on a log axis, a
// vertical line at its time. gnuplot (docs/dependencies.md) writes the PNG with its cairo
// terminal and the SVG with its svg terminal.
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
// gnuplot succeeded). Errors: InvalidArgument when no method has an error to plot, and
// run_gnuplot's.
io::IoStatus write_plot(const std::vector<StudyRecord>& records, const std::string& prefix);

}  // namespace shpack::study
