// cli_hard_cases_test.cpp - the hard cases through files and the shpack command: NaN,
// +-Inf, negative and denormal texels in EXR (float and half), PFM, every --nonfinite and
// --negative policy and its diagnostics; denormal, 1e30, 1e-30, FLT_MAX and all-black scenes
// (no null, i.e. no NaN or Inf, anywhere in the JSON); sizes that need --layout equirect;
// the solid angles of every layout the command reads; --window sloan on a real map.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "hard_cases/hard_case_support.h"
#include "shpack/convolution.h"
#include "shpack/project.h"
#include "shpack/unity_pack.h"
#include "support/test_util.h"

namespace shpack_hard {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using shpack::ShL2;
using shpack_test::kU;

std::string test_name() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return std::string(info->test_suite_name()) + "." + info->name();
}

ChildRun shpack(const ScratchDir& dir, const std::vector<std::string>& args) {
  return run_child(shpack_cli(), args, dir.path());
}

// `shpack convert FILE ARGS... -o DIR/out.json`; the parsed document, or null on failure
// (with the run in `run`).
Json convert(const ScratchDir& dir, const fs::path& file, const std::vector<std::string>& args, ChildRun& run) {
  std::vector<std::string> all = {"convert", file.string(), "-o", (dir / "out.json").string()};
  all.insert(all.end(), args.begin(), args.end());
  run = shpack(dir, all);
  if (run.exit_code != 0) return nullptr;
  Json doc = Json::parse(read_text(dir / "out.json"));
  fs::remove(dir / "out.json");
  return doc;
}

ShL2 radiance_of(const Json& doc) {
  ShL2 sh;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) sh.c[c][i] = doc.at("radiance_sh").at(c).at(i).get<double>();
  return sh;
}

// Every number of the document is finite: nlohmann writes NaN and Inf as null.
void expect_no_null(const Json& j, const std::string& pointer, const std::string& what) {
  if (j.is_null()) ADD_FAILURE() << what << ": null (a NaN or Inf) at " << pointer;
  if (j.is_object())
    for (const auto& [key, value] : j.items()) expect_no_null(value, pointer + "/" + key, what);
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i) expect_no_null(j[i], pointer + "/" + std::to_string(i), what);
}

ShL2 project_in_process(const std::vector<float>& rgb, std::uint32_t w, std::uint32_t h,
                        shpack::NonFinite nonfinite = shpack::NonFinite::Error,
                        shpack::Negative negative = shpack::Negative::Keep) {
  shpack::ProjectOptions options;
  options.nonfinite = nonfinite;
  options.negative = negative;
  ShL2 sh;
  const shpack::Status st = shpack::project_equirect(shpack::make_view(rgb.data(), w, h, 3), options, sh);
  EXPECT_TRUE(st.ok()) << shpack_test::describe(st);
  return sh;
}

// ---------------------------------------------------------------------------------------
// Values

