// convert --format csharp|hlsl|unity-yaml and --l1: every form is parsed back and its floats
// compared bit for bit with the JSON document's; the L1 document is checked against the L1
// truncation of E/pi as Unity's Light Probe Proxy Volume shader evaluates it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/io/output_format.h"
#include "shpack/unity_pack.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;
using shpack_io_test::hdri;
using shpack_io_test::run_shpack;
using shpack_io_test::ScratchDir;
using Json = nlohmann::json;

using Floats27 = std::array<std::array<float, kShCount>, kChannelCount>;
using Vectors7 = std::array<std::array<float, 4>, 7>;  // SHAr, SHAg, SHAb, SHBr, SHBg, SHBb, SHC
constexpr std::array<const char*, 7> kVectorKeys = {"unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr",
                                                    "unity_SHBg", "unity_SHBb", "unity_SHC"};

// What the JSON document says, as the floats a reader gets (double -> float is exact here).
struct JsonFloats {
  Floats27 sh{};
  Vectors7 shader{};
};

JsonFloats json_floats(const std::string& text) {
  const Json j = Json::parse(text);
  JsonFloats out;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) out.sh[c][i] = static_cast<float>(j["sphericalHarmonicsL2"][c][i].get<double>());
  for (int v = 0; v < 7; ++v)
    for (int k = 0; k < 4; ++k) out.shader[v][k] = static_cast<float>(j["shader"][kVectorKeys[v]][k].get<double>());
  return out;
}

// A literal read two ways: straight to float (strtof) and through double (strtod, then
// a cast), as a C# or HLSL compiler might. Both must give the same float; NaN otherwise.
float parse_float(const std::string& text) {
  char* end = nullptr;
  const float direct = std::strtof(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nanf("");
  const auto via_double = static_cast<float>(std::strtod(text.c_str(), nullptr));
  return std::bit_cast<std::uint32_t>(direct) == std::bit_cast<std::uint32_t>(via_double) ? direct : std::nanf("");
}

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

// The 27 `sh[c, i] = <literal>f;` assignments of the C# form; ok only if each (c, i) is
// assigned exactly once and every such line reads whole.
bool parse_csharp(const std::string& text, Floats27& out) {
  std::array<std::array<int, kShCount>, kChannelCount> seen{};
  int count = 0;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t at = line.find_first_not_of(' ');
    if (at == std::string::npos || line.compare(at, 3, "sh[") != 0) continue;
    int c = -1, i = -1, end = 0;
    char literal[64] = {};
    if (std::sscanf(line.c_str() + at, "sh[%d, %d] = %63[^f;]f;%n", &c, &i, literal, &end) != 3 ||
        at + end != line.size())
      return false;
    if (c < 0 || c >= kChannelCount || i < 0 || i >= kShCount || seen[c][i]++) return false;
    out[c][i] = parse_float(literal);
    ++count;
  }
  return count == kChannelCount * kShCount;
}

// The seven `static const float4 <prefix>_<name> = float4(a, b, c, d);` of the HLSL form, in
// Unity's order, each once.
bool parse_hlsl(const std::string& text, Vectors7& out) {
  int count = 0;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.starts_with("static const float4 ")) continue;
    char name[128] = {};
    char v[4][64] = {};
    int end = 0;
    if (std::sscanf(line.c_str(), "static const float4 %127s = float4(%63[^f,]f, %63[^f,]f, %63[^f,]f, %63[^f)]f);%n",
                    name, v[0], v[1], v[2], v[3], &end) != 5 ||
        static_cast<std::size_t>(end) != line.size())
      return false;
    const std::string key = "unity_" + std::string(name).substr(std::string(name).rfind('_') + 1);
    if (count >= 7 || key != kVectorKeys[count]) return false;
    for (int k = 0; k < 4; ++k) out[count][k] = parse_float(v[k]);
    ++count;
  }
  return count == 7;
}

// The YAML form, parsed strictly: comment lines, then exactly the lines "sh[ 0]: v" ..
// "sh[26]: v" in order (Unity's field names), each value a whole number.
bool parse_unity_yaml(const std::string& text, Floats27& out) {
  std::istringstream lines(text);
  std::string line;
  int next = 0;
  while (std::getline(lines, line)) {
    if (line.starts_with("#")) {
      if (next != 0) return false;  // comments only at the top
      continue;
    }
    const std::string name = std::string("sh[") + (next < 10 ? " " : "") + std::to_string(next) + "]: ";
    if (next >= kChannelCount * kShCount || !line.starts_with(name)) return false;
    out[next / kShCount][next % kShCount] = parse_float(line.substr(name.size()));
    ++next;
  }
  return next == kChannelCount * kShCount;
}

void expect_same_bits(const Floats27& got, const Floats27& want, const std::string& what) {
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i)
      EXPECT_EQ(bits(got[c][i]), bits(want[c][i])) << what << " c=" << c << " i=" << i << " got " << got[c][i]
                                                   << " want " << want[c][i];
}

