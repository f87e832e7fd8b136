// engine_formats_test.cpp - the outputs for other engines (--format threejs|filament|gltf),
// --frame, and the format named by -o's extension, each against the engine's own reader or
// tool where this machine has it: three.js (npm `three`, run by node) and Debian's cmgen.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/conventions.h"
#include "shpack/engine_frame.h"
#include "shpack/sh_basis.h"

namespace shpack_io_test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using shpack::Dir3;
using shpack::EngineFrame;
using shpack::kChannelCount;
using shpack::kShCount;

constexpr double kFloatEps = 0x1p-24;  // unit roundoff of float32

Json convert_json(const ScratchDir& dir, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"convert", hdri("studio.exr").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const CliRun r = run_shpack(dir, args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return Json::parse(r.out);
}

// E/pi of the document's radiance_sh (Unity's frame) at unit d, and sum of |terms| for the
// tolerances below.
std::array<double, 2> e_over_pi(const Json& doc, int channel, const Dir3& d) {
  const std::array<double, kShCount> y = shpack::eval_basis(d.x, d.y, d.z);
  double sum = 0, size = 0;
  for (int i = 0; i < kShCount; ++i) {
    const double term = doc["radiance_sh"][channel][i].get<double>() * shpack::kCosineLobeOverPi[shpack::kBand[i]] * y[i];
    sum += term;
    size += std::abs(term);
  }
  return {sum, size};
}

const std::array<Dir3, 8> kDirections = {{{1, 0, 0},
                                          {0, 1, 0},
                                          {0, 0, 1},
                                          {-1, 0, 0},
                                          {0, -1, 0},
                                          {0, 0, -1},
                                          {0.48, 0.6, -0.64},
                                          {-0.36, -0.48, 0.8}}};

// The inverse of to_engine_frame: engine axis k is sign[k] * Unity axis from[k].
Dir3 from_engine_frame(EngineFrame frame, const Dir3& d) {
  const shpack::EngineAxes& axes = shpack::engine_frame_spec(frame).axes;
  const std::array<double, 3> e = {d.x, d.y, d.z};
  std::array<double, 3> u{};
  for (int k = 0; k < 3; ++k) u[axes.from[k]] = axes.sign[k] * e[k];
  return {u[0], u[1], u[2]};
}

// Runs a shell command, returning its exit status and stdout.
int run_command(const std::string& command, std::string& out) {
  out.clear();
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return -1;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.append(buffer.data(), n);
  return pclose(pipe);
}

// ---- three.js ---------------------------------------------------------------------------

// The fixture: npm `three` installed once under the build folder.
bool three_installed(std::string& why) {
  const fs::path fixture = fs::path(SHPACK_TEST_FIXTURE_DIR) / "threejs";
  if (fs::exists(fixture / "node_modules" / "three" / "package.json")) return true;
  fs::create_directories(fixture);
  std::string out;
  const std::string command = "cd '" + fixture.string() +
                              "' && npm install --no-audit --no-fund --silent three@0.187.0 2>&1";
  if (run_command(command, out) != 0) {
    why = "npm could not install three (no network?): " + out;
    return false;
  }
  return true;
}

// Loads the document with ObjectLoader.parse, and builds the probe from its "object" as
// LightProbe.fromJSON did before it moved into ObjectLoader (r187 has no fromJSON: sh and
// intensity), and prints getIrradianceAt(n) of both for each direction, "r g b r g b".
constexpr const char* kThreeScript = R"(import { LightProbe, ObjectLoader, SphericalHarmonics3, Vector3 } from 'three';
import { readFileSync } from 'node:fs';
const json = JSON.parse(readFileSync(process.argv[2], 'utf8'));
const loaded = new ObjectLoader().parse(json);
if (!loaded.isLightProbe) throw new Error('not a LightProbe: ' + loaded.type);
const direct = new LightProbe(new SphericalHarmonics3().fromArray(json.object.sh), json.object.intensity);
for (const text of process.argv.slice(3)) {
  const [x, y, z] = text.split(',').map(Number);
  const n = new Vector3(x, y, z).normalize();
  const a = loaded.sh.getIrradianceAt(n, new Vector3()).multiplyScalar(loaded.intensity);
  const b = direct.sh.getIrradianceAt(n, new Vector3()).multiplyScalar(direct.intensity);
  console.log(a.x, a.y, a.z, b.x, b.y, b.z);
}
)";

