// convert_command.h - `shpack convert`: environment maps to Unity SH JSON documents.
//
//   shpack convert IN [-o OUT.json]        one map; without -o the JSON goes to stdout
//   shpack convert IN... --out-dir DIR     one DIR/<stem>.json per map; a failed map is
//                                          reported and the others are still converted
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "shpack/io/layout.h"
#include "shpack/project.h"

namespace shpack::cli {

struct ConvertOptions {
  std::vector<std::string> inputs;
  std::string output;   // -o; empty: stdout
  std::string out_dir;  // --out-dir
  io::Layout layout = io::Layout::Auto;
  Method method = Method::Exact;
  NonFinite nonfinite = NonFinite::Error;
  Negative negative = Negative::Keep;
  double intensity = 1.0;  // linear factor
  double exposure = 0.0;   // EV: a further factor 2^exposure
  double rotate_deg = 0.0; // yaw about +Y, degrees (Skybox/Panoramic _Rotation)
  std::string window = "none";  // --window, parsed by shpack::parse_window
  unsigned threads = 0;    // 0: all hardware threads
};

CLI::App* add_convert_command(CLI::App& app, ConvertOptions& options);

// Exit code: kExitOk, kExitFailure if any input failed, kExitUsage for a bad command line.
int run_convert(const ConvertOptions& options);

}  // namespace shpack::cli