// 16 x 8 of 1.5 with: NaN (15, 0) first in row-major order, +Inf (0, 1), -Inf (8, 7);
// negatives -2 (1, 0) and -1e-40 (14, 1); +1e-40 (8, 1) and -0 (0, 7), which do not count.
constexpr std::uint32_t kW = 16, kH = 8;
std::vector<float> planted() {
  std::vector<float> rgb(std::size_t{3} * kW * kH, 1.5f);
  auto at = [&](std::uint32_t x, std::uint32_t y, int c) -> float& { return rgb[(std::size_t{y} * kW + x) * 3 + c]; };
  at(15, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  at(0, 1, 1) = std::numeric_limits<float>::infinity();
  at(8, 7, 2) = -std::numeric_limits<float>::infinity();
  at(1, 0, 2) = -2.0f;
  at(14, 1, 1) = -1e-40f;
  at(8, 1, 0) = 1e-40f;
  at(0, 7, 0) = -0.0f;
  return rgb;
}

std::vector<float> cleaned(std::vector<float> rgb, bool clamp) {
  for (float& v : rgb)
    if (!std::isfinite(v) || (clamp && v < 0)) v = 0.0f;
  return rgb;
}

TEST(CliValues, NonFiniteNegativeAndDenormalTexelsUnderEveryPolicy) {
  const ScratchDir dir(test_name());
  const std::vector<float> rgb = planted();
  ASSERT_EQ(write_exr(dir / "planted.exr", kW, kH, 3, rgb, FileType::Float), "");
  write_pfm(dir / "planted.pfm", kW, kH, rgb);
  for (const char* name : {"planted.exr", "planted.pfm"}) {
    SCOPED_TRACE(name);
    const fs::path file = dir / name;
    // --nonfinite=error (the default): one line naming the file, how many and the first.
    ChildRun run;
    EXPECT_TRUE(convert(dir, file, {}, run).is_null());
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "shpack: " + file.string() +
                           ": 3 NaN/Inf texels (first at x=15, y=0); use --nonfinite=zero to replace them\n");
    EXPECT_FALSE(fs::exists(dir / "out.json"));
    // --nonfinite=zero, --negative=keep|clamp: counted (negatives under both policies) and
    // exactly the in-process projection of the cleaned image.
    for (bool clamp : {false, true}) {
      const Json doc = convert(dir, file, {"--nonfinite=zero", clamp ? "--negative=clamp" : "--negative=keep"}, run);
      ASSERT_EQ(run.exit_code, 0) << run.err;
      const Json& diag = doc.at("diagnostics");
      EXPECT_EQ(diag.at("nonfinite_texels").get<std::uint64_t>(), 3u);
      EXPECT_EQ(diag.at("negative_texels").get<std::uint64_t>(), 2u) << "clamp=" << clamp;
      EXPECT_EQ(radiance_of(doc), project_in_process(cleaned(rgb, clamp), kW, kH)) << "clamp=" << clamp;
      expect_no_null(doc, "", name);
    }
  }
  // PFM stores rows bottom to top: a NaN in its first stored row is image row H - 1.
  std::vector<float> bottom(std::size_t{3} * kW * kH, 1.0f);
  bottom[(std::size_t{kH - 1} * kW + 3) * 3 + 1] = std::numeric_limits<float>::quiet_NaN();
  write_pfm(dir / "bottom.pfm", kW, kH, bottom);
  ChildRun run;
  EXPECT_TRUE(convert(dir, dir / "bottom.pfm", {}, run).is_null());
  EXPECT_NE(run.err.find("1 NaN/Inf texels (first at x=3, y=7)"), std::string::npos) << run.err;
}

TEST(CliValues, InfFromHalfOverflowIsCounted) {
  // A half-float EXR written from float values (OpenEXR's conversion): 65504 is the half
  // maximum and stays finite; 1e5 overflows to +Inf and -1e5 to -Inf; 1e-40 underflows to 0.
  const ScratchDir dir(test_name());
  std::vector<float> rgb(std::size_t{3} * kW * kH, 0.25f);
  rgb[(std::size_t{2} * kW + 5) * 3 + 0] = 65504.0f;
  rgb[(std::size_t{3} * kW + 6) * 3 + 1] = 1e5f;
  rgb[(std::size_t{4} * kW + 7) * 3 + 2] = -1e5f;
  rgb[(std::size_t{5} * kW + 8) * 3 + 0] = 1e-40f;
  ASSERT_EQ(write_exr(dir / "half.exr", kW, kH, 3, rgb, FileType::Half), "");
  ChildRun run;
  EXPECT_TRUE(convert(dir, dir / "half.exr", {}, run).is_null());
  EXPECT_NE(run.err.find("2 NaN/Inf texels (first at x=6, y=3)"), std::string::npos) << run.err;
  const Json doc = convert(dir, dir / "half.exr", {"--nonfinite=zero"}, run);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(doc.at("diagnostics").at("nonfinite_texels").get<int>(), 2);
  EXPECT_EQ(doc.at("diagnostics").at("negative_texels").get<int>(), 0) << "-Inf is non-finite, not negative";
  std::vector<float> want = rgb;  // the half values: 0.25 and 65504 exact, Inf -> 0, 1e-40 -> 0
  want[(std::size_t{3} * kW + 6) * 3 + 1] = 0;
  want[(std::size_t{4} * kW + 7) * 3 + 2] = 0;
  want[(std::size_t{5} * kW + 8) * 3 + 0] = 0;
  EXPECT_EQ(radiance_of(doc), project_in_process(want, kW, kH));
}