// A document whose 27 Unity floats are arbitrary finite floats over the whole exponent range
// (subnormals included, and -0), so that any lossy literal shows. |x| < 2^120 keeps the
// packed sh0 - sh6 and 3 sh6 finite.
ShDocument random_float_document(std::mt19937_64& rng) {
  std::uniform_int_distribution<std::uint32_t> any_bits;
  ShDocument doc;
  doc.source = {{"sky 2k.exr"}, {std::string(64, 'a')}, Layout::Equirect, 1024, 512};
  for (auto& channel : doc.sh.unity_form.c) {
    for (double& v : channel) {
      float f;
      do f = std::bit_cast<float>(any_bits(rng));
      while (!std::isfinite(f) || std::fabs(f) >= 0x1p120f);
      v = f;
    }
  }
  doc.sh.unity_form.c[1][4] = -0.0;
  // The finish stage packs (pipeline.h); the writers only copy the packed floats.
  doc.sh.unity_sh = to_unity_sh(doc.sh.unity_form);
  doc.sh.shader = to_shader_vectors(doc.sh.unity_form);
  return doc;
}

TEST(OutputFormat, EveryFormReadsBackToTheJsonFloatsBitForBit) {
  std::mt19937_64 rng(0x5eed);
  for (int round = 0; round < 200; ++round) {
    const ShDocument doc = random_float_document(rng);
    const JsonFloats want = json_floats(format_document(doc, OutputFormat::Json));
    Floats27 csharp{}, yaml{};
    Vectors7 hlsl{};
    ASSERT_TRUE(parse_csharp(format_document(doc, OutputFormat::CSharp), csharp)) << to_csharp(doc);
    ASSERT_TRUE(parse_hlsl(format_document(doc, OutputFormat::Hlsl), hlsl)) << to_hlsl(doc);
    ASSERT_TRUE(parse_unity_yaml(format_document(doc, OutputFormat::UnityYaml), yaml)) << to_unity_yaml(doc);
    expect_same_bits(csharp, want.sh, "csharp");
    expect_same_bits(yaml, want.sh, "unity-yaml");
    for (int v = 0; v < 7; ++v)
      for (int k = 0; k < 4; ++k)
        EXPECT_EQ(bits(hlsl[v][k]), bits(want.shader[v][k])) << kVectorKeys[v] << "[" << k << "]";
    if (HasFailure()) return;
  }
}

TEST(OutputFormat, NamesComeFromTheInputAndTheOptionsAreStated) {
  std::mt19937_64 rng(7);
  const ShDocument doc = random_float_document(rng);  // input "sky 2k.exr"
  const std::string csharp = to_csharp(doc), hlsl = to_hlsl(doc), yaml = to_unity_yaml(doc);
  EXPECT_NE(csharp.find("public static class ShpackSky2k\n"), std::string::npos) << csharp;
  EXPECT_NE(hlsl.find("static const float4 shpack_sky_2k_SHAr = "), std::string::npos) << hlsl;
  EXPECT_NE(hlsl.find("float3 shpack_sky_2k_ShadeSH9(float3 n)"), std::string::npos) << hlsl;
  EXPECT_NE(hlsl.find("#ifndef SHPACK_SKY_2K_HLSL_INCLUDED\n"), std::string::npos) << hlsl;
  const std::string options = R"(options: {"method":"exact","window":"none","rotate_deg":0.0,"intensity":1.0})";
  EXPECT_NE(csharp.find("// " + options + "\n"), std::string::npos) << csharp;
  EXPECT_NE(hlsl.find("// " + options + "\n"), std::string::npos) << hlsl;
  EXPECT_NE(yaml.find("# " + options + "\n"), std::string::npos) << yaml;
  EXPECT_EQ(yaml.find("L1 only"), std::string::npos);
}

TEST(OutputFormat, CommandLineFormsMatchItsJson) {
  const ScratchDir dir;
  const std::string map = hdri("sunset.exr").string();
  const auto run = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"convert", map, "--window", "sloan"};
    args.insert(args.end(), extra.begin(), extra.end());
    const shpack_io_test::CliRun r = run_shpack(dir, args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    return r.out;
  };
  for (const bool l1 : {false, true}) {
    const std::vector<std::string> l1_flag = l1 ? std::vector<std::string>{"--l1"} : std::vector<std::string>{};
    std::vector<std::string> json_args = {"--format", "json"};
    json_args.insert(json_args.end(), l1_flag.begin(), l1_flag.end());
    const JsonFloats want = json_floats(run(json_args));
    Floats27 csharp{}, yaml{};
    Vectors7 hlsl{};
    std::vector<std::string> a = {"--format", "csharp"}, b = {"--format", "HLSL"}, c = {"--format=unity-yaml"};
    for (auto* args : {&a, &b, &c}) args->insert(args->end(), l1_flag.begin(), l1_flag.end());
    ASSERT_TRUE(parse_csharp(run(a), csharp));
    ASSERT_TRUE(parse_hlsl(run(b), hlsl));
    ASSERT_TRUE(parse_unity_yaml(run(c), yaml));
    expect_same_bits(csharp, want.sh, l1 ? "csharp --l1" : "csharp");
    expect_same_bits(yaml, want.sh, l1 ? "yaml --l1" : "yaml");
    for (int v = 0; v < 7; ++v)
      for (int k = 0; k < 4; ++k) EXPECT_EQ(bits(hlsl[v][k]), bits(want.shader[v][k])) << kVectorKeys[v] << k;
  }
}

