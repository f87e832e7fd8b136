// plot.h - the error-against-time picture of a study, drawn by gnuplot.
//
// One point per spec (summarize: median time, worst max error over the inputs), on log
// axes, one line per method through its parameters; the Pareto front (the specs that no
// faster spec beats in error) as a grey staircase behind them, and exact, whose error is 0 and
// cannot sit on a log axis, as a vertical line at its time. gnuplot (docs/dependencies.md)
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

// Writes PREFIX.png and PREFIX.svg with the `gnuplot` found on PATH. Both are drawn under
// temporary names and renamed once gnuplot succeeded, so a failure replaces neither.
// Errors: NotFound when gnuplot is not installed, WriteFailed with gnuplot's first error
// line, each naming the output.
io::IoStatus write_plot(const std::vector<StudyRecord>& records, const std::string& prefix);

}  // namespace shpack::study