// A W x H float EXR of one value; the document of its conversion.
Json convert_uniform(const ScratchDir& dir, float value, const std::vector<std::string>& args, ChildRun& run) {
  const std::uint32_t w = 32, h = 16;
  EXPECT_EQ(write_exr(dir / "uniform.exr", w, h, 3, std::vector<float>(std::size_t{3} * w * h, value), FileType::Float), "");
  return convert(dir, dir / "uniform.exr", args, run);
}

TEST(CliValues, ExtremeUniformScenes) {
  // Uniform v: radiance L00 = 2 sqrt(pi) v to equirect_sum_tol (checks.h), which for
  // W = 32 and L00 = k0 4 pi v is ((ceil(32/8) + 26) 4 + 1 + 2) u L00 = 123 u L00 (1.4e-14
  // relative, whatever v: nothing overflows or underflows in double), Unity L00 = v rounded to float
  // once (the double is far inside half an ulp of float(v) for these v), and the minimum
  // of E/pi is v. Denormal 1e-40 stays a non-zero denormal float; FLT_MAX stays finite.
  const ScratchDir dir(test_name());
  for (float v : {1e-40f, 1e-30f, 1e30f, FLT_MAX}) {
    SCOPED_TRACE(v);
    ChildRun run;
    const Json doc = convert_uniform(dir, v, {}, run);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    expect_no_null(doc, "", "uniform");
    const double l00 = 2 * std::sqrt(std::numbers::pi) * static_cast<double>(v);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(doc.at("radiance_sh").at(c).at(0).get<double>(), l00, 123 * kU * l00);
      const double unity0 = doc.at("sphericalHarmonicsL2").at(c).at(0).get<double>();
      EXPECT_EQ(static_cast<float>(unity0), v);
      EXPECT_EQ(static_cast<float>(doc.at("shader").at("unity_SHAr").at(3).get<double>()), v);
      EXPECT_NEAR(doc.at("diagnostics").at("min_e_over_pi").at(c).get<double>(), static_cast<double>(v), 1e-12 * v);
    }
  }
}

TEST(CliValues, AllBlackSceneHasNoNaNAnywhere) {
  const ScratchDir dir(test_name());
  for (const char* window : {"none", "sloan", "hanning:2", "unity"}) {
    SCOPED_TRACE(window);
    ChildRun run;
    const Json doc = convert_uniform(dir, 0.0f, {std::string("--window=") + window}, run);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    expect_no_null(doc, "", window);
    for (int c = 0; c < 3; ++c) {
      for (int i = 0; i < 9; ++i) {
        EXPECT_EQ(doc.at("radiance_sh").at(c).at(i).get<double>(), 0.0);
        EXPECT_EQ(doc.at("sphericalHarmonicsL2").at(c).at(i).get<double>(), 0.0);
      }
      EXPECT_EQ(doc.at("diagnostics").at("min_e_over_pi").at(c).get<double>(), 0.0);
      EXPECT_FALSE(doc.at("diagnostics").at("window_impossible").at(c).get<bool>());
    }
  }
}

