// Tests of probe validity (docs/scenes.md, "Probe validity"): a probe inside closed geometry
// (a box, a sphere, an OBJ or glTF mesh, a thin wall) is invalid, one in the open, just
// outside a wall or on a floor is valid, and each settings.invalid_probes policy does what it
// says: dilate (the exact weighted mean of the nearest valid probes), keep, error, offset.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bake_support.h"
#include "scene/scene_files.h"
#include "shpack/bake/bake.h"
#include "shpack/scene/scene_loader.h"
#include "support/exr_file.h"
#include "support/test_util.h"

namespace shpack::bake {
namespace {

namespace fs = std::filesystem;
using shpack_test::kEps;

// The number of validity rays per probe and dilation's neighbour count (probe_validity.h),
// as documented.
constexpr int kRays = 256;
constexpr std::size_t kNeighbours = 8;

using shpack_test::Baked;
using shpack_test::bake_ok;
using shpack_test::bake_scene;

// A scene: probes, geometry and settings as JSON texts; sky occlusion of a grey sky, so that
// a probe whose every ray is blocked gets exactly zero.
std::string scene_json(const std::string& probes, const std::string& geometry, const std::string& settings = "{}",
                       const std::string& effects = R"("environment", "sky_occlusion")") {
  return R"({"probes": )" + probes + R"(,
    "environment": {"type": "gradient", "zenith": 1, "horizon": 1, "ground": 1},
    "geometry": )" + geometry + R"(, "effects": [)" + effects + R"(], "settings": )" + settings + "}";
}

constexpr const char* kKeep = R"({"invalid_probes": "keep"})";

// A cube [-1, 1]^3 around `centre` as 12 counter-clockwise triangles seen from outside, in a
// right-handed file (vertex v = x + 2y + 4z, coordinates -1 or 1). Each quad (a, b, c, d) has
// (b - a) x (c - a) pointing out of the cube.
constexpr std::uint16_t kCubeTriangles[36] = {0, 4, 6, 0, 6, 2,   // -x
                                              1, 3, 7, 1, 7, 5,   // +x
                                              0, 1, 5, 0, 5, 4,   // -y
                                              2, 6, 7, 2, 7, 3,   // +y
                                              0, 2, 3, 0, 3, 1,   // -z
                                              4, 5, 7, 4, 7, 6};  // +z
float cube_coordinate(int v, int axis) { return (v >> axis) & 1 ? 1.0f : -1.0f; }

// The cube as an OBJ file, stretched to the box [lo, hi].
std::string cube_obj(const std::array<double, 3>& lo = {-1, -1, -1}, const std::array<double, 3>& hi = {1, 1, 1}) {
  std::ostringstream obj;
  for (int v = 0; v < 8; ++v) {
    obj << "v";
    for (int axis = 0; axis < 3; ++axis) obj << " " << (cube_coordinate(v, axis) > 0 ? hi : lo)[axis];
    obj << "\n";
  }
  for (int t = 0; t < 12; ++t)
    obj << "f " << kCubeTriangles[3 * t] + 1 << " " << kCubeTriangles[3 * t + 1] + 1 << " "
        << kCubeTriangles[3 * t + 2] + 1 << "\n";
  return obj.str();
}

// The same cube as a glTF file with a base64 buffer: 8 float VEC3 positions (96 bytes), then
// 36 uint16 indices (72 bytes).
std::string cube_gltf() {
  std::string bytes(168, '\0');
  for (int v = 0; v < 8; ++v)
    for (int axis = 0; axis < 3; ++axis) {
      const float c = cube_coordinate(v, axis);
      std::memcpy(bytes.data() + 12 * v + 4 * axis, &c, 4);
    }
  std::memcpy(bytes.data() + 96, kCubeTriangles, 72);
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "buffers": [{"byteLength": 168, "uri": "data:application/octet-stream;base64,)" + shpack_test::base64(bytes) + R"("}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 72}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3", "min": [-1, -1, -1], "max": [1, 1, 1]},
                  {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}]})";
}

// Closed geometry: every ray from inside leaves through a back face (the tracer is
// watertight, RTC_SCENE_FLAG_ROBUST), every ray from outside meets a front face first. So
// the fractions are exactly 1 and 0, whatever the directions.
void expect_inside(const Baked& b, std::size_t k, std::uint32_t shape, const std::string& what) {
  const ProbeValidity& v = b.result.validity.at(k);
  EXPECT_EQ(v.backface_fraction, 1.0) << what;
  EXPECT_FALSE(v.valid) << what;
  ASSERT_TRUE(v.backface_shape.has_value()) << what;
  EXPECT_EQ(*v.backface_shape, shape) << what;
}
void expect_outside(const Baked& b, std::size_t k, const std::string& what) {
  const ProbeValidity& v = b.result.validity.at(k);
  EXPECT_EQ(v.backface_fraction, 0.0) << what;
  EXPECT_TRUE(v.valid) << what;
  EXPECT_FALSE(v.backface_shape.has_value()) << what;
}

