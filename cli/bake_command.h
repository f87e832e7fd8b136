// bake_command.h - `shpack bake SCENE.json -o OUT.json`: one Unity SH per probe of a scene.
//
// Reads the scene (docs/scenes.md; scene_loader.h), simulates the effects it lists
// (bake.h), and writes the probes' coefficients and each effect's cost (bake_json.h); a
// scene's lightmaps (lightmap_bake.h) go to their own images and sidecars (lightmap_output.h). A
// progress bar goes to stderr while it runs, when stderr is a terminal.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "shpack/bake/bake_json.h"

namespace shpack::cli {

struct BakeCommandOptions {
  std::string scene;
  std::string output;  // -o; empty: stdout
  bake::BakeFormat format = bake::BakeFormat::Full;
  std::string window = "none";  // --window, parsed by shpack::parse_window
  unsigned threads = 0;         // 0: all hardware threads
  bool quiet = false;           // no progress bar
  std::string lightmap_dir;     // --lightmap-dir; empty: the output's folder (stdout: the current one)
};

CLI::App* add_bake_command(CLI::App& app, BakeCommandOptions& options);

// Exit code: kExitOk, kExitFailure when the scene cannot be read or baked or the output
// written (nothing is written then), kExitUsage for a bad command line.
int run_bake(const BakeCommandOptions& options);

}  // namespace shpack::cli
