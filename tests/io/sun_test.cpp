// convert --extract-sun from the command line: the document's "sun" is an object with the
// Unity light when the map has a sun, null when it has none, absent without the option; the
// option reads equirect maps only. The extraction itself (direction, irradiance, the sky's
// SH, the Unity light) is the core's, tested on pixels in tests/extraction.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "cli_runner.h"
#include "io_test_files.h"

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

}  // namespace
}  // namespace shpack::io