// three.js's getIrradianceAt on the probe must be pi times shpack's E/pi, at the same
// physical direction: n in three.js's frame is Unity's (n.x, n.y, -n.z).
// Tolerance: the 27 floats carry a relative rounding of at most u = 2^-24 each, and three.js
// writes its six constants with 6 significant digits: 0.886227 (pi k0), 2 * 0.511664
// (2 pi/3 k1), 2 * 0.429043 (pi/4 k2), 0.743125 and 0.247708 (3 pi/4 k3, pi/4 k3), 0.429043
// (pi/4 k4), the worst 0.743125 against 0.7431239 (1.5e-6 relative). So each term is off by
// at most (1.5e-6 + u) of itself: |E_three/pi - E/pi| <= 2e-6 * sum|terms|, plus double-
// rounding noise far below it.
TEST(ThreeJsFormat, LightProbeLoadsInThreeJsAndLightsAsShpack) {
  std::string why;
  if (std::system("node --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "no node on this machine";
  if (!three_installed(why)) GTEST_SKIP() << why;
  const ScratchDir dir;
  const Json doc = convert_json(dir, {});
  const fs::path probe = dir / "probe.json", script = fs::path(SHPACK_TEST_FIXTURE_DIR) / "threejs" / "irradiance.mjs";
  const CliRun r = run_shpack(dir, {"convert", hdri("studio.exr").string(), "--format", "threejs", "-o", probe.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ofstream(script) << kThreeScript;
  std::string command = "node '" + script.string() + "' '" + probe.string() + "'";
  for (const Dir3& n : kDirections)
    command += " " + std::to_string(n.x) + "," + std::to_string(n.y) + "," + std::to_string(n.z);
  std::string out;
  ASSERT_EQ(run_command(command + " 2>&1", out), 0) << out;
  std::istringstream lines(out);
  for (const Dir3& n_three : kDirections) {
    const double norm = std::sqrt(n_three.x * n_three.x + n_three.y * n_three.y + n_three.z * n_three.z);
    const Dir3 n = {n_three.x / norm, n_three.y / norm, n_three.z / norm};
    std::array<double, 6> got{};
    for (double& v : got) ASSERT_TRUE(lines >> v) << out;
    const Dir3 unity = from_engine_frame(EngineFrame::ThreeJs, n);
    for (int c = 0; c < kChannelCount; ++c) {
      const auto [want, size] = e_over_pi(doc, c, unity);
      EXPECT_NEAR(got[c] / std::numbers::pi, want, 2e-6 * size) << "ObjectLoader, channel " << c << " n=" << n.x
                                                                 << "," << n.y << "," << n.z;
      EXPECT_EQ(got[c], got[3 + c]) << "fromJSON and ObjectLoader differ";
    }
  }
}

// ---- Filament ---------------------------------------------------------------------------

// A flat (uncompressed) Radiance RGBE file of `radiance` on an equirect W x H grid in
// Unity's convention (conventions.h), so both tools read the same quantised texels.
void write_rgbe(const fs::path& path, int width, int height, const std::array<std::array<double, kShCount>, 3>& sh) {
  std::ofstream file(path, std::ios::binary);
  file << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const Dir3 d = shpack::equirect_direction((i + 0.5) / width, (j + 0.5) / height);
      const std::array<double, kShCount> y = shpack::eval_basis(d.x, d.y, d.z);
      std::array<double, 3> rgb{};
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < kShCount; ++k) rgb[c] += sh[c][k] * y[k];
      const double peak = std::max({rgb[0], rgb[1], rgb[2]});
      int exponent = 0;
      const double mantissa = std::frexp(peak, &exponent);
      const double scale = mantissa * 256.0 / peak;
      for (const double v : rgb) file.put(static_cast<char>(static_cast<int>(v * scale)));
      file.put(static_cast<char>(exponent + 128));
    }
  }
}

// cmgen's sh.txt: 9 lines "(r, g, b); // ...".
bool parse_sh_txt(const std::string& text, std::array<std::array<double, 3>, kShCount>& out) {
  std::istringstream lines(text);
  std::string line;
  int i = 0;
  while (std::getline(lines, line) && i < kShCount) {
    if (line.rfind("(", 0) != 0) continue;
    if (std::sscanf(line.c_str(), "(%lf, %lf, %lf);", &out[i][0], &out[i][1], &out[i][2]) != 3) return false;
    ++i;
  }
  return i == kShCount;
}

// Against Debian's cmgen on a band-limited map, with windowing off (cmgen's default
// --sh-window=auto damps bands 1 and 2). Both tools read the same RGBE texels, but decode
// them differently: cmgen as (m + 0.5) 2^(e - 136) (Radiance's rule), shpack as m 2^(e - 136).
// The map is made to keep every texel's largest channel in [2, 4) (mean 3, each other
// coefficient +-0.1: |sum_{i>0} L_i Y_i| <= 8 * 0.1 * 1.1 < 0.9), so e = 130 everywhere and
// the difference is the constant 0.5 * 2^-6 = 1/128: E/pi's mean only, pre-scaled L00 + 1/128.
// What remains is cmgen's resampling of the 1024 x 512 map into a 256^2 cube before its
// projection: it places samples up to about one equirect texel (2 pi / W) from where the
// map has them, a turn that moves a band-l coefficient by at most l * angle * sum|band|
// (|m| <= l), so tol_i = 2 (2 pi / W) sum_{band of i} |u| plus the 15-decimal print.
TEST(FilamentFormat, MatchesCmgenShShaderOnABandLimitedMap) {
  if (std::system("cmgen --help > /dev/null 2>&1") != 0) GTEST_SKIP() << "no cmgen on this machine";
  const ScratchDir dir;
  constexpr int kWidth = 1024;
  std::array<std::array<double, kShCount>, 3> sh{};
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < kShCount; ++i) sh[c][i] = i == 0 ? 6.0 * std::sqrt(std::numbers::pi) : ((i + c) % 2 ? 0.1 : -0.1);
  const fs::path map = dir / "band.hdr";
  write_rgbe(map, kWidth, kWidth / 2, sh);
  std::string out;
  ASSERT_EQ(run_command("cd '" + dir.path().string() +
                            "' && cmgen --sh-shader --sh-window=no -q --size=256 --ibl-samples=16 -x cm '" +
                            map.string() + "' > /dev/null 2>&1",
                        out),
            0);
  std::array<std::array<double, 3>, kShCount> cmgen{}, ours{};
  ASSERT_TRUE(parse_sh_txt(text_of(dir / "cm" / "band" / "sh.txt"), cmgen));
  const CliRun r = run_shpack(dir, {"convert", map.string(), "--format", "filament"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(parse_sh_txt(r.out, ours)) << r.out;
  constexpr double kDecoderOffset = 1.0 / 128;
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < kShCount; ++i) {
      double band_size = 0;
      for (int j = 0; j < kShCount; ++j)
        if (shpack::kBand[j] == shpack::kBand[i]) band_size += std::abs(ours[j][c]);
      const double tol = 2.0 * (2.0 * std::numbers::pi / kWidth) * band_size + 1e-14;
      EXPECT_NEAR(cmgen[i][c] - (i == 0 ? kDecoderOffset : 0.0), ours[i][c], tol) << "index " << i << " channel " << c;
    }
  }
}

