// Tests of scene_loader.h: what a valid scene becomes, and that every bad scene file is
// refused with the file and the JSON path of the bad value named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>
#include <numbers>
#include <string>

#include "scene/scene_files.h"
#include "shpack/scene/scene_loader.h"

namespace shpack::scene {
namespace {

using shpack_test::write_scene;

TEST(SceneLoader, ReadsAGridLightsGeometryAndEffects) {
  const auto path = write_scene("good.json", R"({
    "probes": {"min": [0, 0, 0], "max": [1, 2, 3], "counts": [2, 3, 1]},
    "environment": {"type": "gradient", "zenith": [0.1, 0.2, 0.3], "horizon": 1, "ground": [0, 0, 0]},
    "lights": [
      {"type": "point", "name": "bulb", "position": [0, 3, 0], "power": 100},
      {"type": "spot", "position": [0, 3, 0], "direction": [0, -2, 0], "inner_angle_deg": 10,
       "outer_angle_deg": 30, "intensity": [1, 2, 3]},
      {"type": "directional", "direction": [0, -1, 0], "irradiance": 2, "angular_diameter_deg": 0.53}
    ],
    "geometry": [{"type": "box", "name": "table", "min": [-1, 0, -1], "max": [1, 0.1, 1], "albedo": 0.5},
                 {"type": "sphere", "position": [0, 1, 0], "radius": 0.5, "emission": [1, 1, 1]}],
    "effects": ["direct", "environment", "shadows", "bounce:3"],
    "settings": {"seed": 7, "shadow_samples": 64}
  })");
  Scene scene;
  const io::IoStatus st = load_scene(path, scene);
  ASSERT_TRUE(st.ok()) << st.message;
  ASSERT_EQ(scene.probes.size(), 6u);
  // x fastest, then y; both ends included.
  EXPECT_EQ(scene.probes[0], (Point3{0, 0, 0}));
  EXPECT_EQ(scene.probes[1], (Point3{1, 0, 0}));
  EXPECT_EQ(scene.probes[5], (Point3{1, 2, 0}));
  ASSERT_EQ(scene.lights.size(), 3u);
  EXPECT_EQ(scene.lights[0].label, "lights[0] 'bulb'");
  EXPECT_NEAR(scene.lights[0].colour[1], 100 / (4 * std::numbers::pi), 1e-15) << "power P -> I = P / 4 pi";
  EXPECT_EQ(scene.lights[1].direction, (Dir3{0, -1, 0})) << "directions are normalised";
  EXPECT_NEAR(scene.lights[1].outer_angle, std::numbers::pi / 6, 1e-15);
  EXPECT_NEAR(scene.lights[2].angular_diameter, 0.53 * std::numbers::pi / 180, 1e-17);
  ASSERT_EQ(scene.geometry.size(), 2u);
  EXPECT_EQ(scene.geometry[0].indices.size(), 36u) << "a box is 12 triangles";
  EXPECT_EQ(scene.geometry[0].label, "geometry[0] 'table'");
  EXPECT_EQ(scene.environment.type, EnvironmentType::Gradient);
  EXPECT_EQ(scene.environment.horizon, (Rgb{1, 1, 1}));
  EXPECT_TRUE(scene.effects.direct && scene.effects.environment && scene.effects.shadows);
  EXPECT_FALSE(scene.effects.sky_occlusion || scene.effects.emission);
  EXPECT_EQ(scene.effects.bounces, 3);
  EXPECT_EQ(scene.settings.seed, 7u);
  EXPECT_EQ(scene.settings.shadow_samples, 64);
  EXPECT_EQ(scene.sha256.size(), 64u);
}

struct BadScene {
  const char* name;
  const char* json;
  const char* message;  // after "<file>: "
};

class SceneLoaderErrors : public testing::TestWithParam<BadScene> {};

TEST_P(SceneLoaderErrors, NameTheFileAndTheJsonPath) {
  const BadScene& bad = GetParam();
  const auto path = write_scene(std::string(bad.name) + ".json", bad.json);
  Scene scene;
  scene.probes.push_back({9, 9, 9});  // must survive a failed load
  const io::IoStatus st = load_scene(path, scene);
  ASSERT_FALSE(st.ok()) << bad.name;
  EXPECT_EQ(st.message, path.string() + ": " + bad.message) << bad.name;
  ASSERT_EQ(scene.probes.size(), 1u) << bad.name << ": the output is untouched";
}

constexpr const char* kLightsPrefix = R"({"probes": [[0, 0, 0]], "effects": ["direct"], "lights": [
  {"type": "ambient", "radiance": 1}, {"type": "hemisphere", "sky": 1, "ground": 0}, )";

