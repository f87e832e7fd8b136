// `shpack bench`: its JSON is parseable and complete, its errors are one line. Timings are
// printed, never asserted.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/study/method_sweep.h"
#include "shpack/study/study_inputs.h"

namespace {

namespace fs = std::filesystem;
using shpack_io_test::CliRun;
using shpack_io_test::run_shpack;
using shpack_io_test::ScratchDir;

// A 64 x 32 map, smooth with one bright texel: small enough for a quick sweep under ASan.
fs::path write_tiny_map(const ScratchDir& dir) {
  std::vector<float> pixels(64 * 32 * 3);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) pixels[(y * 64 + x) * 3 + c] = 0.5f + 0.01f * float(x + y + c);
  pixels[(10 * 64 + 20) * 3] = 1000.0f;
  const fs::path path = dir / "tiny.exr";
  EXPECT_TRUE(shpack_io_test::write_image(path, 64, 32, 3, pixels));
  return path;
}

// The draws and the kinds of the expected errors (study.h): mc and is their closed form
// (RMS exact, max a bound), deterministic rules their one error, qmc drawn from --seeds (3)
// until its interval is within 10% or the cap of 128 draws the test asks for.
void check_draws_and_kinds(const nlohmann::json& r, shpack::SamplingMethod method) {
  using shpack::SamplingMethod;
  const bool closed_form = method == SamplingMethod::MonteCarlo || method == SamplingMethod::Importance;
  if (method == SamplingMethod::QuasiMonteCarlo) {
    EXPECT_GE(r["seeds"].get<unsigned>(), 3u) << r["spec"];
    EXPECT_LE(r["seeds"].get<unsigned>(), 128u) << r["spec"];
    const double low = r["err_rms_pct_ci95"][0], high = r["err_rms_pct_ci95"][1];
    if (r["seeds"] != 128) {
      EXPECT_LE(high - low, 0.2 * r["err_rms_pct"].get<double>()) << r["spec"];
    }
    EXPECT_EQ(r["error_kind"], "sampled");
    EXPECT_EQ(r["expected_err_rms_pct"], r["err_rms_pct"]);
  } else {
    EXPECT_EQ(r["seeds"], shpack::uses_seed(method) ? 3 : 1) << r["spec"];
    EXPECT_EQ(r["error_kind"], "exact") << r["spec"];
    EXPECT_EQ(r["err_max_kind"], closed_form ? "bound" : "exact") << r["spec"];
  }
  if (closed_form) {
    // The bound of expected_error.h, sqrt(E[max^2]) <= 3 sqrt(E[rms^2]), by construction.
    EXPECT_EQ(r["expected_err_max_pct"].get<double>(), 3.0 * r["expected_err_rms_pct"].get<double>());
  }
}