// ---- glTF -------------------------------------------------------------------------------

// The light of EXT_lights_image_based: its place in the document (root lights, the scene's
// light index), and its irradianceCoefficients E_i (Condon-Shortley signs, glTF frame):
// sum_i E_i s_i Y_i(n) / pi must be shpack's E/pi at Unity's direction of glTF's n, within
// the float rounding of the coefficients (u per term). At glTF's axes that puts Unity's
// +X (right) at glTF -X and Unity's +Z at glTF +Z, where glTF 2.0 puts right and forward.
TEST(GltfFormat, LightFollowsTheExtensionAndGltfsAxes) {
  const ScratchDir dir;
  const Json doc = convert_json(dir, {});
  const CliRun r = run_shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "probe.gltf").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json gltf = Json::parse(text_of(dir / "probe.gltf"));
  EXPECT_EQ(gltf["asset"]["version"], "2.0");
  EXPECT_EQ(gltf["extensionsUsed"], Json::array({"EXT_lights_image_based"}));
  EXPECT_EQ(gltf["scenes"][gltf["scene"].get<int>()]["extensions"]["EXT_lights_image_based"]["light"], 0);
  const Json& light = gltf["extensions"]["EXT_lights_image_based"]["lights"][0];
  EXPECT_EQ(light["rotation"], Json::array({0.0, 0.0, 0.0, 1.0}));
  EXPECT_EQ(light["intensity"], 1.0);
  ASSERT_EQ(light["irradianceCoefficients"].size(), 9u);
  for (const Dir3& n : kDirections) {
    const double norm = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    const Dir3 unit = {n.x / norm, n.y / norm, n.z / norm};
    const std::array<double, kShCount> y = shpack::eval_basis(unit.x, unit.y, unit.z);
    for (int c = 0; c < kChannelCount; ++c) {
      double got = 0;
      for (int i = 0; i < kShCount; ++i)
        got += light["irradianceCoefficients"][i][c].get<double>() * shpack::kCondonShortleySign[i] * y[i];
      const auto [want, size] = e_over_pi(doc, c, from_engine_frame(EngineFrame::Gltf, unit));
      EXPECT_NEAR(got / std::numbers::pi, want, 4 * kFloatEps * size + 1e-15) << "channel " << c;
    }
  }
  EXPECT_EQ(shpack::to_engine_frame(EngineFrame::Gltf, {1, 0, 0}), (Dir3{-1, 0, 0}));
  EXPECT_EQ(shpack::to_engine_frame(EngineFrame::Gltf, {0, 0, 1}), (Dir3{0, 0, 1}));
}

