// bench_command.h - `shpack bench [INPUTS...]`: what accuracy costs in time, per method.
//
// For each input (default: the bundled maps, installed as <prefix>/share/shpack/hdri/*.exr and
// found from the command's own path, or $SHPACK_DATA_DIR/*.exr; then the synthetic maps of
// bench/study/include/shpack/study/study_inputs.h) and each method and parameter
// (method_sweep.h), the error against exact (accuracy.h) and the time of the projection
// (study.h); a random method's error over --seeds draws (draws.h); the machine's load
// average while it was timed (load_average.h). stdout gets a markdown report, or with --json
// a JSON array; --plot PREFIX draws PREFIX.png and PREFIX.svg (plot.h). Progress goes to
// stderr, one line per run.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "shpack/sampling_methods.h"

namespace shpack::cli {

struct BenchOptions {
  std::vector<std::string> inputs;  // files or synthetic:NAME; empty: the defaults
  std::string methods;              // --methods; empty: every method's sweep
  unsigned repeats = 5;             // timed runs per method and parameter
  unsigned seeds = 16;              // draws of each random method (mc, qmc, is) per parameter
  unsigned max_draws = 16;         // qmc: the cap on its draws (study.h)
  unsigned scene_seeds = 4;         // bakes of a scene per sample count and estimator
  unsigned threads = 1;             // for exact, center, mip; 0: all cores
  std::uint64_t seed = kDefaultMethodSeed;
  bool quick = false;               // a shorter sweep (CI)
  bool view_error = false;          // --view-error: what Unity shows per configuration (view_error_study.h)
  bool json = false;
  std::string plot;                 // --plot PREFIX; empty: no plot
};

CLI::App* add_bench_command(CLI::App& app, BenchOptions& options);

// Exit code: kExitOk, kExitFailure if an input or the plot failed (the other inputs are
// still measured and reported), kExitUsage for a bad command line.
int run_bench(const BenchOptions& options);

}  // namespace shpack::cli