// Regression for a bug this test found: lib/io/src/convert.cpp checked only the
// 27 floats of to_unity_sh(unity_form); the shader vectors (SHA.w = s0 - s6, SHB.z = 3 s6)
// could overflow to Inf while those fit, and the JSON writer wrote null into "shader" with
// exit 0. convert now finishes through the core's finish_projection (pipeline.h), which
// checks both.
TEST(CliValues, ShaderVectorsThatOverflowFloatAreRefused) {
  // The 27 floats can fit while a shader vector does not: SHA.w = s0 - s6 and SHB.z = 3 s6
  // are formed in double and rounded once (unity_pack.h). Light only near the plane z = 0
  // (columns around lon = 0 and pi, 1/16 of the sphere, M = 3e38) has s0 = M/16 and
  // s6 = (k3^2/4) int (3z^2 - 1) L ~ -(5/256) M, so s0 - s6 ~ 1.31 s0; --intensity 16.3 puts
  // s0 at 3.06e38 < FLT_MAX and s0 - s6 at 4.0e38 > FLT_MAX. convert.h promises Unsupported
  // when "the result does not fit in float32": the command must refuse (as it does when one
  // of the 27 floats overflows), not write null (nlohmann's Inf) into "shader".
  const ScratchDir dir(test_name());
  const std::uint32_t w = 64, h = 32;
  std::vector<float> rgb(std::size_t{3} * w * h, 0.0f);
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x : {0u, 31u, 32u, 63u})
      for (int c = 0; c < 3; ++c) rgb[(std::size_t{y} * w + x) * 3 + c] = 3e38f;
  ASSERT_EQ(write_exr(dir / "band.exr", w, h, 3, rgb, FileType::Float), "");
  ChildRun run;
  const Json doc = convert(dir, dir / "band.exr", {"--intensity", "16.3"}, run);
  if (run.exit_code == 0) expect_no_null(doc, "", "band.exr --intensity 16.3");
  EXPECT_EQ(run.exit_code, 1) << "wrote a document whose shader vectors overflow float";
  EXPECT_NE(run.err.find("too bright"), std::string::npos) << run.err;
}

// ---------------------------------------------------------------------------------------
// Sizes and layouts

TEST(CliSizes, ShapesThatAreNot2To1NeedLayoutEquirect) {
  // 1x1 (a uniform environment) and 2:1 are detected as equirect; 3x1, 1x2, 5x3 fit no
  // layout and 7x7 several (the sphere maps), and the one-line error says to name it with
  // --layout; with --layout equirect each is the in-process projection.
  const ScratchDir dir(test_name());
  struct Size {
    std::uint32_t w, h;
    bool detected;
  };
  for (const Size s : {Size{1, 1, true}, Size{2, 1, true}, Size{4, 2, true}, Size{3, 1, false}, Size{1, 2, false},
                       Size{5, 3, false}, Size{7, 7, false}}) {
    SCOPED_TRACE(std::to_string(s.w) + "x" + std::to_string(s.h));
    std::vector<float> rgb(std::size_t{3} * s.w * s.h);
    for (std::size_t k = 0; k < rgb.size(); ++k) rgb[k] = 0.5f + 0.25f * static_cast<float>(k % 7);
    ASSERT_EQ(write_exr(dir / "small.exr", s.w, s.h, 3, rgb, FileType::Float), "");
    ChildRun run;
    const Json detected = convert(dir, dir / "small.exr", {}, run);
    if (s.detected) {
      ASSERT_EQ(run.exit_code, 0) << run.err;
      EXPECT_EQ(radiance_of(detected), project_in_process(rgb, s.w, s.h));
    } else {
      EXPECT_EQ(run.exit_code, 1);
      EXPECT_NE(run.err.find(s.w == s.h ? "ambiguous" : "cannot be detected"), std::string::npos) << run.err;
      EXPECT_NE(run.err.find("--layout"), std::string::npos) << run.err;
      EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
    }
    const Json doc = convert(dir, dir / "small.exr", {"--layout", "equirect"}, run);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(radiance_of(doc), project_in_process(rgb, s.w, s.h));
  }
}

