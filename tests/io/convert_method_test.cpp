// `shpack convert --method NAME[:PARAM] --seed S`: every method of sampling_methods.h from
// the command line, named in the JSON, repeatable bit for bit.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <limits>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/pipeline.h"

namespace {

namespace fs = std::filesystem;
using shpack_io_test::CliRun;
using shpack_io_test::hdri;
using shpack_io_test::run_shpack;
using shpack_io_test::ScratchDir;

nlohmann::json parsed(const CliRun& run) {
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return nlohmann::json::parse(run.out, nullptr, /*allow_exceptions=*/false);
}

TEST(ConvertMethod, RandomMethodIsRepeatableBitForBitAndFollowsTheSeed) {
  const ScratchDir dir;
  const std::string courtyard = hdri("courtyard.exr").string();
  const CliRun first = run_shpack(dir, {"convert", courtyard, "--method", "mc:4096", "--seed", "7"});
  const CliRun again = run_shpack(dir, {"convert", courtyard, "--method", "mc:4096", "--seed", "7"});
  const CliRun other = run_shpack(dir, {"convert", courtyard, "--method", "mc:4096", "--seed", "8"});
  const nlohmann::json a = parsed(first), b = parsed(again), c = parsed(other);
  ASSERT_FALSE(a.is_discarded());
  ASSERT_FALSE(c.is_discarded());
  EXPECT_EQ(first.out, again.out);  // the whole document, every digit
  EXPECT_EQ(a["options"]["method"], "mc:4096:7");
  EXPECT_EQ(c["options"]["method"], "mc:4096:8");
  EXPECT_NE(a["radiance_sh"], c["radiance_sh"]);
  // The same seed spelled in the spec gives the same document.
  EXPECT_EQ(run_shpack(dir, {"convert", courtyard, "--method", "mc:4096:7"}).out, first.out);
}

TEST(ConvertMethod, EveryMethodNamesItselfInTheJson) {
  const ScratchDir dir;
  const std::string studio = hdri("studio.exr").string();
  for (const std::string method : {"exact", "center", "mip:2", "qmc:256", "fib:256", "is:256", "riemann:16",
                                   "cube:8", "cube-exact:8", "lsq:64"}) {
    const nlohmann::json doc = parsed(run_shpack(dir, {"convert", studio, "--method", method}));
    ASSERT_FALSE(doc.is_discarded()) << method;
    EXPECT_EQ(doc["options"]["method"], method);
  }
  // The default seed is not written: the name reads back to the same spec either way.
  const nlohmann::json mc = parsed(run_shpack(dir, {"convert", studio, "--method", "mc:64"}));
  EXPECT_EQ(mc["options"]["method"], "mc:64");
}

TEST(ConvertMethod, ExactAndCenterStillStream) {
  const ScratchDir dir;
  const std::string studio = hdri("studio.exr").string();
  EXPECT_EQ(run_shpack(dir, {"convert", studio, "--method", "exact"}).out,
            run_shpack(dir, {"convert", studio}).out);
  shpack::ConvertOptions center, mip;
  center.method.method = shpack::SamplingMethod::Center;
  mip.method.method = shpack::SamplingMethod::Mip;
  EXPECT_TRUE(shpack::streams_rows(center, shpack::Layout::Equirect));
  EXPECT_FALSE(shpack::streams_rows(mip, shpack::Layout::Equirect));
}

TEST(ConvertMethod, BadSpecsAreUsageErrors) {
  const ScratchDir dir;
  const std::string studio = hdri("studio.exr").string();
  const std::vector<std::vector<std::string>> usage_errors = {
      {"--method", "mc"},          {"--method", "mc:0"},       {"--method", "lsq:8"},
      {"--method", "exact:3"},     {"--method", "fib:64:3"},   {"--method", "mc:4096", "--seed", "-1"},
      {"--method", "mc:64:3", "--seed", "4"},  // the seed given twice
  };
  for (const std::vector<std::string>& extra : usage_errors) {
    std::vector<std::string> args = {"convert", studio};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun run = run_shpack(dir, args);
    EXPECT_EQ(run.exit_code, 2) << extra[1] << "\n" << run.err;
    EXPECT_EQ(run.err.rfind("shpack: ", 0), 0u) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
  }
}

TEST(ConvertMethod, SampledNaNIsReportedWithTheRemedy) {
  const ScratchDir dir;
  const std::vector<float> nan(8 * 4 * 3, std::numeric_limits<float>::quiet_NaN());
  ASSERT_TRUE(shpack_io_test::write_image(dir / "nan.exr", 8, 4, 3, nan));
  CliRun run = run_shpack(dir, {"convert", (dir / "nan.exr").string(), "--method", "fib:16"});
  EXPECT_EQ(run.exit_code, 1);
  // fib:16 reads 16 texels, all NaN; the first sample is nearest the +Y pole (row 0).
  EXPECT_EQ(run.err.rfind("shpack: " + (dir / "nan.exr").string() + ": 16 NaN/Inf texel reads by fib:16 (first at x=", 0), 0u)
      << run.err;
  EXPECT_NE(run.err.find(", y=0); use --nonfinite=zero to replace them\n"), std::string::npos) << run.err;
  run = run_shpack(dir, {"convert", (dir / "nan.exr").string(), "--method", "fib:16", "--nonfinite=zero"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

TEST(ConvertMethod, SampledMethodsNeedAnEquirectShape) {
  const ScratchDir dir;
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "odd.exr", 6, 4, {1.0f, 1.0f, 1.0f}));
  const CliRun run = run_shpack(dir, {"convert", (dir / "odd.exr").string(), "--method", "mc:64"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("cannot be detected"), std::string::npos) << run.err;
  EXPECT_EQ(run_shpack(dir, {"convert", (dir / "odd.exr").string(), "--method", "mc:64", "--layout", "equirect"})
                .exit_code,
            0);
}

}  // namespace
