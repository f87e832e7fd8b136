// Tests of `shpack bake --shard K/N` and `shpack merge` as a user runs them: the merged files
// are the one-machine bake's, byte for byte (the JSON's timings aside); wrong parts fail in
// one line naming the file and write nothing.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "bake_support.h"
#include "scene/scene_files.h"

namespace {

namespace fs = std::filesystem;

using shpack_test::run_cli;

constexpr const char* kScene = R"({
  "environment": {"type": "gradient", "zenith": [0.2, 0.3, 0.8], "horizon": 0.7, "ground": 0.2},
  "lights": [{"type": "directional", "direction": [-0.4, -0.8, -0.3], "irradiance": 5, "angular_diameter_deg": 4}],
  "geometry": [
    {"type": "plane", "name": "floor", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0],
     "size": [4, 4], "albedo": 0.5, "lightmap": {"resolution": [6, 6]}},
    {"type": "box", "min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5], "albedo": 0.6}],
  "probes": [[0, 0.5, 0], [1.5, 0.5, 1.5], [-1.5, 1, 0.5]],
  "effects": ["direct", "environment", "shadows", "sky_occlusion", "bounce:1"],
  "settings": {"shadow_samples": 16, "sky_samples": 64, "bounce_samples": 64}})";

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The document without what measures time (keys ending in _ms or _per_s).
nlohmann::json without_timings(nlohmann::json j) {
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (auto& [key, value] : j.items())
      if (!key.ends_with("_ms") && !key.ends_with("_per_s")) out[key] = without_timings(value);
    return out;
  }
  if (j.is_array())
    for (auto& v : j) v = without_timings(v);
  return j;
}

TEST(MergeCli, MergedShardsWriteTheOneMachineFiles) {
  const fs::path scene = shpack_test::write_scene("merge_cli.json", kScene);
  const fs::path one = shpack_test::scene_scratch() / "merge_one";
  const fs::path merged = shpack_test::scene_scratch() / "merge_merged";
  fs::create_directories(one);
  fs::create_directories(merged);
  std::string err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " -o " + (one / "out.json").string() + " --quiet", err), 0) << err;
  std::string parts;
  for (const char* k : {"3", "1", "2"}) {  // merged in another order than baked
    const fs::path part = shpack_test::scene_scratch() / (std::string("merge_part") + k);
    std::string bake = "bake ";  // appended: g++ 12 -O3 misreads "literal" + string&& (-Wstringop-overflow)
    bake.append(scene.string()).append(" --shard ").append(k).append("/3 --threads 1 -o ").append(part.string());
    ASSERT_EQ(run_cli(bake.append(" --quiet"), err), 0) << err;
    parts.append(" ").append(part.string());
  }
  ASSERT_EQ(run_cli("merge" + parts + " -o " + (merged / "out.json").string(), err), 0) << err;
  for (const char* group : {"SHAr", "SHAg", "SHAb", "texels"}) {
    const std::string name = std::string("floor.") + group + ".exr";
    EXPECT_EQ(bytes_of(one / name), bytes_of(merged / name)) << name;
  }
  for (const char* json : {"out.json", "floor.lightmap.json"})
    EXPECT_EQ(without_timings(nlohmann::json::parse(bytes_of(one / json))),
              without_timings(nlohmann::json::parse(bytes_of(merged / json))))
        << json;
}

TEST(MergeCli, WrongPartsFailInOneLineNamingTheFileAndWriteNothing) {
  const fs::path scene = shpack_test::write_scene("merge_bad.json", kScene);
  const fs::path dir = shpack_test::scene_scratch() / "merge_bad";
  fs::create_directories(dir);
  std::string err;
  const fs::path p1 = dir / "p1", p2 = dir / "p2";
  ASSERT_EQ(run_cli("bake " + scene.string() + " --shard 1/2 -o " + p1.string() + " --quiet", err), 0) << err;
  ASSERT_EQ(run_cli("bake " + scene.string() + " --shard 2/2 -o " + p2.string() + " --quiet", err), 0) << err;
  const fs::path out = dir / "out.json";
  {
    std::ofstream keep(out);
    keep << "a good output\n";
  }
  const auto fails = [&](const std::string& args, const std::string& want) {
    EXPECT_EQ(run_cli("merge " + args + " -o " + out.string(), err), 1) << args;
    EXPECT_NE(err.find(want), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_EQ(bytes_of(out), "a good output\n");
    EXPECT_FALSE(fs::exists(dir / "floor.SHAr.exr"));
  };
  fails(p1.string(), "shard 2/2 is missing");
  fails(p1.string() + " " + p1.string() + " " + p2.string(), "shard 1/2 twice");
  const std::string bytes = bytes_of(p2);
  const fs::path cut = dir / "cut";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() - 5);
  fails(p1.string() + " " + cut.string(), cut.string() + ": truncated or altered");
  // Another scene (one probe more): its own hash.
  nlohmann::json other = nlohmann::json::parse(kScene);
  other["probes"].push_back({0, 2, 0});
  const fs::path other_scene = shpack_test::write_scene("merge_other.json", other.dump());
  const fs::path q = dir / "q";
  ASSERT_EQ(run_cli("bake " + other_scene.string() + " --shard 2/2 -o " + q.string() + " --quiet", err), 0) << err;
  fails(p1.string() + " " + q.string(), q.string() + ": a part of another scene");
  // A part is a file of its own: --shard without -o is a usage error.
  EXPECT_EQ(run_cli("bake " + scene.string() + " --shard 1/2 --quiet", err), 2);
  EXPECT_NE(err.find("-o PART"), std::string::npos) << err;
  EXPECT_EQ(run_cli("bake " + scene.string() + " --shard 3/2 -o " + (dir / "x").string(), err), 2);
  EXPECT_FALSE(fs::exists(dir / "x"));
}

}  // namespace