TEST(ProbeValidity, InsideAClosedBoxOrSphereIsInvalidAndKeepKeepsItsZeros) {
  const Baked b = bake_ok("box", scene_json("[[0, 0.5, 0], [1.01, 0.5, 0], [0, 1.001, 0], [5, 5, 5.2]]",
                                            R"([{"type": "box", "name": "crate", "min": [-1, 0, -1], "max": [1, 1, 1]},
                                                {"type": "sphere", "position": [5, 5, 5], "radius": 1}])",
                                            kKeep));
  expect_inside(b, 0, 0, "inside the box");
  expect_outside(b, 1, "1 cm outside its +x wall");
  expect_outside(b, 2, "1 mm above its top");
  expect_inside(b, 3, 1, "inside the sphere");
  EXPECT_EQ(b.result.radiance[0], ShL2{}) << "keep: the sky all hidden, exactly, as baked";
  EXPECT_EQ(b.result.radiance[3], ShL2{});
  EXPECT_GT(b.result.radiance[1].c[0][0], 0.0);
  EXPECT_EQ(b.result.validity_counts.invalid, 2u);
  EXPECT_EQ(b.result.validity_counts.dilated, 0u);
  EXPECT_TRUE(b.result.validity_cost.enabled);
  EXPECT_EQ(b.result.validity_cost.rays, 4u * kRays) << "keep traces no offset ray";
}

TEST(ProbeValidity, InsideAClosedMeshIsInvalidForObjAndMirroredGltf) {
  // The glTF file is mirrored into Unity's frame (mirror_z, its default), which reverses the
  // triangles' winding: the loader must keep their fronts outside.
  shpack_test::write_scene("cube.obj", cube_obj());
  shpack_test::write_scene("cube.gltf", cube_gltf());
  for (const std::string file : {"cube.obj", "cube.gltf"}) {
    const Baked b = bake_ok("mesh", scene_json("[[3, 0.2, -0.1], [3, 2.02, 0], [5, 0, 0]]",
                                               R"([{"type": "mesh", "path": ")" + file + R"(", "position": [3, 1, 0]}])",
                                               kKeep));
    expect_inside(b, 0, 0, file + ": inside");
    expect_outside(b, 1, file + ": 2 cm above it");
    expect_outside(b, 2, file + ": beside it");
  }
}

TEST(ProbeValidity, APlaneHasNoInsideOnEitherSideOrOnIt) {
  for (const std::string up : {"[0, 0, 1]", "[0, 0, -1]"}) {
    const Baked b = bake_ok("floor", scene_json("[[0, 0, 0], [0, 0.001, 0], [0, -0.001, 0], [0.3, 1, 0.2]]",
                                                R"([{"type": "plane", "position": [0, 0, 0], "right": [1, 0, 0], "up": )" +
                                                    up + R"(, "size": [10, 10]}])"));
    for (std::size_t k = 0; k < 4; ++k) expect_outside(b, k, "up " + up + ", probe " + std::to_string(k));
  }
}

TEST(ProbeValidity, AThinWallHasAnInsideAndAnOutside) {
  const std::string wall = R"([{"type": "box", "name": "wall", "min": [-0.05, -5, -5], "max": [0.05, 5, 5]}])";
  const Baked b = bake_ok("wall", scene_json("[[0.01, 0, 0], [0.06, 0, 0], [-0.051, 1, 2]]", wall, kKeep));
  expect_inside(b, 0, 0, "inside the wall");
  expect_outside(b, 1, "1 cm outside it");
  expect_outside(b, 2, "1 mm outside its other side");
}

// The weighted mean of probe k's nearest valid probes, computed here from the documented rule:
// the kNeighbours nearest (ties by index), weights 1 / d^2.
struct Expected {
  ShL2 mean;
  ShL2 abs_mean;  // sum w |x| / sum w, for the rounding tolerance
};
template <class Value>
Expected dilated_value(const Baked& b, std::size_t k, const Value& value) {
  std::vector<std::pair<double, std::size_t>> valid;
  const Point3& p = b.scene.probes[k];
  for (std::size_t j = 0; j < b.scene.probes.size(); ++j) {
    if (!b.result.validity[j].valid) continue;
    const Point3& q = b.scene.probes[j];
    valid.push_back({(p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + (p.z - q.z) * (p.z - q.z), j});
  }
  std::sort(valid.begin(), valid.end());
  valid.resize(std::min(valid.size(), kNeighbours));
  Expected e;
  double total = 0;
  for (const auto& [d2, j] : valid) total += 1 / d2;
  for (const auto& [d2, j] : valid)
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) {
        e.mean.c[c][i] += (1 / d2) / total * value(j).c[c][i];
        e.abs_mean.c[c][i] += (1 / d2) / total * std::fabs(value(j).c[c][i]);
      }
  return e;
}

