// Tests of `shpack bake` as a user runs it: exit codes, nothing written on failure, the two
// output formats.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "bake_support.h"
#include "scene/scene_files.h"

namespace {

namespace fs = std::filesystem;

using shpack_test::run_cli;

constexpr const char* kGood = R"({"probes": [[0, 1, 0], [1, 1, 0], [2, 1, 0]],
  "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 3}],
  "geometry": [{"type": "plane", "position": [0, 0, 0], "right": [1, 0, 0], "up": [0, 0, 1], "size": [10, 10]}],
  "effects": ["direct", "shadows"]})";

TEST(BakeCli, WritesProbesAndEffectCosts) {
  const fs::path scene = shpack_test::write_scene("cli_good.json", kGood);
  const fs::path out = shpack_test::scene_scratch() / "cli_good_out.json";
  std::string err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " -o " + out.string() + " --quiet", err), 0) << err;
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(out));
  ASSERT_EQ(doc.at("probes").size(), 3u);
  EXPECT_EQ(doc.at("probes")[1].at("position"), nlohmann::json::parse("[1.0, 1.0, 0.0]"));
  for (const char* key : {"radiance_sh", "sphericalHarmonicsL2", "shader", "diagnostics"})
    EXPECT_TRUE(doc.at("probes")[0].contains(key)) << key;
  EXPECT_TRUE(doc.at("effects").contains("direct"));
  EXPECT_TRUE(doc.at("effects").contains("shadows"));
  EXPECT_FALSE(doc.at("effects").contains("bounce")) << "only the effects the scene asks for";
  EXPECT_EQ(doc.at("effects").at("direct").at("rays"), 0);
  // A directional light from straight above and a plane below the probes: the planner sees
  // that no ray towards the light can meet the plane, so shadows trace nothing.
  EXPECT_EQ(doc.at("effects").at("shadows").at("rays"), 0);
}

TEST(BakeCli, WritesLightmapImagesAndSidecar) {
  // A lightmap-only scene: the images and the sidecar land beside the output, the preview reads
  // them, and the sidecar says how to read them.
  const fs::path scene = shpack_test::write_scene("cli_lightmap.json", R"({
    "environment": {"type": "gradient", "zenith": 0.6, "horizon": 0.6, "ground": 0.6},
    "geometry": [{"type": "plane", "name": "floor/../x", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0],
                  "size": [2, 2], "lightmap": {"resolution": [4, 2], "l2": true}}],
    "effects": ["environment"]})");
  const fs::path dir = shpack_test::scene_scratch() / "cli_lightmap_out";
  fs::create_directories(dir);
  std::string err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " -o " + (dir / "out.json").string() + " --quiet", err), 0) << err;
  // The name is a file stem: '/' and '.' are replaced, so nothing is written outside `dir`.
  for (const char* group : {"SHAr", "SHAg", "SHAb", "SHBr", "SHBg", "SHBb", "SHC", "texels"})
    EXPECT_TRUE(fs::is_regular_file(dir / (std::string("floor____x.") + group + ".exr"))) << group;
  const nlohmann::json sidecar = nlohmann::json::parse(std::ifstream(dir / "floor____x.lightmap.json"));
  EXPECT_EQ(sidecar.at("kind"), "shpack-sh-lightmap");
  EXPECT_EQ(sidecar.at("bands"), "L2");
  EXPECT_EQ(sidecar.at("texels").at("used"), 8);
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(dir / "out.json"));
  EXPECT_EQ(doc.at("lightmaps").at(0).at("sidecar"), "floor____x.lightmap.json");
  EXPECT_EQ(doc.at("probes").size(), 0u);
  ASSERT_EQ(run_cli("preview " + (dir / "floor____x.lightmap.json").string() + " -o " + (dir / "p.png").string(), err),
            0)
      << err;
  EXPECT_TRUE(fs::is_regular_file(dir / "p.png"));
}