TEST(OutputFormat, OutDirNamesFilesWithTheFormatsExtension) {
  const ScratchDir dir;
  const shpack_io_test::CliRun r = run_shpack(
      dir, {"convert", hdri("studio.exr").string(), hdri("night.exr").string(), "--format", "csharp",
                   "--out-dir", (dir / "out").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "studio.cs"));
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "night.cs"));
  EXPECT_FALSE(fs::exists(dir / "out" / "studio.json"));
  EXPECT_EQ(run_shpack(dir, {"convert", hdri("studio.exr").string(), "--format", "png"}).exit_code, 2);
}

// --l1: what Unity's Light Probe Proxy Volume evaluates in quality mode Low,
// SHEvalLinearL0L1_SampleProbeVolume = dot(SHA, (n, 1)) per channel (UnityCG.cginc), must be
// the L1 truncation of E/pi:  sum_{l <= 1} (A_l / pi) sum_m L_lm Y_lm(n)
//   = k0 L_00 + (2/3) k1 (L_1,-1 y + L_1,0 z + L_1,1 x),  k0 = 1/(2 sqrt(pi)), k1 = sqrt(3) k0,
// computed here from the full document's radiance_sh, with the constants written out.
TEST(OutputFormat, L1IsTheL1TruncationOfIrradianceAsTheProxyVolumeShaderSeesIt) {
  const ScratchDir dir;
  for (const char* name : {"courtyard.exr", "sunset.exr", "night.exr"}) {
    const std::string map = hdri(name).string();
    const shpack_io_test::CliRun full = run_shpack(dir, {"convert", map});
    const shpack_io_test::CliRun l1 = run_shpack(dir, {"convert", map, "--l1"});
    ASSERT_EQ(full.exit_code, 0) << full.err;
    ASSERT_EQ(l1.exit_code, 0) << l1.err;
    const Json f = Json::parse(full.out), g = Json::parse(l1.out);
    EXPECT_EQ(g["options"]["l1"], true);
    EXPECT_FALSE(f["options"].contains("l1"));

    const double k0 = 0.5 / std::sqrt(std::numbers::pi), k1 = std::sqrt(3.0) * k0;
    std::mt19937_64 rng(0x5eed);
    std::normal_distribution<double> gauss;
    for (int c = 0; c < 3; ++c) {
      const Json& sh = g["sphericalHarmonicsL2"][c];
      for (int i = 0; i < 4; ++i) EXPECT_EQ(sh[i], f["sphericalHarmonicsL2"][c][i]) << name << " c=" << c;
      for (int i = 4; i < 9; ++i) EXPECT_EQ(sh[i].get<double>(), 0.0) << name << " c=" << c << " i=" << i;
      // Unity's packing of the L1 probe: w = sh0 (sh6 = 0), and no L2 vectors.
      const Json& sha = g["shader"][kVectorKeys[c]];
      EXPECT_EQ(sha, Json::array({sh[3], sh[1], sh[2], sh[0]})) << name;
      EXPECT_EQ(g["shader"][kVectorKeys[3 + c]], Json::array({0.0, 0.0, 0.0, 0.0}));

      const Json& L = f["radiance_sh"][c];
      const std::array<float, 4> a = {sha[0].get<float>(), sha[1].get<float>(), sha[2].get<float>(),
                                      sha[3].get<float>()};
      for (int k = 0; k < 200; ++k) {
        double x = gauss(rng), y = gauss(rng), z = gauss(rng);
        const double len = std::sqrt(x * x + y * y + z * z);
        x /= len, y /= len, z /= len;
        const double want = k0 * L[0].get<double>() + (2.0 / 3.0) * k1 *
                                                           (L[1].get<double>() * y + L[2].get<double>() * z +
                                                            L[3].get<double>() * x);
        // The shader's float dot(SHA, (n, 1)).
        const float fx = static_cast<float>(x), fy = static_cast<float>(y), fz = static_cast<float>(z);
        const float got = a[0] * fx + a[1] * fy + a[2] * fz + a[3];
        // Rounding: each float operand once (<= 2 u per product) and 3 additions: 6 u of the
        // sum of |terms|, u = 2^-24; 8 u leaves room for the double reference.
        const double tol = 8 * 0x1p-24 * (std::fabs(a[0] * x) + std::fabs(a[1] * y) + std::fabs(a[2] * z) + std::fabs(a[3]));
        EXPECT_NEAR(got, want, tol) << name << " c=" << c << " n=" << x << "," << y << "," << z;
      }
    }
  }
}

}  // namespace
}  // namespace shpack::io