// Summing n = 8 terms w_j x_j / sum w in a different order and grouping: each result is within
// about (n + 3) u sum_j w_j |x_j| / sum w of the exact mean (Higham, Accuracy and Stability of
// Numerical Algorithms, 2002, eq. 4.4, with the divisions' rounding); twice that between two.
void expect_mean(const ShL2& got, const Expected& want, const std::string& what) {
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i)
      EXPECT_NEAR(got.c[c][i], want.mean.c[c][i], 2 * (kNeighbours + 3) * kEps * want.abs_mean.c[c][i] + 1e-300)
          << what << " c=" << c << " i=" << i;
}

TEST(ProbeValidity, DilateGivesTheSquaredDistanceWeightedMeanOfTheEightNearestValidProbes) {
  // A crate around probe 0; ten valid probes at different distances (two of them farther than
  // the eight nearest), lit differently by a point light (unshadowed: only direct).
  const std::string probes = R"([[0, 0.5, 0], [1.5, 0.5, 0], [0, 0.5, 1.7], [-1.9, 0.5, 0], [0, 0.5, -2.1],
    [0, 2.3, 0], [1.6, 1.6, 0], [-1.8, 1.4, 1.2], [2, 2, 2], [4, 1, 0], [-5, 3, 1]])";
  const Baked b = bake_ok("dilate", R"({"probes": )" + probes + R"(,
    "lights": [{"type": "point", "position": [3, 4, -2], "intensity": [5, 4, 3]}, {"type": "ambient", "radiance": 0.1}],
    "geometry": [{"type": "box", "name": "crate", "min": [-1, 0, -1], "max": [1, 1, 1]}], "effects": ["direct"]})");
  ASSERT_EQ(b.result.validity.size(), 11u);
  expect_inside(b, 0, 0, "probe 0");
  for (std::size_t k = 1; k < 11; ++k) expect_outside(b, k, "probe " + std::to_string(k));
  EXPECT_TRUE(b.result.validity[0].dilated);
  EXPECT_EQ(b.result.validity_counts.dilated, 1u);
  EXPECT_TRUE(b.result.geometry.built) << "validity needs the tracer, though no effect traces rays";
  EXPECT_EQ(b.result.costs[static_cast<std::size_t>(Effect::Direct)].rays, 0u);
  const auto total = [&](std::size_t j) -> const ShL2& { return b.result.radiance[j]; };
  expect_mean(b.result.radiance[0], dilated_value(b, 0, total), "total");
  const auto direct = [&](std::size_t j) -> const ShL2& {
    return b.result.effects[j][static_cast<std::size_t>(Effect::Direct)];
  };
  expect_mean(b.result.effects[0][static_cast<std::size_t>(Effect::Direct)], dilated_value(b, 0, direct),
              "direct part");
}

TEST(ProbeValidity, ErrorNamesTheFirstInvalidProbeAndTheShapeAroundIt) {
  const Baked b = bake_scene("error", scene_json("[[5, 5, 5], [0, 0.5, 0], [0.2, 0.5, 0]]",
                                                 R"([{"type": "sphere", "position": [9, 9, 9], "radius": 1},
                                                     {"type": "box", "name": "crate", "min": [-1, 0, -1], "max": [1, 1, 1]}])",
                                                 R"({"invalid_probes": "error"})"));
  ASSERT_FALSE(b.status.ok());
  EXPECT_EQ(b.status.message, b.scene.file.string() +
                                  ": probes[1] (0, 0.5, 0) is inside geometry[1] 'crate': 256 of its 256 rays hit back "
                                  "faces, more than settings.validity_threshold 0.25 (settings.invalid_probes \"error\")");
}

