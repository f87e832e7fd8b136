// convert --extract-sun from the command line: the document's "sun" is an object with the
// Unity light when the map has a sun, null when it has none, absent without the option; the
// option reads equirect maps only. --extract-lights N: "lights", each lowering the error. The extraction itself (direction, irradiance, the sky's
// SH, the Unity light) is the core's, tested on pixels in tests/extraction.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/light_fit.h"

namespace shpack::io {
namespace {

using shpack_io_test::ScratchDir;

TEST(SunExtractionCli, CommandWritesTheSunOrNull) {
  const ScratchDir dir;
  shpack_io_test::CliRun run = shpack_io_test::run_shpack(dir, {"convert", shpack_io_test::hdri("sunset.exr").string(), "--extract-sun"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  ASSERT_TRUE(j["sun"].is_object()) << j.dump();
  EXPECT_EQ(j["sun"]["unity_light"]["quaternion"].size(), 4u);
  EXPECT_GT(j["sun"]["irradiance"][0].get<double>(), 0.0);

  run = shpack_io_test::run_shpack(dir, {"convert", shpack_io_test::hdri("studio.exr").string(), "--extract-sun"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(nlohmann::json::parse(run.out)["sun"].is_null());
  run = shpack_io_test::run_shpack(dir, {"convert", shpack_io_test::hdri("sunset.exr").string()});
  EXPECT_FALSE(nlohmann::json::parse(run.out).contains("sun"));
  const std::string f = shpack_io_test::hdri("studio.exr").string();
  run = shpack_io_test::run_shpack(dir, {"convert", "--faces", f, f, f, f, f, f, "--extract-sun"});
  EXPECT_EQ(run.exit_code, 2) << run.err;  // equirect maps only
}

TEST(LightExtractionCli, CommandWritesTheChosenLightsOrAnEmptyArray) {
  const ScratchDir dir;
  const std::string sunset = shpack_io_test::hdri("sunset.exr").string();
  shpack_io_test::CliRun run = shpack_io_test::run_shpack(dir, {"convert", sunset, "--extract-lights", "4"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  ASSERT_TRUE(j["lights"].is_array()) << j.dump();
  ASSERT_GE(j["lights"].size(), 1u);  // its sun
  EXPECT_LE(j["lights"].size(), 4u);
  EXPECT_LE(j["lights"].size(), j["light_candidates"].get<std::size_t>());
  double before = j["lights"][0]["unity_view_error_before_pct"].get<double>();
  for (const nlohmann::json& light : j["lights"]) {
    EXPECT_EQ(light["unity_light"]["quaternion"].size(), 4u);
    EXPECT_EQ(light["unity_view_error_before_pct"].get<double>(), before);  // each starts where the last ended
    EXPECT_LT(light["unity_view_error_after_pct"].get<double>(), before);
    before = light["unity_view_error_after_pct"].get<double>();
    // The light within its reach of its source's centre (light_fit.h).
    EXPECT_LE(light["offset_deg"].get<double>(), light_reach_deg(light["angular_radius_deg"].get<double>()) + 1e-9);
  }
  // The result's max is searched from the directions the last light's was measured at
  // (view_error.h): at least it.
  EXPECT_LE(before, j["diagnostics"]["unity_view_error_max_pct"].get<double>());
  EXPECT_FALSE(j.contains("sun"));

  run = shpack_io_test::run_shpack(dir, {"convert", sunset, "--extract-lights", "0"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(nlohmann::json::parse(run.out).contains("lights"));  // 0: no extraction asked for
  run = shpack_io_test::run_shpack(dir, {"convert", sunset, "--extract-lights", "9"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("--extract-lights"), std::string::npos) << run.err;
  run = shpack_io_test::run_shpack(dir, {"convert", sunset, "--extract-lights", "2", "--extract-sun"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const std::string f = shpack_io_test::hdri("studio.exr").string();
  run = shpack_io_test::run_shpack(dir, {"convert", "--faces", f, f, f, f, f, f, "--extract-lights", "1"});
  EXPECT_EQ(run.exit_code, 2) << run.err;  // equirect maps only
}

}  // namespace
}  // namespace shpack::io
