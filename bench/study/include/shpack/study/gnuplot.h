// gnuplot.h - running gnuplot for the studies' pictures (plot.h, scene_study.h).
//
// A script is written beside the outputs and run by the `gnuplot` found on PATH
// (docs/dependencies.md); it draws under temporary names, which are renamed into place only
// once gnuplot succeeded, so a failure replaces neither picture.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "shpack/io/io_status.h"
#include "shpack/study/pareto_front.h"

namespace shpack::study {

// gnuplot's single-quoted string: no escapes but '' for a quote, so any path survives.
std::string gnuplot_quoted(const std::string& text);
// A number as gnuplot reads it back, nine significant digits.
std::string gnuplot_number(double v);

// A front's staircase as data rows "time error", for log axes: its points with both above 0;
// when it ends at an error of 0 (exact, which a log axis cannot show), a last row of the
// error before at that point's time, so the staircase runs on to where the error drops to 0.
std::string gnuplot_front_rows(const std::vector<FrontPoint>& front);

// Writes PREFIX.png and PREFIX.svg with the script that script(png, svg) returns.
// Errors: NotFound when gnuplot is not installed, WriteFailed with gnuplot's first error
// line, each naming the PNG.
io::IoStatus run_gnuplot(const std::string& prefix,
                         const std::function<std::string(const std::filesystem::path& png,
                                                         const std::filesystem::path& svg)>& script);

}  // namespace shpack::study
