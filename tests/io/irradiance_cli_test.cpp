// `shpack irradiance`: the image it writes is an OpenEXR file the project's reader reads back,
// of the output layout's size, holding E/pi (a uniform map's radiance everywhere); a bad
// source, a sampled source on a cube map and a missing input are one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/io/exr_writer.h"
#include "shpack/io/image_file.h"

namespace {

namespace fs = std::filesystem;
using shpack_io_test::CliRun;
using shpack_io_test::run_shpack;
using shpack_io_test::ScratchDir;

fs::path uniform_map(const ScratchDir& dir, int width, int height, const char* name) {
  const std::vector<float> pixels(static_cast<std::size_t>(3 * width * height), 0.5f);
  const fs::path path = dir / name;
  EXPECT_TRUE(shpack_io_test::write_image(path, width, height, 3, pixels));
  return path;
}

TEST(IrradianceCli, WritesEOverPiInTheLayoutAsked) {
  const ScratchDir dir;
  const fs::path map = uniform_map(dir, 64, 32, "uniform.exr");
  const struct {
    std::vector<std::string> flags;
    std::uint32_t width, height;
    double tolerance;  // irradiance_image_test.cpp derives each; -1: the bound the command prints
  } cases[] = {
      {{"--source", "sh", "--size", "8"}, 16, 8, 1e-6},
      {{"--source", "exact", "--layout", "hcross", "--size", "4"}, 16, 12, -1},  // its own bound
      {{"--source", "riemann:8192", "--layout", "vstrip", "--size", "4"}, 4, 24, 0.1},
      {{"--source", "mc:4096", "--size", "8", "--seed", "3"}, 16, 8, 0.061},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"irradiance", map.string(), "-o", (dir / "e.exr").string()};
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    const CliRun run = run_shpack(dir, args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    double tolerance = c.tolerance;
    if (tolerance < 0) {  // "irradiance: WxH, exact within B (...)"
      const std::size_t at = run.err.find("exact within ");
      ASSERT_NE(at, std::string::npos) << run.err;
      tolerance = std::stod(run.err.substr(at + 13)) * (1 + 1e-5);  // printed to 6 digits
    }
    shpack::io::ImageFile image;
    ASSERT_TRUE(shpack::io::read_image_file(dir / "e.exr", image).ok());
    EXPECT_EQ(image.width, c.width);
    EXPECT_EQ(image.height, c.height);
    ASSERT_EQ(image.channels, 3u);
    // A cross's or strip's texels outside the faces are 0; the hcross above has 6 of 12 cells.
    std::size_t faces = 0;
    for (float v : image.pixels)
      if (v != 0.0f) {
        ++faces;
        EXPECT_NEAR(v, 0.5, tolerance) << c.flags[1];
      }
    EXPECT_EQ(faces, c.flags[1] == "exact" ? 6u * 4 * 4 * 3 : image.pixels.size()) << c.flags[1];
  }
}

TEST(IrradianceCli, FacesAreSixFilesOfThePattern) {
  // Six N x N faces in Unity's order; each is the strip's cell (the same texel directions),
  // so face +Y of a map brighter upwards is the brightest.
  const ScratchDir dir;
  std::vector<float> pixels;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) pixels.insert(pixels.end(), 3, y < 16 ? 2.0f : 0.5f);
  ASSERT_TRUE(shpack_io_test::write_image(dir / "sky.exr", 64, 32, 3, pixels));
  const std::string pattern = (dir / "e_{face}.exr").string();
  CliRun run = run_shpack(dir, {"irradiance", (dir / "sky.exr").string(), "-o", pattern, "--layout", "faces",
                                "--size", "4", "--source", "sh"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  run = run_shpack(dir, {"irradiance", (dir / "sky.exr").string(), "-o", (dir / "strip.exr").string(), "--layout",
                         "hstrip", "--size", "4", "--source", "sh"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  shpack::io::ImageFile strip;
  ASSERT_TRUE(shpack::io::read_image_file(dir / "strip.exr", strip).ok());
  const char* names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
  for (int f = 0; f < 6; ++f) {
    shpack::io::ImageFile face;
    ASSERT_TRUE(shpack::io::read_image_file(dir / ("e_" + std::string(names[f]) + ".exr"), face).ok()) << names[f];
    ASSERT_EQ(face.width, 4u);
    ASSERT_EQ(face.height, 4u);
    for (std::uint32_t y = 0; y < 4; ++y)
      for (std::uint32_t x = 0; x < 4; ++x)
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(face.pixels[(y * 4 + x) * 3 + c], strip.pixels[(y * 24 + f * 4 + x) * 3 + c]) << names[f];
  }
  run = run_shpack(dir, {"irradiance", (dir / "sky.exr").string(), "-o", (dir / "one.exr").string(), "--layout", "faces"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
}

TEST(IrradianceCli, BadRequestsAreOneLineErrors) {
  const ScratchDir dir;
  const fs::path map = uniform_map(dir, 64, 32, "uniform.exr");
  const fs::path cross = uniform_map(dir, 64, 48, "cross.exr");
  const std::string out = (dir / "e.exr").string();
  CliRun run = run_shpack(dir, {"irradiance", map.string(), "-o", out, "--source", "mc:0"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("'mc:0'"), std::string::npos) << run.err;
  run = run_shpack(dir, {"irradiance", cross.string(), "-o", out, "--source", "riemann:100"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("equirect maps only"), std::string::npos) << run.err;
  run = run_shpack(dir, {"irradiance", (dir / "missing.exr").string(), "-o", out});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_NE(run.err.find("missing.exr"), std::string::npos) << run.err;
  for (const CliRun* r : {&run})
    EXPECT_EQ(std::count(r->err.begin(), r->err.end(), '\n'), 1) << r->err;
  EXPECT_FALSE(fs::exists(out));  // nothing was written by a failure
  // `-`: the map on stdin, and its errors named so.
  run = run_shpack(dir, {"irradiance", "-", "-o", out, "--source", "sh", "--size", "4"}, map);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(out));
  run = run_shpack(dir, {"irradiance", "-", "-o", out, "--source", "riemann:100"}, cross);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err.rfind("shpack: stdin: ", 0), 0u) << run.err;
}

}  // namespace
