// merge_command.h - `shpack merge PART... -o OUT.json`: the parts of a sharded bake
// (`shpack bake SCENE.json --shard K/N -o PART`) joined into exactly what `shpack bake
// SCENE.json -o OUT.json` writes (bake_part.h, docs/scale.md).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "bake_command.h"

namespace shpack::cli {

struct MergeOptions {
  std::vector<std::string> parts;
  std::string scene;         // --scene; empty: the path the parts recorded
  BakeCommandOptions output; // -o, --format, --window, --lightmap-dir, --quiet
};

CLI::App* add_merge_command(CLI::App& app, MergeOptions& options);

// Exit code: kExitOk; kExitFailure for a part that cannot be read or does not belong (one
// line naming it), the scene, or an output that cannot be written (nothing is written then);
// kExitUsage for a bad command line.
int run_merge(const MergeOptions& options);

}  // namespace shpack::cli