TEST(BenchCli, QuickJsonHasOneRecordPerRunWithTheKeys) {
  const ScratchDir dir;
  const fs::path map = write_tiny_map(dir);
  const CliRun run = run_shpack(dir, {"bench", map.string(), "--json", "--quick", "--repeats", "2", "--seed", "7",
                                      "--seeds", "3", "--max-draws", "128"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json records = nlohmann::json::parse(run.out, nullptr, /*allow_exceptions=*/false);
  ASSERT_TRUE(records.is_array()) << run.out;
  const std::vector<shpack::MethodSpec> specs = shpack::study::full_sweep(/*quick=*/true, 7);
  ASSERT_EQ(records.size(), specs.size());
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const nlohmann::json& r = records[i];
    for (const char* key : {"input", "method", "param", "seed", "seeds", "threads", "time_ms_median", "time_ms_min",
                            "time_ms_max", "err_max_pct", "err_max_pct_p10", "err_max_pct_p90", "err_rms_pct",
                            "err_rms_pct_p10", "err_rms_pct_p90", "coef_err_max", "min_e_over_pi", "load_average", "expected_err_rms_pct",
                            "expected_err_max_pct", "error_kind", "err_max_kind", "err_rms_pct_ci95",
                            "err_max_pct_ci95"})
      EXPECT_TRUE(r.contains(key)) << key << " in record " << i;
    check_draws_and_kinds(r, specs[i].method);
    EXPECT_LE(r["err_max_pct_p10"].get<double>(), r["err_max_pct_p90"].get<double>()) << r["spec"];
    EXPECT_EQ(r["load_average"].size(), 3u);
    EXPECT_EQ(r["input"], map.string());
    EXPECT_EQ(r["spec"], std::string(shpack::method_name(specs[i]).view()));
    EXPECT_EQ(r["seed"].is_null(), !shpack::uses_seed(specs[i].method)) << r["spec"];
    if (shpack::uses_seed(specs[i].method)) {
      EXPECT_EQ(r["seed"], 7u);
    }
    EXPECT_EQ(r["repeats"], 2);
    EXPECT_LE(r["time_ms_min"].get<double>(), r["time_ms_median"].get<double>());
    EXPECT_LE(r["time_ms_median"].get<double>(), r["time_ms_max"].get<double>());
    EXPECT_GE(r["err_max_pct"].get<double>(), r["err_rms_pct"].get<double>()) << r["spec"];
    EXPECT_TRUE(std::isfinite(r["min_e_over_pi"].get<double>()));
  }
  EXPECT_EQ(records[0]["method"], "exact");
  EXPECT_EQ(records[0]["err_max_pct"], 0.0);  // the reference measured against itself
  // Progress: one line per run on stderr, nothing else.
  EXPECT_EQ(static_cast<std::size_t>(std::count(run.err.begin(), run.err.end(), '\n')), specs.size()) << run.err;
}

TEST(BenchCli, MarkdownAndPlot) {
  const ScratchDir dir;
  const fs::path map = write_tiny_map(dir);
  const CliRun run = run_shpack(dir, {"bench", map.string(), "synthetic:band-limited", "--methods", "exact,center,fib",
                                      "--quick", "--repeats", "1", "--plot", (dir / "plot").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("## All 2 inputs\n"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("## Convergence\n"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\n| fib:1024 | 1024 | 1 |"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\nLoad average (1 min, /proc/loadavg) while timed: "), std::string::npos) << run.out;
  EXPECT_GT(fs::file_size(dir / "plot.png"), 0u);
  EXPECT_GT(fs::file_size(dir / "plot.svg"), 0u);
  // No temporary is left: they are hidden files beside the output (atomic_write.h).
  for (const auto& entry : fs::directory_iterator(dir.path()))
    EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();
}

// Without inputs: the maps of the folder SHPACK_DATA_DIR names, then the synthetic maps; with
// no such folder (the built command has no share/shpack/hdri beside it), the synthetic maps
// alone and one line saying so. The source tree's data/hdri is never a default.
TEST(BenchCli, WithoutInputsTheDataFolderThenTheSyntheticMaps) {
  const ScratchDir dir;
  fs::create_directories(dir / "hdri");
  const fs::path map = write_tiny_map(dir);
  fs::rename(map, dir / "hdri" / "tiny.exr");
  const std::vector<std::string> args = {"bench", "--methods", "center", "--json", "--quick", "--repeats", "1"};
  struct Unset {
    ~Unset() { unsetenv("SHPACK_DATA_DIR"); }
  } unset;  // the command inherits the variable; later tests in this process must not

  ASSERT_EQ(setenv("SHPACK_DATA_DIR", (dir / "hdri").c_str(), 1), 0);
  CliRun run = run_shpack(dir, args);
  nlohmann::json records = nlohmann::json::parse(run.out, nullptr, /*allow_exceptions=*/false);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  std::vector<std::string> inputs = {(dir / "hdri" / "tiny.exr").string()};
  for (const std::string& name : shpack::study::synthetic_map_names()) inputs.push_back(name);
  ASSERT_TRUE(records.is_array()) << run.out;
  ASSERT_EQ(records.size(), inputs.size()) << run.out;
  for (std::size_t i = 0; i < inputs.size(); ++i) EXPECT_EQ(records[i]["input"], inputs[i]);
  EXPECT_EQ(run.err.find("no bundled maps"), std::string::npos) << run.err;

  ASSERT_EQ(setenv("SHPACK_DATA_DIR", (dir / "missing").c_str(), 1), 0);
  run = run_shpack(dir, args);
  records = nlohmann::json::parse(run.out, nullptr, /*allow_exceptions=*/false);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(records.is_array()) << run.out;
  ASSERT_EQ(records.size(), inputs.size() - 1) << run.out;
  for (std::size_t i = 1; i < inputs.size(); ++i) EXPECT_EQ(records[i - 1]["input"], inputs[i]);
  // The note, then one progress line per run.
  EXPECT_EQ(run.err.rfind("bench: no bundled maps (neither $SHPACK_DATA_DIR nor ", 0), 0u) << run.err;
  EXPECT_EQ(static_cast<std::size_t>(std::count(run.err.begin(), run.err.end(), '\n')), inputs.size()) << run.err;
}

// --view-error: one record per configuration with every key; each is what `convert` with
// those flags reports (the same pipeline, bit for bit, whatever the threads); the markdown
// says whether the goal is met, and the plot is drawn.
TEST(BenchCli, ViewErrorRecordsAreWhatConvertReports) {
  const ScratchDir dir;
  const fs::path map = write_tiny_map(dir);
  CliRun run = run_shpack(dir, {"bench", "--view-error", map.string(), "--json", "--repeats", "1"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json records = nlohmann::json::parse(run.out, nullptr, /*allow_exceptions=*/false);
  ASSERT_TRUE(records.is_array()) << run.out;
  const std::vector<std::pair<std::string, std::vector<std::string>>> flags = {
      {"plain", {}},
      {"extract-sun", {"--extract-sun"}},
      {"extract-lights 2", {"--extract-lights", "2"}},
      {"window sloan", {"--window", "sloan"}},
      {"extract-lights 4, window optimal", {"--extract-lights", "4", "--window", "optimal"}}};
  std::size_t found = 0;
  for (const nlohmann::json& r : records) {
    for (const char* key : {"input", "config", "max_pct", "rms_pct", "bound_pct", "min_e_over_pi_pct", "lights",
                            "time_ms_median", "time_ms_min", "time_ms_max"})
      EXPECT_TRUE(r.contains(key)) << key;
    EXPECT_GE(r["max_pct"].get<double>(), r["rms_pct"].get<double>());
    for (const auto& [config, args] : flags) {
      if (r["config"] != config) continue;
      ++found;
      std::vector<std::string> convert = {"convert", map.string(), "--nonfinite", "zero"};
      convert.insert(convert.end(), args.begin(), args.end());
      const CliRun converted = run_shpack(dir, convert);
      ASSERT_EQ(converted.exit_code, 0) << converted.err;
      const nlohmann::json doc = nlohmann::json::parse(converted.out);
      EXPECT_EQ(r["max_pct"], doc["diagnostics"]["unity_view_error_max_pct"]) << config;
      EXPECT_EQ(r["rms_pct"], doc["diagnostics"]["unity_view_error_rms_pct"]) << config;
      const std::size_t lights = doc.contains("lights") ? doc["lights"].size() : doc.contains("sun") && doc["sun"].is_object();
      EXPECT_EQ(r["lights"], lights) << config;
    }
  }
  EXPECT_EQ(found, flags.size());
  EXPECT_GE(records.back()["min_e_over_pi_pct"].get<double>(), 0.0);  // the optimal window: never negative

  run = run_shpack(dir, {"bench", "--view-error", map.string(), "--repeats", "1", "--plot", (dir / "ve").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("\nGoal (extract-lights 4, window optimal: max error <= 5 %, E/pi never negative): met on "),
            std::string::npos)
      << run.out;
  EXPECT_GT(fs::file_size(dir / "ve.png"), 0u);
  EXPECT_GT(fs::file_size(dir / "ve.svg"), 0u);
}

TEST(BenchCli, ErrorsAreOneLine) {
  const ScratchDir dir;
  const fs::path missing = dir / "missing.exr";
  CliRun run = run_shpack(dir, {"bench", missing.string(), "--quick"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + missing.string() + ": no such file\n");

  run = run_shpack(dir, {"bench", "synthetic:nothing", "--quick"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err.rfind("shpack: synthetic:nothing: ", 0), 0u) << run.err;

  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"bench", "--methods", "mc:0"}, {"bench", "--methods", "fast"}, {"bench", "--methods", "mc,"},
           {"bench", "--repeats", "0"}, {"bench", "--threads", "-1"}, {"bench", "--seed", "-1"},
           {"bench", "--seeds", "0"}}) {
    run = run_shpack(dir, args);
    EXPECT_EQ(run.exit_code, 2) << args[2] << "\n" << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
  }
}

}  // namespace