TEST(BakeCli, LightmapOnAMeshWithoutUvsIsOneLine) {
  shpack_test::write_scene("cli_no_uv.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n");
  const fs::path scene = shpack_test::write_scene("cli_no_uv.json", R"({
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 3}],
    "geometry": [{"type": "mesh", "path": "cli_no_uv.obj", "lightmap": {"resolution": [4, 4]}}],
    "effects": ["direct"]})");
  std::string err;
  EXPECT_EQ(run_cli("bake " + scene.string() + " -o " + (shpack_test::scene_scratch() / "no_uv.json").string(), err),
            1);
  EXPECT_NE(err.find("cli_no_uv.obj"), std::string::npos) << err;
  EXPECT_NE(err.find("lightmap"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
}

TEST(BakeCli, UnityProbesFormatIsFlatArraysInProbeOrder) {
  const fs::path scene = shpack_test::write_scene("cli_unity.json", kGood);
  const fs::path out = shpack_test::scene_scratch() / "cli_unity_out.json";
  const fs::path full = shpack_test::scene_scratch() / "cli_unity_full.json";
  std::string err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " --format unity-probes -o " + out.string(), err), 0) << err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " -o " + full.string(), err), 0) << err;
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(out));
  const nlohmann::json ref = nlohmann::json::parse(std::ifstream(full));
  EXPECT_EQ(doc.at("format"), "unity-probes");
  ASSERT_EQ(doc.at("count"), 3);
  ASSERT_EQ(doc.at("positions").size(), 9u);
  ASSERT_EQ(doc.at("sphericalHarmonicsL2").size(), 81u);
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 9; ++i)
        EXPECT_EQ(doc.at("sphericalHarmonicsL2")[27 * k + 9 * c + i],
                  ref.at("probes")[k].at("sphericalHarmonicsL2")[c][i])
            << "k=" << k << " c=" << c << " i=" << i;
}

TEST(BakeCli, ABadSceneExitsNonZeroNamesThePathAndWritesNothing) {
  const fs::path scene = shpack_test::write_scene("cli_bad.json", R"({"probes": [[0, 0, 0]], "effects": ["direct"],
    "lights": [{"type": "ambient", "radiance": 1}, {"type": "hemisphere", "sky": 1, "ground": 0},
               {"type": "sphere", "position": [0, 3, 0], "radius": -1, "intensity": 1}]})");
  const fs::path out = shpack_test::scene_scratch() / "cli_bad_out.json";
  fs::remove(out);
  std::string err;
  EXPECT_EQ(run_cli("bake " + scene.string() + " -o " + out.string(), err), 1);
  EXPECT_EQ(err, "shpack: " + scene.string() + ": lights[2].radius: must be > 0\n");
  EXPECT_FALSE(fs::exists(out));
  // An existing output survives a failed bake untouched.
  std::ofstream(out) << "keep";
  EXPECT_EQ(run_cli("bake " + scene.string() + " -o " + out.string(), err), 1);
  std::ifstream in(out);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), "keep");
}

