#include "bench_command.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <system_error>

#include "report.h"
#include "validators.h"
#include "shpack/study/method_sweep.h"
#include "shpack/study/gnuplot.h"
#include "shpack/study/plot.h"
#include "shpack/study/scene_study.h"
#include "shpack/study/study.h"
#include "shpack/study/study_inputs.h"
#include "shpack/study/study_report.h"
#include "shpack/study/view_error_study.h"

namespace shpack::cli {
namespace {

void print_progress(const study::StudyRecord& r, std::size_t done, std::size_t total) {
  std::fprintf(stderr, "bench: %s [%zu/%zu] %s: %.3g ms, err max %.3g%%\n", r.input.c_str(), done, total,
               method_name(r.spec).c_str(), r.time_ms_median, r.accuracy.err_max_pct);
}

// Prints a study's report and, with a plot prefix, draws its plot: the exit code, given
// whether every input was measured.
int finish_report(const std::string& report, const std::string& plot_prefix, bool all_ok,
                  const std::function<io::IoStatus()>& plot) {
  std::cout << report << std::flush;
  if (!std::cout) {
    report_error("stdout: cannot write the report");
    return kExitFailure;
  }
  if (!plot_prefix.empty())
    if (const io::IoStatus st = plot(); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
  return all_ok ? kExitOk : kExitFailure;
}

bool is_scene(const std::string& input) { return std::filesystem::path(input).extension() == ".json"; }

// `shpack bench SCENE.json`: each Monte Carlo effect's error against time (scene_study.h).
int run_scene_bench(const std::vector<std::string>& scenes, const BenchOptions& options) {
  study::SceneStudySettings settings;
  settings.seeds = options.scene_seeds;
  settings.threads = options.threads;
  if (options.quick) {
    settings.counts = {64, 256, 1024};
    settings.reference_samples = 16384;
    settings.lightmap_side = 4;
  }
  std::vector<study::SceneStudyRecord> records;
  bool all_ok = true;
  for (const std::string& scene : scenes) {
    const io::IoStatus st = study::run_scene_study(scene, settings, records, [](const study::SceneStudyRecord& r) {
      std::fprintf(stderr, "bench: %s %s %s %s %.0f samples: %.3g CPU ms, err max %.3g%%, %.3g %s/s\n", r.scene.c_str(),
                   r.receivers.c_str(), r.effect.c_str(), r.estimator.c_str(), r.samples, r.cpu_ms, r.err_max_pct,
                   r.per_s, r.receivers.c_str());
    });
    if (!st.ok()) {
      report_error(st.message);
      all_ok = false;
    }
  }
  if (records.empty()) return kExitFailure;
  return finish_report(options.json ? study::scene_json_report(records) : study::scene_markdown_report(records),
                       options.plot, all_ok, [&] {
                         return study::run_gnuplot(options.plot, [&](const std::filesystem::path& png,
                                                                     const std::filesystem::path& svg) {
                           return study::scene_plot_script(records, png, svg);
                         });
                       });
}

}  // namespace

// The inputs when none are given: the installed data (<exe dir>/../share/shpack/hdri) or
// $SHPACK_DATA_DIR, never the source tree; then the synthetic maps.
std::vector<std::string> default_map_inputs() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path dir = study::find_bundled_maps(std::getenv(study::kDataDirVariable), exe);
  std::vector<std::string> inputs = study::default_inputs(dir);
  if (dir.empty())
    std::fprintf(stderr, "bench: no bundled maps (neither $%s nor <command's folder>/../share/shpack/hdri "
                 "is a folder); measuring the synthetic maps only\n", study::kDataDirVariable);
  else if (inputs.size() == study::synthetic_map_names().size())
    std::fprintf(stderr, "bench: no bundled maps in %s; measuring the synthetic maps only\n", dir.c_str());
  return inputs;
}

// --view-error: view_error_study.h on each input.
int run_view_error_bench(const std::vector<std::string>& inputs, const BenchOptions& options) {
  std::vector<study::ViewErrorRecord> records;
  bool all_ok = true;
  for (const std::string& input : inputs) {
    study::StudyImage image;
    io::IoStatus st = study::load_study_input(input, image);
    if (st.ok()) st = study::run_view_error_study(image, options.repeats, records);
    if (!st.ok()) {
      report_error(st.message);
      all_ok = false;
    } else {
      std::fprintf(stderr, "bench: %s done\n", input.c_str());
    }
  }
  if (records.empty()) return kExitFailure;
  return finish_report(options.json ? study::view_error_json(records) : study::view_error_markdown(records),
                       options.plot, all_ok, [&] { return study::write_view_error_plot(records, options.plot); });
}

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options) {
  CLI::App* cmd = app.add_subcommand("bench", "Accuracy against time of every projection method");
  cmd->add_option("inputs", options.inputs,
                  "Equirect maps (- for one on stdin), or synthetic:band-limited|texel|sun|gradient, or scenes (SCENE.json: each "
                  "Monte Carlo effect of `shpack bake` against a reference of the scene) "
                  "(default: $SHPACK_DATA_DIR/*.exr, else the installed <prefix>/share/shpack/hdri/*.exr; "
                  "then the synthetic maps)")
      ->type_name("FILE");
  cmd->add_option("--methods", options.methods,
                  "Comma-separated: a name (mc) runs its sweep, a spec (mc:4096) one run "
                  "(default: every method)")
      ->type_name("LIST")
      ->check([](const std::string& text) {
        std::vector<MethodSpec> specs;
        const Status st = study::parse_method_list(text, false, kDefaultMethodSeed, specs);
        return st.ok() ? std::string() : "'" + text + "': " + st.what;
      });
  cmd->add_option("--repeats", options.repeats, "Timed runs of each, 1 to 1000000 (default 5)")
      ->type_name("N")
      ->check(unsigned_in(1, 1000000));
  cmd->add_option("--seeds", options.seeds,
                  "Draws of each random method (mc, qmc, is), seeds SEED, SEED+1, ...: errors are their RMS "
                  "with the 10th and 90th percentiles; 1 to 1000000 (default 16)")
      ->type_name("N")
      ->check(unsigned_in(1, 1000000));
  cmd->add_option("--max-draws", options.max_draws,
                  "qmc, which has no closed-form error: draws doubled from --seeds until its RMS error's 95% "
                  "interval is within 10%, or this many; 1 to 1000000 (default 16: the first round only)")
      ->type_name("N")
      ->check(unsigned_in(1, 1000000));
  cmd->add_option("--threads", options.threads,
                  "Threads for exact, center and mip; the others use one (default 1; 0: all cores)")
      ->type_name("N")
      ->check(unsigned_integer());
  cmd->add_option("--seed", options.seed,
                  "Seed of mc, qmc and is (default " + std::to_string(kDefaultMethodSeed) + ")")
      ->type_name("N")
      ->check(unsigned_integer());
  cmd->add_option("--scene-seeds", options.scene_seeds,
                  "Bakes of a scene per sample count and estimator, 1 to 1000 (default 4)")
      ->type_name("N")
      ->check(unsigned_in(1, 1000));
  cmd->add_flag("--quick", options.quick, "Three parameters per method instead of six or seven");
  cmd->add_flag("--view-error", options.view_error,
                "Instead of the methods: the error of what Unity shows per map for plain SH, --extract-sun, "
                "--extract-lights 1 to 4 and each window, with the time of each conversion");
  cmd->add_flag("--json", options.json, "Print a JSON array, one record per run, instead of markdown");
  cmd->add_option("--plot", options.plot, "Also draw error against time into PREFIX.png and PREFIX.svg")
      ->type_name("PREFIX");
  return cmd;
}

