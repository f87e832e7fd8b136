// bake_command.h - `shpack bake SCENE.json -o OUT.json`: one Unity SH per probe of a scene.
//
// Reads the scene (docs/scenes.md; scene_loader.h), simulates the effects it lists
// (bake.h), and writes the probes' coefficients and each effect's cost (bake_json.h); a
// scene's lightmaps (lightmap_bake.h) go to their own images and sidecars (lightmap_output.h). A
// progress bar goes to stderr while it runs, when stderr is a terminal.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "shpack/bake/bake_json.h"
#include "shpack/bake/lightmap_bake.h"

namespace shpack::cli {

struct BakeCommandOptions {
  std::string scene;
  std::string output;  // -o; empty: stdout
  bake::BakeFormat format = bake::BakeFormat::Full;
  std::string window = "none";  // --window, parsed by shpack::parse_window
  unsigned threads = 0;         // 0: all hardware threads
  bool quiet = false;           // no progress bar
  std::string lightmap_dir;     // --lightmap-dir; empty: the output's folder (stdout: the current one)
  std::string shard;            // --shard K/N; empty: the whole bake
};

CLI::App* add_bake_command(CLI::App& app, BakeCommandOptions& options);

// Exit code: kExitOk, kExitFailure when the scene cannot be read or baked or the output
// written (nothing is written then), kExitUsage for a bad command line.
int run_bake(const BakeCommandOptions& options);

// What `shpack bake` and `shpack merge` share. The problem, one line, if an output (the JSON,
// without --shard each lightmap's files) is one of `inputs`; empty if none is.
std::string check_bake_outputs(const scene::Scene& scene, const BakeCommandOptions& options,
                               const std::vector<std::filesystem::path>& inputs);
// The engine's options from the command's: threads, progress.
bake::BakeOptions engine_options(const BakeCommandOptions& options);
// The warnings of a bake, the lightmaps' files, then the JSON (-o, atomically, or stdout).
int write_bake_outputs(const scene::Scene& scene, const BakeCommandOptions& options, const bake::BakeResult& result,
                       const bake::LightmapBakeResult& lightmaps);

}  // namespace shpack::cli
