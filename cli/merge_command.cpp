#include "merge_command.h"

#include <fstream>
#include <iterator>
#include <system_error>

#include "enum_option.h"
#include "output_check.h"
#include "report.h"
#include "shpack/bake/bake_part.h"
#include "shpack/scene/scene_loader.h"
#include "validators.h"

namespace shpack::cli {
namespace {

// A part file whole: a regular file, read to its end (its own size bounds the memory).
bool read_part(const std::string& path, bake::BakePart& part, std::string& error) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    error = path + ": not a regular file";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) {
    error = path + ": cannot be read";
    return false;
  }
  std::string why;
  if (!bake::decode_part(bytes, part, why)) {
    error = path + ": " + why;
    return false;
  }
  return true;
}

}  // namespace

CLI::App* add_merge_command(CLI::App& app, MergeOptions& options) {
  CLI::App* cmd = app.add_subcommand("merge", "Join the parts of a sharded bake (shpack bake --shard K/N) into its output");
  cmd->add_option("parts", options.parts, "The part files, every shard once, in any order")
      ->type_name("PART")
      ->required();
  cmd->add_option("-o,--output", options.output.output, "Output JSON file; - for stdout (default: stdout)")
      ->type_name("FILE");
  cmd->add_option("--scene", options.scene, "The scene file (default: the path the parts were baked from)")
      ->type_name("FILE");
  add_enum_option(*cmd, "--format", options.output.format,
                  {{"full", bake::BakeFormat::Full}, {"unity-probes", bake::BakeFormat::UnityProbes}},
                  "As shpack bake's --format (default full)");
  cmd->add_option("--window", options.output.window, "As shpack bake's --window (default none)")
      ->type_name("W")
      ->check(window_text());
  cmd->add_option("--lightmap-dir", options.output.lightmap_dir,
                  "Folder of the lightmaps' images and sidecars (default: the output's folder)")
      ->type_name("DIR");
  return cmd;
}

int run_merge(const MergeOptions& options) {
  std::vector<bake::BakePart> parts(options.parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::string error;
    if (!read_part(options.parts[i], parts[i], error)) {
      report_error(error);
      return kExitFailure;
    }
  }
  scene::Scene scene;
  const std::string scene_file = options.scene.empty() ? parts[0].scene_file : options.scene;
  if (io::IoStatus st = scene::load_scene(scene_file, scene); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  std::vector<std::filesystem::path> inputs = scene_input_files(scene);
  inputs.insert(inputs.end(), options.parts.begin(), options.parts.end());
  if (const std::string problem = check_bake_outputs(scene, options.output, inputs); !problem.empty()) {
    report_usage_error("merge", problem);
    return kExitUsage;
  }
  bake::BakeResult result;
  bake::LightmapBakeResult lightmaps;
  if (io::IoStatus st = bake::merge_parts(scene, parts, options.parts, result, lightmaps); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  return write_bake_outputs(scene, options.output, result, lightmaps);
}

}  // namespace shpack::cli
