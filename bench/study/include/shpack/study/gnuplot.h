// gnuplot.h - running gnuplot for the studies' pictures (plot.h, scene_study.h).
//
// A script is written beside the outputs and run by the `gnuplot` found on PATH
// (docs/dependencies.md); it draws under temporary names, which are renamed into place only
// once gnuplot succeeded, so a failure replaces neither picture.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "shpack/io/io_status.h"

namespace shpack::study {

// gnuplot's single-quoted string: no escapes but '' for a quote, so any path survives.
std::string gnuplot_quoted(const std::string& text);
// A number as gnuplot reads it back, nine significant digits.
std::string gnuplot_number(double v);

// Writes PREFIX.png and PREFIX.svg with the script that script(png, svg) returns.
// Errors: NotFound when gnuplot is not installed, WriteFailed with gnuplot's first error
// line, each naming the PNG.
io::IoStatus run_gnuplot(const std::string& prefix,
                         const std::function<std::string(const std::filesystem::path& png,
                                                         const std::filesystem::path& svg)>& script);

}  // namespace shpack::study
