#include "bake_command.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>

#include "enum_option.h"
#include "output_check.h"
#include "report.h"
#include "shpack/bake/bake.h"
#include "shpack/bake/bake_part.h"
#include "shpack/bake/lightmap_output.h"
#include "shpack/io/exr_writer.h"
#include "shpack/io/atomic_write.h"
#include "shpack/scene/scene_loader.h"
#include "validators.h"

namespace shpack::cli {
namespace {

// "\rshpack bake: shadows   [##########..........]  50%  5000/10000 probes" (a lightmap's
// passes: "lightmap shadows ... points"), ended by a
// line break when the pass completes.
void draw_progress(const char* pass, std::size_t done, std::size_t total) {
  constexpr int kWidth = 30;
  const int filled = total ? static_cast<int>(kWidth * done / total) : kWidth;
  std::string bar(filled, '#');
  bar.resize(kWidth, '.');
  const bool lightmap = std::string_view(pass).starts_with("lightmap ");
  std::fprintf(stderr, "\rshpack bake: %-22s [%s] %3d%%  %zu/%zu %s", pass, bar.c_str(),
               total ? static_cast<int>(100 * done / total) : 100, done, total, lightmap ? "points" : "probes");
  if (done == total) std::fputc('\n', stderr);
  std::fflush(stderr);
}

// One line per thing done to probes inside geometry (docs/scenes.md, "Probe validity"), so
// that no invalid probe passes silently.
void warn_invalid_probes(const scene::Scene& scene, const bake::BakeResult& result) {
  const bake::ValidityCounts& counts = result.validity_counts;
  if (counts.invalid == 0) return;
  std::ostringstream os;
  os << scene.file.string() << ": ";
  const std::string file = os.str();
  os.str("");
  os << " of " << scene.probes.size() << " probes are inside geometry (more than "
     << 100 * scene.settings.validity_threshold << "% of their rays hit back faces)";
  const std::string inside = os.str();
  if (counts.moved)
    report_error(file + std::to_string(counts.moved) + inside + " and were baked at an offset_position");
  if (counts.dilated)
    report_error(file + std::to_string(counts.dilated) + inside +
                 " and were dilated: each took the distance-weighted mean of its nearest valid probes");
  const std::size_t kept = counts.invalid - counts.moved - counts.dilated;
  if (kept)
    report_error(file + std::to_string(kept) + inside + " and were kept as baked (settings.invalid_probes \"keep\")");
}

// One line when a target could not be met within settings.max_samples: how many probes, in
// which effects, and the largest error left (docs/scenes.md, "How wrong a probe may be").
void warn_capped_probes(const scene::Scene& scene, const bake::BakeResult& result) {
  std::size_t capped = 0;
  double worst = 0;
  std::string effects;
  for (std::size_t e = 0; e < bake::kEffectCount; ++e) {
    bool any = false;
    for (std::size_t k = 0; k < result.sampling.size(); ++k)
      if (result.sampling[k][e].capped) {
        any = true;
        worst = std::max(worst, result.sampling[k][e].error_pct);
      }
    if (any) effects += std::string(effects.empty() ? "" : ", ") + bake::effect_name(static_cast<bake::Effect>(e));
  }
  for (const auto& probe : result.sampling)
    capped += std::any_of(probe.begin(), probe.end(), [](const bake::EffectSampling& s) { return s.capped; }) ? 1 : 0;
  if (capped == 0) return;
  std::ostringstream os;
  os << scene.file.string() << ": " << capped << " of " << scene.probes.size() << " probes reached settings.max_samples ("
     << scene.settings.max_samples << ") before settings.target_error_pct (" << scene.settings.target_error_pct
     << " %) in " << effects << "; the largest error estimate left is " << worst << " %";
  report_error(os.str());
}

// --lightmap-dir, or the output's folder, or (stdout) the current one.
std::filesystem::path lightmap_folder(const BakeCommandOptions& options) {
  std::filesystem::path dir = options.lightmap_dir;
  if (dir.empty() && !options.output.empty() && options.output != "-")
    dir = std::filesystem::path(options.output).parent_path();
  return dir.empty() ? std::filesystem::path(".") : dir;
}

// Every file the scene's lightmaps are written to (lightmap_output.h's groups, the sidecar).
std::vector<std::filesystem::path> lightmap_files(const scene::Scene& scene, const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const scene::LightmapTarget& target : scene.lightmaps) {
    for (const char* group : {"SHAr", "SHAg", "SHAb", "texels"}) files.push_back(dir / (target.name + "." + group + ".exr"));
    if (target.l2)
      for (const char* group : {"SHBr", "SHBg", "SHBb", "SHC"}) files.push_back(dir / (target.name + "." + group + ".exr"));
    files.push_back(dir / (target.name + ".lightmap.json"));
  }
  return files;
}

// Each lightmap's images (<name>.<group>.exr) and sidecar (<name>.lightmap.json) in `dir`,
// each file written atomically; the first failure stops and is returned.
io::IoStatus write_lightmaps(const scene::Scene& scene, const bake::LightmapBakeResult& result,
                             const std::filesystem::path& dir) {
  for (std::size_t m = 0; m < result.maps.size(); ++m) {
    const scene::LightmapTarget& target = scene.lightmaps[m];
    const bake::LightmapTexels& map = result.maps[m];
    std::vector<bake::LightmapImage> images;
    std::string why;
    if (!bake::lightmap_images(target, map, images, why))
      return io::IoStatus::error(io::IoErrc::Unsupported, scene.file, why);
    for (const bake::LightmapImage& image : images)
      if (io::IoStatus st = io::write_exr(dir / (target.name + "." + image.group + ".exr"), map.width, map.height,
                                          image.channels, image.pixels);
          !st.ok())
        return st;
    if (io::IoStatus st = io::write_file_atomically(dir / (target.name + ".lightmap.json"),
                                                    bake::lightmap_sidecar(scene, target, map, result));
        !st.ok())
      return st;
  }
  return io::IoStatus::success();
}

}  // namespace