TEST(BakeCli, HostileScenesFailInOneLineAndWriteNothing) {
  // 50,000 nested arrays overflowed the stack (exit 139); /dev/zero aborted with an uncaught
  // bad_alloc (two lines, exit 134).
  const std::string deep = std::string(50000, '[') + std::string(50000, ']');
  const fs::path scene = shpack_test::write_scene("cli_deep.json", R"({"probes": [[0, 0, 0]], "effects": [)" + deep +
                                                                       ", " + deep + "]}");
  const fs::path out = shpack_test::scene_scratch() / "cli_hostile_out.json";
  fs::remove(out);
  std::string err;
  EXPECT_EQ(run_cli("bake " + scene.string() + " -o " + out.string(), err), 1);
  EXPECT_EQ(err, "shpack: " + scene.string() + ": nested deeper than 64 levels\n");
  EXPECT_EQ(run_cli("bake /dev/zero -o " + out.string(), err), 1);
  EXPECT_EQ(err, "shpack: /dev/zero: is a device, not a regular file\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(BakeCli, ThreadsBeyondTheCoresAreCapped) {
  // 2^32 - 1 threads ran out of memory; 100000 took 7 s and 550 MB. The output does not
  // depend on the thread count.
  const fs::path scene = shpack_test::write_scene("cli_threads.json", kGood);
  const fs::path one = shpack_test::scene_scratch() / "cli_threads_1.json";
  const fs::path many = shpack_test::scene_scratch() / "cli_threads_max.json";
  std::string err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " --format unity-probes --threads 1 -o " + one.string(), err), 0) << err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " --format unity-probes --threads 4294967295 -o " + many.string(), err),
            0)
      << err;
  EXPECT_EQ(err, "");
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(one)), nlohmann::json::parse(std::ifstream(many)));
  EXPECT_EQ(run_cli("bake " + scene.string() + " --threads -1", err), 2) << "not an unsigned integer";
}

}  // namespace

namespace {

// A sun 4 degrees wide half hidden by a box: the shadows effect samples.
constexpr const char* kPenumbra = R"({"probes": [[0, 0, 0], [0.01, 0, 0]],
  "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1, "angular_diameter_deg": 4}],
  "geometry": [{"type": "box", "min": [-100, 1, -100], "max": [0, 2, 100]}],
  "effects": ["direct", "shadows"], "settings": )";

TEST(BakeCli, EveryProbeSaysHowWrongItMayBeAndHowManySamplesItTook) {
  const fs::path scene = shpack_test::write_scene("cli_error.json", std::string(kPenumbra) + R"({"target_error_pct": 0.5}})");
  const fs::path out = shpack_test::scene_scratch() / "cli_error_out.json";
  std::string err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " -o " + out.string(), err), 0) << err;
  EXPECT_EQ(err, "") << "the target is met: nothing to warn about";
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(out));
  for (const auto& probe : doc.at("probes")) {
    const auto& d = probe.at("diagnostics");
    EXPECT_LE(d.at("error_estimate_pct").get<double>(), 0.5);
    EXPECT_GE(d.at("samples").at("shadows").get<int>(), 256);
    EXPECT_TRUE(d.at("capped").empty());
  }
  EXPECT_EQ(doc.at("sampling").at("target_error_pct"), 0.5);
  EXPECT_LE(doc.at("effects").at("shadows").at("error_estimate_pct_max").get<double>(), 0.5);
  EXPECT_EQ(doc.at("effects").at("shadows").at("capped_probes"), 0);
}

TEST(BakeCli, ProbesThatReachTheCapAreCountedInOneWarning) {
  const fs::path scene =
      shpack_test::write_scene("cli_capped.json", std::string(kPenumbra) + R"({"target_error_pct": 1e-6, "max_samples": 512}})");
  const fs::path out = shpack_test::scene_scratch() / "cli_capped_out.json";
  std::string err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " -o " + out.string(), err), 0) << err;
  EXPECT_EQ(err.rfind("shpack: " + scene.string() + ": 2 of 2 probes reached settings.max_samples (512) before "
                      "settings.target_error_pct (1e-06 %) in shadows; the largest error estimate left is ", 0), 0u)
      << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(out));
  EXPECT_EQ(doc.at("probes")[0].at("diagnostics").at("capped"), nlohmann::json::parse(R"(["shadows"])"));
  EXPECT_EQ(doc.at("effects").at("shadows").at("capped_probes"), 2);
}

}  // namespace