int run_bench(const BenchOptions& options) {
  if (!options.inputs.empty() && std::all_of(options.inputs.begin(), options.inputs.end(), is_scene))
    return run_scene_bench(options.inputs, options);
  if (std::any_of(options.inputs.begin(), options.inputs.end(), is_scene)) {
    report_usage_error("bench", "bench: give scenes (.json) or maps, not both in one run");
    return kExitUsage;
  }
  std::vector<std::string> inputs = options.inputs;
  if (inputs.empty()) inputs = default_map_inputs();
  if (options.view_error) return run_view_error_bench(inputs, options);
  std::vector<MethodSpec> specs = study::full_sweep(options.quick, options.seed);
  if (!options.methods.empty() &&
      !study::parse_method_list(options.methods, options.quick, options.seed, specs).ok())
    return kExitUsage;  // checked by CLI11
  study::StudySettings settings{options.repeats, options.threads, options.seeds};
  settings.max_draws = options.max_draws;
  std::vector<study::StudyRecord> records;
  bool all_ok = true;
  for (const std::string& input : inputs) {
    study::StudyImage image;
    io::IoStatus st = study::load_study_input(input, image);
    if (st.ok()) st = study::run_study(image, specs, settings, records, print_progress);
    if (!st.ok()) {
      report_error(st.message);
      all_ok = false;
    }
  }
  if (records.empty()) return kExitFailure;
  return finish_report(options.json ? study::json_report(records) : study::markdown_report(records), options.plot,
                       all_ok, [&] { return study::write_plot(records, options.plot); });
}

}  // namespace shpack::cli