// ---- --frame and the format of -o -------------------------------------------------------

// --frame F rewrites radiance_sh only, exactly as sh_to_engine_frame maps the default's;
// the default document has no radiance_sh_frame key.
TEST(FrameOption, RadianceShIsTheMappedDefault) {
  const ScratchDir dir;
  const Json unity = convert_json(dir, {});
  EXPECT_FALSE(unity.contains("radiance_sh_frame"));
  for (std::size_t k = 1; k < shpack::kEngineFrames.size(); ++k) {
    const auto frame = static_cast<EngineFrame>(k);
    const Json other = convert_json(dir, {"--frame", shpack::kEngineFrames[k].name});
    EXPECT_EQ(other["radiance_sh_frame"], shpack::kEngineFrames[k].description);
    EXPECT_EQ(other["sphericalHarmonicsL2"], unity["sphericalHarmonicsL2"]);
    for (int c = 0; c < kChannelCount; ++c) {
      std::array<double, kShCount> in{};
      for (int i = 0; i < kShCount; ++i) in[i] = unity["radiance_sh"][c][i].get<double>();
      const std::array<double, kShCount> want = shpack::sh_to_engine_frame(frame, in);
      for (int i = 0; i < kShCount; ++i) EXPECT_EQ(other["radiance_sh"][c][i].get<double>(), want[i]) << k << " " << i;
    }
  }
}

TEST(OutputFormat, FollowsTheOutputsExtensionAndRefusesAContradiction) {
  const ScratchDir dir;
  const std::string map = hdri("studio.exr").string();
  ASSERT_EQ(run_shpack(dir, {"convert", map, "-o", (dir / "a.cs").string()}).exit_code, 0);
  EXPECT_NE(text_of(dir / "a.cs").find("public static class ShpackStudio"), std::string::npos);
  ASSERT_EQ(run_shpack(dir, {"convert", map, "-o", (dir / "a.yaml").string()}).exit_code, 0);
  EXPECT_NE(text_of(dir / "a.yaml").find("sh[26]: "), std::string::npos);
  ASSERT_EQ(run_shpack(dir, {"convert", map, "-o", (dir / "a.hlsl").string()}).exit_code, 0);
  EXPECT_NE(text_of(dir / "a.hlsl").find("shpack_studio_ShadeSH9"), std::string::npos);
  ASSERT_EQ(run_shpack(dir, {"convert", map, "--format", "threejs", "-o", (dir / "t.json").string()}).exit_code, 0);
  EXPECT_EQ(Json::parse(text_of(dir / "t.json"))["object"]["type"], "LightProbe");
  ASSERT_EQ(run_shpack(dir, {"convert", map, "--format", "filament", "-o", (dir / "sh.txt").string()}).exit_code, 0);
  const CliRun bad = run_shpack(dir, {"convert", map, "--format", "csharp", "-o", (dir / "b.json").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--format csharp"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("--format json"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "b.json"));
  EXPECT_EQ(run_shpack(dir, {"convert", map, "--format", "gltf", "-o", (dir / "b.yaml").string()}).exit_code, 2);
  EXPECT_EQ(run_shpack(dir, {"convert", map, "--format", "csharp", "--frame", "threejs"}).exit_code, 2);
}

}  // namespace
}  // namespace shpack_io_test