INSTANTIATE_TEST_SUITE_P(
    Scenes, SceneLoaderErrors,
    testing::Values(
        BadScene{"radius", R"({"probes": [[0, 0, 0]], "effects": ["direct"], "lights": [
          {"type": "ambient", "radiance": 1}, {"type": "hemisphere", "sky": 1, "ground": 0},
          {"type": "sphere", "position": [0, 5, 0], "radius": 0, "intensity": 1}]})",
                 "lights[2].radius: must be > 0"},
        BadScene{"unknown_key", R"({"probes": [[0, 0, 0]], "effects": ["direct"], "lights": [
          {"type": "point", "position": [0, 5, 0], "intensity": 1, "colour": 2}]})",
                 "lights[0]: unknown key 'colour'"},
        BadScene{"power_and_intensity", R"({"probes": [[0, 0, 0]], "effects": [], "lights": [
          {"type": "point", "position": [0, 5, 0], "intensity": 1, "power": 2}]})",
                 "lights[0]: needs exactly one of 'intensity' and 'power'"},
        BadScene{"no_intensity", R"({"probes": [[0, 0, 0]], "effects": [], "lights": [
          {"type": "point", "position": [0, 5, 0]}]})",
                 "lights[0]: needs exactly one of 'intensity' and 'power'"},
        BadScene{"light_type", R"({"probes": [[0, 0, 0]], "effects": [], "lights": [{"type": "laser"}]})",
                 "lights[0].type: is not one of the allowed values"},
        BadScene{"negative_colour", R"({"probes": [[0, 0, 0]], "effects": [], "lights": [
          {"type": "ambient", "radiance": [1, -1, 0]}]})",
                 "lights[0].radiance[1]: must be >= 0"},
        BadScene{"short_vector", R"({"probes": [[0, 0]], "effects": []})",
                 "probes[0]: Array should contain no fewer than 3 elements."},
        BadScene{"missing_effects", R"({"probes": [[0, 0, 0]]})", "(root): missing 'effects'"},
        BadScene{"bad_effect", R"({"probes": [[0, 0, 0]], "effects": ["direct", "bounce:0"]})",
                 "effects[1]: is not an effect (direct, environment, shadows, sky_occlusion, emission, bounce:N)"},
        BadScene{"shadows_alone", R"({"probes": [[0, 0, 0]], "effects": ["shadows"]})",
                 "effects: shadows needs direct"},
        BadScene{"environment_missing", R"({"probes": [[0, 0, 0]], "effects": ["environment"]})",
                 "effects: environment needs an 'environment' section"},
        BadScene{"zero_direction", R"({"probes": [[0, 0, 0]], "effects": [], "lights": [
          {"type": "directional", "direction": [0, 0, 0], "irradiance": 1}]})",
                 "lights[0].direction: must be a non-zero direction"},
        BadScene{"spot_angles", R"({"probes": [[0, 0, 0]], "effects": [], "lights": [
          {"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "inner_angle_deg": 40,
           "outer_angle_deg": 30, "intensity": 1}]})",
                 "lights[0].inner_angle_deg: must be <= outer_angle_deg"},
        BadScene{"rect_axes", R"({"probes": [[0, 0, 0]], "effects": [], "lights": [
          {"type": "rect", "position": [0, 1, 0], "right": [1, 0, 0], "up": [1, 1, 0], "size": [1, 1],
           "radiance": 1}]})",
                 "lights[0].up: must be orthogonal to right"},
        BadScene{"albedo", R"({"probes": [[0, 0, 0]], "effects": [], "geometry": [
          {"type": "sphere", "position": [0, 1, 0], "radius": 1, "albedo": [0.5, 1, 0.5]}]})",
                 "geometry[0].albedo[1]: must be < 1"},
        BadScene{"box", R"({"probes": [[0, 0, 0]], "effects": [], "geometry": [
          {"type": "box", "min": [0, 0, 0], "max": [1, 0, 1]}]})",
                 "geometry[0].max: must exceed min on every axis"},
        BadScene{"grid", R"({"probes": {"min": [0, 0, 0], "max": [1, 1, 1], "counts": [0, 1, 1]}, "effects": []})",
                 "probes.counts[0]: must be >= 1"},
        BadScene{"syntax", "{\"probes\": [[0, 0, 0]],\n \"effects\": [}",
                 "not valid JSON: line 2, column 14: syntax error while parsing value - unexpected '}'; "
                 "expected '[', '{', or a literal"}),
    [](const testing::TestParamInfo<BadScene>& info) { return std::string(info.param.name); });

TEST(SceneLoader, MissingReferencedFilesAreNamed) {
  const auto path = write_scene("missing_map.json", R"({"probes": [[0, 0, 0]], "effects": ["environment"],
    "environment": {"type": "map", "path": "no_such_sky.exr"}})");
  Scene scene;
  const io::IoStatus st = load_scene(path, scene);
  ASSERT_FALSE(st.ok());
  const std::string map = (path.parent_path() / "no_such_sky.exr").string();
  EXPECT_EQ(st.message, path.string() + ": environment.path: " + map + ": no such file");
}

