// The shpack command with layouts, faces, frames, layers and colour spaces; the exactness of
// --rotate on a map; and batches converted in parallel.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/rotate.h"
#include "shpack/sh_basis.h"

namespace {

namespace fs = std::filesystem;
using shpack_io_test::CliRun;
using shpack_io_test::hdri;
using shpack_io_test::run_shpack;
using shpack_io_test::ScratchDir;
using shpack_io_test::write_constant_image;
using Json = nlohmann::json;

Json document(const CliRun& run) {
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return Json::parse(run.out.empty() ? std::string("null") : run.out);
}

shpack::ShL2 radiance_of(const Json& doc) {
  shpack::ShL2 sh;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) sh.c[c][i] = doc["radiance_sh"][c][i].get<double>();
  return sh;
}

double max_abs(const shpack::ShL2& sh) {
  double m = 0;
  for (const auto& ch : sh.c)
    for (double v : ch) m = std::fmax(m, std::fabs(v));
  return m;
}

// R, G, B of a w x h image as float, through OpenImageIO.
bool read_rgb(const fs::path& path, int w, int h, std::vector<float>& values) {
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
  if (!in || in->spec().width != w || in->spec().height != h) return false;
  values.resize(std::size_t{3} * w * h);
  return in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, values.data());
}

void expect_near(const shpack::ShL2& a, const shpack::ShL2& b, double tol, const std::string& what) {
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(a.c[c][i], b.c[c][i], tol) << what << " c=" << c << " i=" << i;
}

TEST(CliLayouts, LayoutsAreNamedInTheJson) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "cross.exr", 8, 6, {1, 2, 3}));
  ASSERT_TRUE(write_constant_image(dir / "probe.exr", 6, 6, {1, 2, 3}));
  EXPECT_EQ(document(run_shpack(dir, {"convert", (dir / "cross.exr").string()}))["source"]["layout"], "hcross");
  const Json probe = document(run_shpack(dir, {"convert", (dir / "probe.exr").string(), "--layout", "angular"}));
  EXPECT_EQ(probe["source"]["layout"], "angular");
  EXPECT_FALSE(probe["source"].contains("cube_frame"));
  const Json framed = document(run_shpack(dir, {"convert", (dir / "cross.exr").string(), "--cube-frame", "gl"}));
  EXPECT_EQ(framed["source"]["cube_frame"], "gl");
  // A uniform environment whatever the layout: L00 = 2 sqrt(pi) R.
  EXPECT_NEAR(probe["radiance_sh"][1][0].get<double>(), 4.0 * std::sqrt(std::numbers::pi), 1e-12);
}

TEST(CliLayouts, AnAmbiguousShapeIsOneLineListingWhatFits) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "sq.exr", 6, 6, {1, 1, 1}));
  const fs::path out = dir / "out.json";
  const CliRun run = run_shpack(dir, {"convert", (dir / "sq.exr").string(), "-o", out.string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "sq.exr").string() +
                         ": the layout of a 6x6 image is ambiguous: it fits octahedral, angular and mirrorball; "
                         "name the layout with --layout\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliLayouts, FacesMakeOneDocument) {
  const ScratchDir dir;
  std::vector<std::string> args = {"convert", "--faces"};
  for (const char* name : {"px", "nx", "py", "ny", "pz", "nz"}) {
    ASSERT_TRUE(write_constant_image(dir / (std::string(name) + ".exr"), 4, 4, {1, 1, 1}));
    args.push_back((dir / (std::string(name) + ".exr")).string());
  }
  args.insert(args.end(), {"-o", (dir / "cube.json").string()});
  const CliRun run = run_shpack(dir, args);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json doc = Json::parse(shpack_io_test::read_bytes(dir / "cube.json"));
  EXPECT_EQ(doc["source"]["layout"], "faces");
  EXPECT_EQ(doc["source"]["files"], Json({"px.exr", "nx.exr", "py.exr", "ny.exr", "pz.exr", "nz.exr"}));
  EXPECT_EQ(doc["source"]["cube_frame"], "unity");

  // A face of another size: one line naming it, exit 1, nothing written.
  ASSERT_TRUE(write_constant_image(dir / "ny.exr", 8, 8, {1, 1, 1}));
  args.back() = (dir / "bad.json").string();
  const CliRun bad = run_shpack(dir, args);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.err, "shpack: " + (dir / "ny.exr").string() + ": the face is 8x8 but px.exr is 4x4\n");
  EXPECT_FALSE(fs::exists(dir / "bad.json"));
  // Five faces, or faces with inputs: a usage error.
  EXPECT_EQ(run_shpack(dir, {"convert", "--faces", "a", "b", "c", "d", "e"}).exit_code, 2);
  EXPECT_EQ(run_shpack(dir, {"convert", hdri("studio.exr").string(), "--faces", "a", "b", "c", "d", "e", "f"}).exit_code, 2);
}