TEST(CliSizes, LayoutsThroughTheCommandSumTo4Pi) {
  // A unit image in every layout the command reads: radiance L00 / k0 = 4 pi to 1e-12
  // (the hard cases' target; derived: ~16u for equirect and cubes, quadrature within 5e-15 for the sphere
  // maps, geometry_test.cpp). Add each new --layout here with a size it accepts.
  struct Case {
    const char* layout;
    std::uint32_t w, h;
  };
  const ScratchDir dir(test_name());
  // Cube layouts with N = 4 (the crosses' unused cells hold 1 too and must be ignored), the
  // sphere maps at 8 x 8 (angular and mirror ball ignore the corners outside the disc).
  for (const Case k : {Case{"equirect", 64, 32}, Case{"equirect", 7, 3}, Case{"equirect", 1, 1},
                       Case{"hcross", 16, 12}, Case{"vcross", 12, 16}, Case{"hstrip", 24, 4}, Case{"vstrip", 4, 24},
                       Case{"hcross", 1, 1}, Case{"octahedral", 8, 8}, Case{"angular", 8, 8},
                       Case{"mirrorball", 8, 8}, Case{"octahedral", 1, 1}}) {
    SCOPED_TRACE(std::string(k.layout) + " " + std::to_string(k.w) + "x" + std::to_string(k.h));
    ASSERT_EQ(write_exr(dir / "ones.exr", k.w, k.h, 3, std::vector<float>(std::size_t{3} * k.w * k.h, 1.0f),
                        FileType::Float),
              "");
    ChildRun run;
    const Json doc = convert(dir, dir / "ones.exr", {"--layout", k.layout}, run);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const double sum = doc.at("radiance_sh").at(0).at(0).get<double>() / shpack::kY0;
    EXPECT_NEAR(sum, 4 * std::numbers::pi, 1e-12 * 4 * std::numbers::pi);
    EXPECT_EQ(doc.at("source").at("layout").get<std::string>(), k.layout);
  }
}

// ---------------------------------------------------------------------------------------
// Ringing

TEST(CliRinging, SloanRemovesTheRingingOfARealMap) {
  // data/hdri/sunrise.exr: a low sun. Without a window the L2 reconstruction of E/pi goes
  // negative (the exact minimum, diagnostics.min_e_over_pi); with --window sloan every
  // channel's minimum is >= 0, the bands it needed are damped (factors < 1), L00 is kept
  // bit for bit, and the window is named in the options.
  const ScratchDir dir(test_name());
  const fs::path map = shpack_test::hdri_path("sunrise");
  ChildRun run;
  const Json plain = convert(dir, map, {}, run);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json sloan = convert(dir, map, {"--window", "sloan"}, run);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(sloan.at("options").at("window").get<std::string>(), "sloan");
  double lowest = INFINITY;
  for (int c = 0; c < 3; ++c) {
    const double before = plain.at("diagnostics").at("min_e_over_pi").at(c).get<double>();
    const double after = sloan.at("diagnostics").at("min_e_over_pi").at(c).get<double>();
    lowest = std::min(lowest, before);
    EXPECT_GE(after, 0.0) << "c=" << c;
    const Json& f = sloan.at("diagnostics").at("window_factors").at(c);
    EXPECT_EQ(f.at(0).get<double>(), 1.0);
    if (before < 0) {
      EXPECT_LT(f.at(1).get<double>(), 1.0) << "c=" << c;
      EXPECT_LT(f.at(2).get<double>(), 1.0) << "c=" << c;
    } else {
      EXPECT_EQ(f, plain.at("diagnostics").at("window_factors").at(c)) << "a channel that does not ring is kept";
    }
    EXPECT_FALSE(sloan.at("diagnostics").at("window_impossible").at(c).get<bool>());
    EXPECT_EQ(sloan.at("radiance_sh").at(c).at(0), plain.at("radiance_sh").at(c).at(0)) << "L00 kept";
    EXPECT_EQ(sloan.at("sphericalHarmonicsL2").at(c).at(0), plain.at("sphericalHarmonicsL2").at(c).at(0));
  }
  EXPECT_LT(lowest, 0.0) << "sunrise.exr rings without a window";
  // --window unity applies Unity's constant factors to every channel.
  const Json unity = convert(dir, map, {"--window", "unity"}, run);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(unity.at("diagnostics").at("window_factors").at(c), Json::array({1.0, 0.922066, 0.731864}));
}

}  // namespace
}  // namespace shpack_hard