TEST(SceneLoader, ReadsAnObjMesh) {
  const auto obj = write_scene("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n");
  const auto path = write_scene("mesh.json", R"({"probes": [[0, 1, 0]], "effects": [],
    "geometry": [{"type": "mesh", "path": "quad.obj", "position": [0, 2, 0], "scale": 2, "mirror_z": true}]})");
  Scene scene;
  const io::IoStatus st = load_scene(path, scene);
  ASSERT_TRUE(st.ok()) << st.message;
  ASSERT_EQ(scene.geometry.size(), 1u);
  EXPECT_EQ(scene.geometry[0].indices.size(), 6u) << "the quad is triangulated";
  ASSERT_EQ(scene.geometry[0].vertices.size(), 12u);
  EXPECT_EQ(scene.geometry[0].vertices[6], 2.0f);   // x of v3, scaled
  EXPECT_EQ(scene.geometry[0].vertices[7], 2.0f);   // y moved up by 2
  EXPECT_EQ(scene.geometry[0].vertices[8], -2.0f);  // z mirrored
}

}  // namespace
}  // namespace shpack::scene

namespace shpack::scene {
namespace {

// A buffer of one triangle: 3 float VEC3 positions (36 bytes), then 3 uint16 indices (6 bytes,
// padded to 8).
std::string triangle_buffer() {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::uint16_t i[4] = {0, 1, 2, 0};
  std::string bytes(44, '\0');
  std::memcpy(bytes.data(), p, 36);
  std::memcpy(bytes.data() + 36, i, 8);
  return bytes;
}

// The glTF document around the buffer: a parent node moved by +2 in x holding a child that
// is scaled by 3 and turned 90 degrees about +Y (quaternion (0, sin 45, 0, cos 45)).
std::string gltf_json(const std::string& buffer_entry) {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"translation": [2, 0, 0], "children": [1]},
              {"mesh": 0, "scale": [3, 3, 3], "rotation": [0, 0.7071067811865476, 0, 0.7071067811865476]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "buffers": [)" + buffer_entry + R"(],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
}

void expect_turned_triangle(const Scene& scene, const std::string& what) {
  ASSERT_EQ(scene.geometry.size(), 1u) << what;
  const std::vector<float>& v = scene.geometry[0].vertices;
  ASSERT_EQ(v.size(), 9u) << what;
  // Mirrored into Unity's frame, the triangle is listed in the reverse order, so that its
  // counter-clockwise front stays its front.
  EXPECT_EQ(scene.geometry[0].indices, (std::vector<std::uint32_t>{0, 2, 1})) << what;
  // Vertex 1, (1, 0, 0): scaled to (3, 0, 0), turned about +Y by 90 degrees (right-handed:
  // x -> -z) to (0, 0, -3), moved to (2, 0, -3); in Unity's frame z -> -z: (2, 0, 3).
  EXPECT_NEAR(v[3], 2.0f, 1e-6) << what;
  EXPECT_NEAR(v[4], 0.0f, 1e-6) << what;
  EXPECT_NEAR(v[5], 3.0f, 1e-6) << what;
  // Vertex 2, (0, 1, 0): (0, 3, 0) on the axis, moved to (2, 3, 0).
  EXPECT_NEAR(v[6], 2.0f, 1e-6) << what;
  EXPECT_NEAR(v[7], 3.0f, 1e-6) << what;
  EXPECT_NEAR(v[8], 0.0f, 1e-6) << what;
}

TEST(SceneLoader, ReadsGltfWithDataUriAndNodeTransforms) {
  const std::string bytes = triangle_buffer();
  shpack_test::write_scene("tri.gltf", gltf_json(R"({"byteLength": 44, "uri": "data:application/octet-stream;base64,)" +
                                                 shpack_test::base64(bytes) + R"("})"));
  const auto path = shpack_test::write_scene("gltf.json", R"({"probes": [[0, 1, 0]], "effects": [],
    "geometry": [{"type": "mesh", "path": "tri.gltf"}]})");
  Scene scene;
  const io::IoStatus st = load_scene(path, scene);
  ASSERT_TRUE(st.ok()) << st.message;
  expect_turned_triangle(scene, ".gltf");
}

TEST(SceneLoader, ReadsGlbWithItsBinaryChunk) {
  const std::string bin = triangle_buffer();
  std::string json = gltf_json(R"({"byteLength": 44})");
  while (json.size() % 4) json += ' ';
  const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string glb = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size())) +
                          u32(static_cast<std::uint32_t>(json.size())) + u32(0x4E4F534Au) + json +
                          u32(static_cast<std::uint32_t>(bin.size())) + u32(0x004E4942u) + bin;
  shpack_test::write_scene("tri.glb", glb);
  const auto path = shpack_test::write_scene("glb.json", R"({"probes": [[0, 1, 0]], "effects": [],
    "geometry": [{"type": "mesh", "path": "tri.glb"}]})");
  Scene scene;
  const io::IoStatus st = load_scene(path, scene);
  ASSERT_TRUE(st.ok()) << st.message;
  expect_turned_triangle(scene, ".glb");
  // A truncated file is refused with the file and the JSON path named.
  shpack_test::write_scene("tri.glb", glb.substr(0, 30));
  const io::IoStatus bad = load_scene(path, scene);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.message.find("geometry[0].path: " + (path.parent_path() / "tri.glb").string() + ": "), std::string::npos)
      << bad.message;
}

}  // namespace
}  // namespace shpack::scene