CLI::App* add_bake_command(CLI::App& app, BakeCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand("bake", "Bake a scene (lights, environment, effects) into one SH per probe");
  cmd->add_option("scene", options.scene,
                  "The scene file (docs/scenes.md); - for stdin, its files then relative to the current folder")
      ->type_name("FILE")
      ->required();
  cmd->add_option("-o,--output", options.output, "Output JSON file; - for stdout (default: stdout)")->type_name("FILE");
  add_enum_option(*cmd, "--format", options.format,
                  {{"full", bake::BakeFormat::Full}, {"unity-probes", bake::BakeFormat::UnityProbes}},
                  "full: every probe's keys and the effects' costs; unity-probes: flat positions and "
                  "SphericalHarmonicsL2 arrays (default full)");
  cmd->add_option("--window", options.window,
                  "Deringing per probe: none, hanning:W, lanczos:W, unity, sloan or optimal (default none)")
      ->type_name("W")
      ->check(window_text());
  cmd->add_option("--threads", options.threads, "Worker threads (default 0: all cores; at most the cores)")
      ->type_name("N")
      ->check(unsigned_integer());
  cmd->add_flag("--quiet", options.quiet, "No progress bar on stderr");
  cmd->add_option("--lightmap-dir", options.lightmap_dir,
                  "Folder of the lightmaps' images and sidecars (default: the output's folder)")
      ->type_name("DIR");
  cmd->add_option("--shard", options.shard,
                  "Bake only shard K of N (probes and lightmap texels balanced by cost) into the part file -o; "
                  "shpack merge joins the parts (docs/scale.md)")
      ->type_name("K/N")
      ->check([](const std::string& text) {
        bake::ShardSpec shard;
        std::string why;
        return bake::parse_shard(text, shard, why) ? std::string() : why;
      });
  return cmd;
}

int write_bake_outputs(const scene::Scene& scene, const BakeCommandOptions& options, const bake::BakeResult& result,
                       const bake::LightmapBakeResult& lightmaps) {
  bake::BakeJsonOptions json_options;
  json_options.format = options.format;
  if (!parse_window(options.window, json_options.window).ok()) return kExitUsage;  // checked by CLI11
  warn_invalid_probes(scene, result);
  warn_capped_probes(scene, result);
  if (!scene.lightmaps.empty()) {
    json_options.lightmaps = &lightmaps;
    if (io::IoStatus st = write_lightmaps(scene, lightmaps, lightmap_folder(options)); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
  }
  std::string json;
  if (io::IoStatus st = bake::bake_to_json(scene, result, json_options, json); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  if (options.output.empty()) {
    std::cout << json << std::flush;
    if (!std::cout) {
      report_error("stdout: cannot write the JSON");
      return kExitFailure;
    }
    return kExitOk;
  }
  if (io::IoStatus st = io::write_file_atomically(options.output, json); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  return kExitOk;
}

std::string check_bake_outputs(const scene::Scene& scene, const BakeCommandOptions& options,
                               const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::string> outputs{options.output};
  if (options.shard.empty())
    for (const std::filesystem::path& file : lightmap_files(scene, lightmap_folder(options)))
      outputs.push_back(file.string());
  for (const std::string& output : outputs)
    if (std::string problem = check_output_not_input(output, inputs); !problem.empty()) return problem;
  return {};
}

bake::BakeOptions engine_options(const BakeCommandOptions& options) {
  bake::BakeOptions bake_options;
  // More threads than cores cannot be faster, and each costs a stack and buffers: 100000
  // took 7 s and 550 MB for 75 probes, 2^32 - 1 ran out of memory. The output is the same for
  // any count.
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  bake_options.threads = options.threads == 0 ? 0 : std::min(options.threads, cores);
  if (!options.quiet && isatty(STDERR_FILENO)) bake_options.progress = draw_progress;
  return bake_options;
}

namespace {

// --shard K/N: the part file alone (no lightmap images: the merge writes them).
int run_shard(const scene::Scene& scene, const BakeCommandOptions& options, const bake::BakeOptions& bake_options) {
  bake::ShardSpec shard;
  std::string why;
  if (!bake::parse_shard(options.shard, shard, why)) return kExitUsage;  // checked by CLI11
  if (options.output.empty() || options.output == "-") {
    report_usage_error("bake", "--shard writes a part file: give it with -o PART");
    return kExitUsage;
  }
  bake::BakePart part;
  if (io::IoStatus st = bake::bake_part(scene, bake_options, shard, part); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  if (io::IoStatus st = io::write_file_atomically(options.output, bake::encode_part(part)); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

int run_bake(const BakeCommandOptions& options) {
  scene::Scene scene;
  if (io::IoStatus st = scene::load_scene(options.scene, scene); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  // The outputs are none of the files read: the scene, its map, its meshes (before the bake).
  if (const std::string problem = check_bake_outputs(scene, options, scene_input_files(scene)); !problem.empty()) {
    report_usage_error("bake", problem);
    return kExitUsage;
  }
  const bake::BakeOptions bake_options = engine_options(options);
  if (!options.shard.empty()) return run_shard(scene, options, bake_options);
  bake::BakeResult result;
  if (io::IoStatus st = bake::bake(scene, bake_options, result); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  bake::LightmapBakeResult lightmaps;
  if (!scene.lightmaps.empty())
    if (io::IoStatus st = bake::bake_lightmaps(scene, bake_options, lightmaps); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
  return write_bake_outputs(scene, options, result, lightmaps);
}

}  // namespace shpack::cli