TEST(ProbeValidity, EveryProbeInvalidWithNothingToDilateFromIsAnError) {
  const Baked b = bake_scene("all_invalid", scene_json("[[0, 0.5, 0], [0.5, 0.5, 0.5]]",
                                                       R"([{"type": "box", "min": [-1, 0, -1], "max": [1, 1, 1]}])"));
  ASSERT_FALSE(b.status.ok());
  EXPECT_EQ(b.status.message, b.scene.file.string() +
                                  ": no valid probe to dilate from (every probe is inside geometry); probes[0] (0, 0.5, "
                                  "0) is inside geometry[0]: 256 of its 256 rays hit back faces, more than "
                                  "settings.validity_threshold 0.25");
}

TEST(ProbeValidity, OffsetMovesAProbeOutOfAThinWallAndBakesItThere) {
  // Probe 0 is 4 cm inside the +x face of a 10 cm wall. Along a ray d leaving through that
  // face at t = 0.04 / d_x, the candidate is 1 cm further (no surface beyond): x = 0.05 +
  // 0.01 d_x, outside, and valid (it sees only the wall's front). The nearest exit is that
  // face's, so the probe moves by 0.04 / d_x + 0.01 with d_x the largest of its rays.
  const std::string wall = R"([{"type": "box", "name": "wall", "min": [-0.05, -5, -5], "max": [0.05, 5, 5]},
                                 {"type": "box", "name": "block", "min": [3, -1, -1], "max": [5, 1, 1]}])";
  const std::string lights = R"("lights": [{"type": "point", "position": [2, 0.5, 0.3], "intensity": 3}],)";
  const std::string json = R"({"probes": [[0.01, 0, 0], [4, 0, 0], [1, 0, 0]], )" + lights + R"(
    "geometry": )" + wall + R"(, "effects": ["direct", "shadows"],
    "settings": {"invalid_probes": "offset", "max_offset": 0.2}})";
  const Baked b = bake_ok("offset", json);
  const ProbeValidity& v = b.result.validity[0];
  EXPECT_FALSE(v.valid);
  EXPECT_EQ(v.backface_fraction, 1.0);
  ASSERT_TRUE(v.offset_position.has_value());
  const Point3 q = *v.offset_position;
  EXPECT_GT(q.x, 0.05) << "out of the wall, on the near side";
  EXPECT_LE(q.x, 0.06 + 1e-9);
  const double moved = std::hypot(q.x - 0.01, q.y, q.z);
  EXPECT_LE(moved, 0.2) << "within max_offset";
  EXPECT_EQ(v.offset_backface_fraction, 0.0);
  EXPECT_FALSE(v.dilated);
  EXPECT_EQ(b.result.validity_counts.moved, 1u);
  // Probe 1, 1 m inside the block, has no exit within 0.2 m: it stays invalid and is dilated,
  // from probe 2 and the moved probe 0.
  EXPECT_FALSE(b.result.validity[1].valid);
  EXPECT_FALSE(b.result.validity[1].offset_position.has_value());
  EXPECT_TRUE(b.result.validity[1].dilated);
  // Probe 0's SH is a bake at the offset position: the same scene with the probe placed there.
  scene::Scene there = b.scene;
  there.probes = {q, b.scene.probes[1], b.scene.probes[2]};
  there.settings.invalid_probes = scene::InvalidProbes::Keep;
  BakeResult direct;
  BakeOptions options;
  options.threads = 2;
  ASSERT_TRUE(bake(there, options, direct).ok());
  EXPECT_EQ(b.result.radiance[0], direct.radiance[0]);
  EXPECT_GT(b.result.radiance[0].c[0][0], 0.0) << "the light on its side reaches it";
}

TEST(ProbeValidity, TheSameForAnyThreadCount) {
  const std::string json = R"({"probes": {"min": [-1.5, 0.25, -1.5], "max": [1.5, 1.25, 1.5], "counts": [4, 3, 4]},
    "lights": [{"type": "point", "position": [0, 3, 0], "intensity": 2}],
    "geometry": [{"type": "box", "min": [-1, 0, -1], "max": [1, 1, 1]},
                 {"type": "sphere", "position": [1.5, 0.75, 1.5], "radius": 0.3}],
    "effects": ["direct", "shadows"], "settings": {"invalid_probes": "offset", "max_offset": 0.3, "seed": 5}})";
  const Baked one = bake_ok("threads1", json, 1), three = bake_ok("threads3", json, 3);
  ASSERT_EQ(one.result.validity.size(), 48u);
  EXPECT_GT(one.result.validity_counts.invalid, 0u);
  for (std::size_t k = 0; k < 48; ++k) {
    EXPECT_EQ(one.result.validity[k].backface_fraction, three.result.validity[k].backface_fraction) << k;
    EXPECT_EQ(one.result.validity[k].offset_position, three.result.validity[k].offset_position) << k;
    EXPECT_EQ(one.result.radiance[k], three.result.radiance[k]) << k;
  }
}