// One pattern with {face} is the six files it names, in Unity's order: the same document.
TEST(CliLayouts, AFacePatternIsTheSixFilesItNames) {
  const ScratchDir dir;
  std::vector<std::string> six = {"convert", "--faces"};
  float value = 1;  // a different radiance per face, so that the order shows in the coefficients
  for (const char* name : {"px", "nx", "py", "ny", "pz", "nz"}) {
    ASSERT_TRUE(write_constant_image(dir / ("sky_" + std::string(name) + ".exr"), 4, 4, {value, 2 * value, 1}));
    six.push_back((dir / ("sky_" + std::string(name) + ".exr")).string());
    value += 1;
  }
  const CliRun explicit_run = run_shpack(dir, six);
  const CliRun pattern_run = run_shpack(dir, {"convert", "--faces", (dir / "sky_{face}.exr").string()});
  ASSERT_EQ(explicit_run.exit_code, 0) << explicit_run.err;
  ASSERT_EQ(pattern_run.exit_code, 0) << pattern_run.err;
  EXPECT_EQ(pattern_run.out, explicit_run.out);  // the same file names and coefficients, byte for byte
  EXPECT_EQ(document(pattern_run)["source"]["files"],
            Json({"sky_px.exr", "sky_nx.exr", "sky_py.exr", "sky_ny.exr", "sky_pz.exr", "sky_nz.exr"}));

  // One value without {face}: a usage error in one line, and nothing written.
  const fs::path out = dir / "out.json";
  const CliRun bad = run_shpack(dir, {"convert", "--faces", six[2], "-o", out.string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err,
            "shpack: convert: --faces takes six files, or one pattern containing {face} (see shpack convert --help)\n");
  EXPECT_FALSE(fs::exists(out));
}

// A named layout the image does not fit: the message lists what fits, and does not ask to
// name the layout (it is named).
TEST(CliLayouts, ACrossOfTheWrongAspectIsOneLineAndNothingIsWritten) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "wide.exr", 16, 8, {1, 1, 1}));
  const fs::path out = dir / "out.json";
  const CliRun run = run_shpack(dir, {"convert", (dir / "wide.exr").string(), "--layout", "hcross", "-o", out.string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "wide.exr").string() +
                         ": a 16x8 image is not a hcross (4N x 3N); its shape fits equirect\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliLayouts, AMissingFaceIsOneLineAndNothingIsWritten) {
  const ScratchDir dir;
  std::vector<std::string> args = {"convert", "--faces"};
  for (const char* name : {"px", "nx", "py", "ny", "pz", "nz"}) {
    const fs::path face = dir / (std::string(name) + ".exr");
    if (std::string(name) != "py") {  // -Y is missing
      ASSERT_TRUE(write_constant_image(face, 4, 4, {1, 1, 1}));
    }
    args.push_back(face.string());
  }
  const fs::path out = dir / "out.json";
  args.insert(args.end(), {"-o", out.string()});
  const CliRun run = run_shpack(dir, args);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "py.exr").string() + ": no such file\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliLayouts, AMissingLayerIsOneLine) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "sky.exr", 8, 4, {1, 1, 1}));
  const fs::path out = dir / "out.json";
  const CliRun run =
      run_shpack(dir, {"convert", (dir / "sky.exr").string(), "--layer", "diffuse", "-o", out.string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "sky.exr").string() + ": no layer 'diffuse' (its layers are none)\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliLayouts, ColorspaceIsRecorded) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "sky.exr", 8, 4, {1, 1, 1}));
  const Json doc = document(run_shpack(dir, {"convert", (dir / "sky.exr").string(), "--colorspace", "acescg"}));
  EXPECT_EQ(doc["source"]["colorspace"], "acescg");
  ASSERT_TRUE(doc["source"].contains("rgb_to_rec709"));
  // White stays white: each row of the matrix sums to 1 (Bradford maps the ACES white to D65).
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(doc["radiance_sh"][c][0].get<double>(), 2.0 * std::sqrt(std::numbers::pi), 1e-12);
}

