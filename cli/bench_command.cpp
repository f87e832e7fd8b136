#include "bench_command.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "report.h"
#include "validators.h"
#include "shpack/study/method_sweep.h"
#include "shpack/study/plot.h"
#include "shpack/study/study.h"
#include "shpack/study/study_inputs.h"
#include "shpack/study/study_report.h"

namespace shpack::cli {
namespace {

void print_progress(const study::StudyRecord& r, std::size_t done, std::size_t total) {
  std::fprintf(stderr, "bench: %s [%zu/%zu] %s: %.3g ms, err max %.3g%%\n", r.input.c_str(), done, total,
               method_name(r.spec).c_str(), r.time_ms_median, r.accuracy.err_max_pct);
}

}  // namespace

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options) {
  CLI::App* cmd = app.add_subcommand("bench", "Accuracy against time of every projection method");
  cmd->add_option("inputs", options.inputs,
                  "Equirect maps, or synthetic:band-limited|texel|sun|gradient "
                  "(default: $SHPACK_DATA_DIR/*.exr, else the installed <prefix>/share/shpack/hdri/*.exr; "
                  "then the synthetic maps)");
  cmd->add_option("--methods", options.methods,
                  "Comma-separated: a name (mc) runs its sweep, a spec (mc:4096) one run "
                  "(default: every method)")
      ->check([](const std::string& text) {
        std::vector<MethodSpec> specs;
        const Status st = study::parse_method_list(text, false, kDefaultMethodSeed, specs);
        return st.ok() ? std::string() : "'" + text + "': " + st.what;
      });
  cmd->add_option("--repeats", options.repeats, "Timed runs of each (default 5)")
      ->check(unsigned_integer() & CLI::Range(1u, 1000000u));
  cmd->add_option("--threads", options.threads,
                  "Threads for exact, center and mip; the others use one (default 1; 0: all cores)")
      ->check(unsigned_integer());
  cmd->add_option("--seed", options.seed,
                  "Seed of mc, qmc and is (default " + std::to_string(kDefaultMethodSeed) + ")")
      ->check(unsigned_integer());
  cmd->add_flag("--quick", options.quick, "Three parameters per method instead of six or seven");
  cmd->add_flag("--json", options.json, "Print a JSON array, one record per run, instead of markdown");
  cmd->add_option("--plot", options.plot, "Also draw error against time into PREFIX.png and PREFIX.svg")
      ->type_name("PREFIX");
  return cmd;
}

int run_bench(const BenchOptions& options) {
  std::vector<MethodSpec> specs = study::full_sweep(options.quick, options.seed);
  if (!options.methods.empty() &&
      !study::parse_method_list(options.methods, options.quick, options.seed, specs).ok())
    return kExitUsage;  // checked by CLI11
  std::vector<std::string> inputs = options.inputs;
  if (inputs.empty()) {
    // The installed data (<exe dir>/../share/shpack/hdri) or $SHPACK_DATA_DIR; never the
    // source tree.
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path dir = study::find_bundled_maps(std::getenv(study::kDataDirVariable), exe);
    inputs = study::default_inputs(dir);
    if (dir.empty())
      std::fprintf(stderr, "bench: no bundled maps (neither $%s nor <command's folder>/../share/shpack/hdri "
                   "is a folder); measuring the synthetic maps only\n", study::kDataDirVariable);
    else if (inputs.size() == study::synthetic_map_names().size())
      std::fprintf(stderr, "bench: no bundled maps in %s; measuring the synthetic maps only\n", dir.c_str());
  }

  const study::StudySettings settings{options.repeats, options.threads};
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
  std::cout << (options.json ? study::json_report(records) : study::markdown_report(records)) << std::flush;
  if (!std::cout) {
    report_error("stdout: cannot write the report");
    return kExitFailure;
  }
  if (!options.plot.empty()) {
    if (io::IoStatus st = study::write_plot(records, options.plot); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
  }
  return all_ok ? kExitOk : kExitFailure;
}

}  // namespace shpack::cli
