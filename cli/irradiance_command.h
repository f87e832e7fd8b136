// irradiance_command.h - `shpack irradiance IN -o OUT.exr`: E/pi of a map as an image
// (irradiance_image.h), from what Unity shows of its L2 SH, from the map itself exactly (with
// its bound), or by the seeds' Riemann and Monte Carlo sums at a sample count.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

#include "shpack/irradiance_image.h"
#include "shpack/layout.h"
#include "shpack/sampling_methods.h"

namespace shpack::cli {

struct IrradianceOptions {
  std::string input;
  std::string output;
  Layout input_layout = Layout::Auto;  // --input-layout, as convert's --layout
  Layout layout = Layout::Equirect;    // --layout: the output's
  std::uint32_t size = 128;
  std::string source = "exact";        // sh, exact, riemann:N, mc:N
  std::uint64_t seed = kDefaultMethodSeed;
  unsigned threads = 0;
};

CLI::App* add_irradiance_command(CLI::App& app, IrradianceOptions& options);

// Exit code: kExitOk, kExitFailure if the map cannot be read or the image written, kExitUsage
// for a bad command line.
int run_irradiance(const IrradianceOptions& options);

// "sh", "exact", "riemann:N", "mc:N" (N >= 1) into `request`'s source and samples; false for
// anything else.
bool parse_irradiance_source(const std::string& text, IrradianceRequest& request);

}  // namespace shpack::cli