// The example of docs/scenes.md, with its sky map and its chair (a cube around the probe at
// (0, 0.5, 0)): that probe used to get zeros from sky occlusion, silently.
TEST(ProbeValidity, TheDocsExampleWithAProbeInsideTheChairIsDilatedAndSaysSo) {
  shpack_test::RgbImage sky(32, 16);
  for (std::uint32_t y = 0; y < 16; ++y)
    for (std::uint32_t x = 0; x < 32; ++x) sky.set(x, y, 1.0f, 0.9f, 0.8f - 0.4f * y / 16);
  std::string error;
  ASSERT_TRUE(shpack_test::write_exr_rgb(shpack_test::scene_scratch() / "sky.exr", sky, error)) << error;
  const std::string chair = cube_obj({-0.3, 0.2, -0.3}, {0.3, 0.8, 0.3});
  shpack_test::write_scene("chair.obj", chair);
  const fs::path scene = shpack_test::write_scene("docs_example.json", R"({
  "probes": {"min": [-2, 0.5, -2], "max": [2, 2, 2], "counts": [5, 3, 5]},
  "environment": {"type": "map", "path": "sky.exr", "rotation_deg": 90},
  "lights": [
    {"type": "directional", "name": "sun", "direction": [0.3, -1, 0.2], "irradiance": [900, 880, 850],
     "angular_diameter_deg": 0.53},
    {"type": "sphere", "name": "lamp", "position": [0, 2.8, 0], "radius": 0.1, "power": 60},
    {"type": "rect", "name": "window", "position": [0, 1.5, 3], "right": [-1, 0, 0], "up": [0, 1, 0],
     "size": [1.2, 1], "radiance": 40}
  ],
  "geometry": [
    {"type": "box", "name": "floor", "min": [-3, -0.1, -3], "max": [3, 0, 3], "albedo": 0.4},
    {"type": "mesh", "name": "chair", "path": "chair.obj", "albedo": [0.6, 0.4, 0.3]}
  ],
  "effects": ["direct", "environment", "shadows", "sky_occlusion", "bounce:2"],
  "settings": {"seed": 1, "shadow_samples": 256}
})");
  const fs::path out = shpack_test::scene_scratch() / "docs_example_out.json";
  std::string err;
  ASSERT_EQ(shpack_test::run_cli("bake " + scene.string() + " -o " + out.string() + " --quiet", err), 0) << err;
  // One line of its own (other warnings, of the Monte Carlo effects, may come too).
  const std::string warning = "shpack: " + scene.string() + ": 1 of 75 probes are inside geometry (more than 25% of "
                              "their rays hit back faces) and were dilated: each took the distance-weighted mean of "
                              "its nearest valid probes\n";
  EXPECT_NE(err.find(warning), std::string::npos) << err;
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(out));
  const std::size_t inside = 2 + 5 * (0 + 3 * 2);  // x = 0, y = 0.5, z = 0: ix = 2, iy = 0, iz = 2
  const nlohmann::json& d = doc.at("probes").at(inside).at("diagnostics");
  EXPECT_EQ(doc.at("probes").at(inside).at("position"), nlohmann::json::parse("[0.0, 0.5, 0.0]"));
  EXPECT_EQ(d.at("valid"), false);
  EXPECT_EQ(d.at("backface_fraction"), 1.0);
  EXPECT_EQ(d.at("inside"), "geometry[1] 'chair'");
  EXPECT_EQ(d.at("dilated"), true);
  EXPECT_GT(doc.at("probes").at(inside).at("radiance_sh").at(0).at(0).get<double>(), 0.0) << "no longer zeros";
  EXPECT_EQ(doc.at("validity").at("dilated"), 1);
  EXPECT_EQ(doc.at("probes").at(0).at("diagnostics").at("valid"), true);
  // "error" writes nothing and exits 1 with the one line.
  const fs::path strict = shpack_test::write_scene(
      "docs_example_error.json", R"({"probes": [[0, 0.5, 0]],
        "geometry": [{"type": "mesh", "name": "chair", "path": "chair.obj"}],
        "effects": [], "settings": {"invalid_probes": "error"}})");
  fs::remove(out);
  EXPECT_EQ(shpack_test::run_cli("bake " + strict.string() + " -o " + out.string(), err), 1);
  EXPECT_EQ(err, "shpack: " + strict.string() + ": probes[0] (0, 0.5, 0) is inside geometry[0] 'chair': 256 of its 256 "
                 "rays hit back faces, more than settings.validity_threshold 0.25 (settings.invalid_probes \"error\")\n");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace shpack::bake
