// convert_command.h - `shpack convert`: environment maps to Unity SH JSON documents.
//
//   shpack convert IN [-o OUT.json]        one map; without -o the JSON goes to stdout
//   shpack convert IN... --out-dir DIR     one DIR/<stem>.json per map, in parallel across
//                                          maps; a failed map is reported (in input order)
//                                          and the others are still converted
//   shpack convert --faces PX NX PY NY PZ NZ [-o OUT.json]   six cube face files
//   shpack convert --faces 'sky_{face}.exr' [-o OUT.json]   the same, {face} = px nx py ny pz nz
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/engine_frame.h"
#include "shpack/colorspace.h"
#include "shpack/layout.h"
#include "shpack/io/image_file.h"
#include "shpack/io/output_format.h"
#include "shpack/project.h"

namespace shpack::cli {

struct ConvertOptions {
  std::vector<std::string> inputs;
  std::string output;   // -o; empty: stdout
  std::string out_dir;  // --out-dir
  Layout layout = Layout::Auto;
  std::string method = "exact";  // --method, parsed by shpack::parse_method
  std::optional<std::uint64_t> seed;  // --seed: for mc, qmc and is
  NonFinite nonfinite = NonFinite::Error;
  Negative negative = Negative::Keep;
  double intensity = 1.0;  // linear factor
  double exposure = 0.0;   // EV: a further factor 2^exposure
  double rotate_deg = 0.0; // yaw about +Y, degrees (Skybox/Panoramic _Rotation)
  std::string window = "none";  // --window, parsed by shpack::parse_window
  unsigned threads = 0;    // 0: all hardware threads
  std::optional<io::OutputFormat> format;  // --format; unset: from -o's extension, else json
  EngineFrame frame = EngineFrame::Unity;  // --frame: the frame of the JSON's radiance_sh
  bool l1 = false;         // --l1: band 2 removed (FinishOptions::l1)
  bool extract_sun = false;  // --extract-sun (light_extraction.h)
  unsigned extract_lights = 0;  // --extract-lights N (light_choice.h)
  std::vector<std::string> faces;  // --faces: six face files in Unity's order, or one {face} pattern
  CubeFrame cube_frame = CubeFrame::Unity;  // --cube-frame
  std::string layer;                        // --layer: EXR part or channel layer
  ColorSpace colorspace = ColorSpace::Auto;  // --colorspace
  std::uint64_t max_texels = io::kDefaultMaxTexels;  // --max-texels: the budget of a map's declared size
};

CLI::App* add_convert_command(CLI::App& app, ConvertOptions& options);

// Exit code: kExitOk, kExitFailure if any input failed, kExitUsage for a bad command line.
int run_convert(const ConvertOptions& options);

}  // namespace shpack::cli