// --rotate on the coefficients against the map itself turned. Turning an equirect map by
// +90 degrees is moving every column W/4 to the left (rotate.h): a permutation of texels, so
// the exact projection of the moved map is the exact rotation of the coefficients up to the
// projection's rounding, ~1e-13 of the largest coefficient here (project.h sums in double).
TEST(CliLayouts, RotateEqualsTheTurnedMapAndFourQuartersAreWhole) {
  const ScratchDir dir;
  const fs::path map = hdri("courtyard.exr");
  const int w = 1024, h = 512;
  std::vector<float> values;
  ASSERT_TRUE(read_rgb(map, w, h, values));
  auto turned = [&](int quarters) {  // moved quarters * W/4 columns to the left
    std::vector<float> out(values.size());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c)
          out[3 * (y * w + x) + c] = values[3 * (y * w + (x + quarters * w / 4) % w) + c];
    return out;
  };
  for (int q = 1; q <= 3; ++q)
    ASSERT_TRUE(shpack_io_test::write_image(dir / ("turned" + std::to_string(q) + ".exr"), w, h, 3, turned(q)));
  const shpack::ShL2 plain = radiance_of(document(run_shpack(dir, {"convert", map.string()})));
  const shpack::ShL2 rotated = radiance_of(document(run_shpack(dir, {"convert", map.string(), "--rotate", "90"})));
  const double tol = 1e-13 * max_abs(plain);
  // --rotate 90 is the rotated coefficients, and the map turned by a quarter.
  expect_near(rotated, shpack::rotate_about_y(plain, 90), tol, "rotate_about_y");
  expect_near(rotated, radiance_of(document(run_shpack(dir, {"convert", (dir / "turned1.exr").string()}))), tol,
              "turned map");
  // Three quarters in the map and a fourth by --rotate: the whole turn, the map itself.
  expect_near(radiance_of(document(run_shpack(dir, {"convert", (dir / "turned3.exr").string(), "--rotate", "90"}))),
              plain, tol, "four quarters");
  // And --rotate 360 is exactly no rotation (rotation_about_y is exact at multiples of 90).
  EXPECT_EQ(radiance_of(document(run_shpack(dir, {"convert", map.string(), "--rotate", "360"}))), plain);
}

TEST(CliLayouts, ABatchConvertsInParallelAndReportsInInputOrder) {
  const ScratchDir dir;
  const fs::path out_dir = dir / "out";
  ASSERT_TRUE(write_constant_image(dir / "square.exr", 6, 6, {1, 1, 1}));  // ambiguous: fails
  std::vector<std::string> args = {"convert"};
  for (const char* name : {"studio", "night", "forest", "city"}) args.push_back(hdri(std::string(name) + ".exr").string());
  args.insert(args.begin() + 2, (dir / "missing.exr").string());
  args.push_back((dir / "square.exr").string());
  args.insert(args.end(), {"--out-dir", out_dir.string(), "--threads", "4"});
  const CliRun run = run_shpack(dir, args);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "missing.exr").string() + ": no such file\nshpack: " +
                         (dir / "square.exr").string() +
                         ": the layout of a 6x6 image is ambiguous: it fits octahedral, angular and mirrorball; "
                         "name the layout with --layout\n");
  for (const char* name : {"studio", "night", "forest", "city"}) {
    EXPECT_TRUE(fs::is_regular_file(out_dir / (std::string(name) + ".json"))) << name;
    // Each document is the one a lone conversion writes, bit for bit.
    const CliRun alone = run_shpack(dir, {"convert", hdri(std::string(name) + ".exr").string()});
    EXPECT_EQ(shpack_io_test::read_bytes(out_dir / (std::string(name) + ".json")),
              std::vector<char>(alone.out.begin(), alone.out.end()))
        << name;
  }
  EXPECT_FALSE(fs::exists(out_dir / "missing.json"));
  EXPECT_FALSE(fs::exists(out_dir / "square.json"));
}

}  // namespace