namespace {

TEST(BakeCli, BenchOfASceneMeasuresEachEffectAgainstAReference) {
  const fs::path scene = shpack_test::write_scene("cli_bench.json", std::string(kPenumbra) + "{}}");
  const fs::path out = shpack_test::scene_scratch() / "cli_bench.out";
  std::string err;
  ASSERT_EQ(run_cli("bench " + scene.string() + " --quick --scene-seeds 2 --json > " + out.string(), err), 0) << err;
  const nlohmann::json records = nlohmann::json::parse(std::ifstream(out));
  // shadows only (the one Monte Carlo effect here): 3 counts for each of the two estimators,
  // and the scene's settings.
  ASSERT_EQ(records.size(), 7u) << records.dump();
  for (const auto& r : records) {
    EXPECT_EQ(r.at("effect"), "shadows");
    EXPECT_EQ(r.at("seeds"), 2);
    EXPECT_GE(r.at("err_max_pct").get<double>(), 0.0);
    EXPECT_LE(r.at("err_max_pct").get<double>(), r.at("err_worst_pct").get<double>());
  }
  EXPECT_EQ(records[0].at("estimator"), "next-events");
  EXPECT_EQ(records[3].at("estimator"), "directions");
  EXPECT_EQ(records[6].at("estimator"), "settings");
  // The penumbra probe's error falls with samples, and the defaults meet their target.
  EXPECT_LT(records[2].at("err_max_pct").get<double>(), records[0].at("err_max_pct").get<double>());
  EXPECT_LT(records[6].at("error_estimate_pct").get<double>(), 1.0);
  ASSERT_NE(run_cli("bench " + scene.string() + " data/hdri/courtyard.exr", err), 0);
  EXPECT_NE(err.find("give scenes (.json) or maps, not both"), std::string::npos) << err;
}

TEST(BakeCli, BenchOfALightmapSceneMeasuresItsTexelsBesideItsProbes) {
  // A sun 40 degrees wide over a floor half under a box's edge 1 above it: the penumbra is
  // 2 tan(20 deg) = 0.73 wide, so texels of the 8 x 8 lightmap (4 x 4 in a quick study, 0.5
  // wide) sample it at their points; the rest of the floor is exact (fully lit or umbra).
  const fs::path scene = shpack_test::write_scene("cli_bench_lightmap.json", R"({"probes": [[0.1, 0.5, 0]],
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1, "angular_diameter_deg": 40}],
    "geometry": [{"type": "box", "min": [-100, 1, -100], "max": [0, 2, 100]},
                 {"type": "plane", "name": "floor", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0],
                  "size": [2, 2], "lightmap": {"resolution": [8, 8]}}],
    "effects": ["direct", "shadows"]})");
  const fs::path out = shpack_test::scene_scratch() / "cli_bench_lightmap.out";
  std::string err;
  ASSERT_EQ(run_cli("bench " + scene.string() + " --quick --scene-seeds 2 --json > " + out.string(), err), 0) << err;
  const nlohmann::json records = nlohmann::json::parse(std::ifstream(out));
  // shadows for each receiver kind: 3 counts for each of the two estimators, and the settings.
  ASSERT_EQ(records.size(), 14u) << records.dump();
  for (std::size_t i = 0; i < records.size(); ++i) {
    const auto& r = records[i];
    EXPECT_EQ(r.at("receivers"), i < 7 ? "probes" : "texels") << r.dump();
    EXPECT_EQ(r.at("count"), i < 7 ? 1u : 16u) << r.dump();
    EXPECT_GT(r.at("receivers_per_s").get<double>(), 0.0) << r.dump();
    EXPECT_EQ(r.at("effect"), "shadows");
  }
  // The worst texel's error falls with samples (64 -> 1024: by 4 in expectation, for a
  // 1/sqrt(N) rate; far more than the spread of an RMS over two seeds), and the settings
  // meet their target.
  EXPECT_LT(records[9].at("err_max_pct").get<double>(), 0.5 * records[7].at("err_max_pct").get<double>())
      << records.dump();
  EXPECT_EQ(records[13].at("estimator"), "settings");
  EXPECT_LT(records[13].at("error_estimate_pct").get<double>(), 1.0);
}

}  // namespace
