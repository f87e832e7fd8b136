// Tests of the scene loader's limits (docs/scenes.md, "Limits"): hostile and careless files are
// refused with one line naming the file and the JSON path, never a crash, a hang or a runaway
// allocation. Each case here crashed, hung, aborted or was silently accepted before.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "obj_mesh.h"
#include "scene/scene_files.h"
#include "shpack/scene/scene_loader.h"

namespace shpack::scene {
namespace {

namespace fs = std::filesystem;
using shpack_test::scene_scratch;
using shpack_test::write_scene;

// The message of a load that must fail, after "<scene file>: " (checked to be there); "" if
// the load succeeded.
std::string load_error(const fs::path& path) {
  Scene scene;
  scene.probes.push_back({9, 9, 9});
  const io::IoStatus st = load_scene(path, scene);
  if (st.ok()) return "";
  EXPECT_EQ(scene.probes.size(), 1u) << "the output is untouched";
  EXPECT_EQ(st.message.find('\n'), std::string::npos) << "one line";
  const std::string prefix = path.string() + ": ";
  EXPECT_EQ(st.message.rfind(prefix, 0), 0u) << st.message;
  return st.message.substr(std::min(prefix.size(), st.message.size()));
}

std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// A scene with one mesh, `obj` written next to it.
fs::path mesh_scene(const std::string& name, const std::string& obj, const std::string& extra = "") {
  write_scene(name + ".obj", obj);
  return write_scene(name + ".json", R"({"probes": [[0, 5, 0]], "effects": [],
    "geometry": [{"type": "mesh", "path": ")" + name + ".obj\"" + extra + "}]}");
}

TEST(SceneLimits, DeepNestingIsRefusedBeforeParsing) {
  // 50,000 levels in 200 KB: valijson's uniqueItems recursed once per level and overflowed the stack.
  const auto deep = write_scene("deep.json", R"({"probes": [[0, 0, 0]], "effects": [)" + nested(50000) + ", " +
                                                 nested(50000) + "]}");
  EXPECT_EQ(load_error(deep), "nested deeper than 64 levels");
  // 64 levels in all (the root object is the first) pass to the schema; 65 do not.
  const auto ok = write_scene("deep64.json", R"({"probes": [[0, 0, 0]], "effects": [)" + nested(62) + "]}");
  EXPECT_EQ(load_error(ok), "effects[0]: has the wrong type");
  const auto over = write_scene("deep65.json", R"({"probes": [[0, 0, 0]], "effects": [)" + nested(63) + "]}");
  EXPECT_EQ(load_error(over), "nested deeper than 64 levels");
  // Brackets inside strings (with escaped quotes) are not nesting.
  const auto strings = write_scene("brackets.json", R"({"probes": [[0, 0, 0]], "effects": [],
    "lights": [{"type": "ambient", "radiance": 1, "name": "\")" + std::string(100, '[') + "\"}]}");
  EXPECT_EQ(load_error(strings), "");
}

TEST(SceneLimits, TheSceneFileIsReadUpToItsLimit) {
  // /dev/zero: read until the allocation failed (bad_alloc, uncaught, two lines).
  EXPECT_EQ(load_error("/dev/zero"), "is a device, not a regular file");
  const fs::path big = scene_scratch() / "big.json";
  write_scene("big.json", "{}");
  fs::resize_file(big, (std::uintmax_t{16} << 20) + 1);  // sparse: refused by its size, unread
  EXPECT_EQ(load_error(big), "the file is 16777217 bytes, above the limit of 16777216 bytes");
}

TEST(SceneLimits, MaterialLibrariesAreNeverRead) {
  // mtllib /dev/zero read 2 GB (bad_alloc); a FIFO blocked forever.
  const fs::path fifo = scene_scratch() / "fifo.mtl";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& lib : {std::string("/dev/zero"), fifo.string()}) {
    const auto path = mesh_scene("mtllib", "mtllib " + lib + "\nusemtl wood\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(load_error(path), "") << lib;
  }
}

TEST(SceneLimits, MeshFilesMustBeRegularAndWithinTheirLimit) {
  const fs::path fifo = scene_scratch() / "fifo.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto path = write_scene("fifo_mesh.json", R"({"probes": [[0, 5, 0]], "effects": [],
    "geometry": [{"type": "mesh", "path": "fifo.obj"}]})");
  EXPECT_EQ(load_error(path), "geometry[0].path: " + fifo.string() + ": is not a regular file");
  const auto big = mesh_scene("big_mesh", "v 0 0 0\n");
  fs::resize_file(scene_scratch() / "big_mesh.obj", (std::uintmax_t{256} << 20) + 1);
  EXPECT_EQ(load_error(big), "geometry[0].path: " + (scene_scratch() / "big_mesh.obj").string() +
                                 ": the file is 268435457 bytes, above the limit of 268435456 bytes");
}

TEST(SceneLimits, ObjIndicesOutOfRangeNameTheLine) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const struct {
    const char* name;
    std::string obj;
    std::string problem;
  } cases[] = {
      {"past_the_end", triangle + "f 1 2 3\n# note\nf 1 2 7\n",
       "line 6: vertex index 7 is out of range (the file has 3 vertices)"},
      {"before_the_first", triangle + "f -1 -2 -4\n", "line 4: vertex index -4 is out of range (3 vertices so far)"},
      {"zero", triangle + "f 0 1 2\n", "line 4: vertex index 0 (indices count from 1)"},
      {"huge", triangle + "f 1 2 99999999999999999999\n", "line 4: vertex index '99999999999999999999' is out of range"},
      {"two_vertices", triangle + "f 1 2\n", "line 4: a face needs at least 3 vertices"},
      {"not_an_index", triangle + "f 1 2 x/1\n", "line 4: 'x/1' is not a vertex reference"},
      {"short_vertex", "v 0 0\n", "line 1: a vertex needs x, y and z"},
      {"bad_number", "v 0 0 1..5\n", "line 1: '1..5' is not a number"},
      {"infinite", "v 0 0 1e999\n", "line 1: '1e999' is not a finite double"},
      {"no_faces", triangle, "no faces"},
  };
  for (const auto& c : cases) {
    const auto path = mesh_scene(c.name, c.obj);
    EXPECT_EQ(load_error(path), "geometry[0].path: " + (scene_scratch() / (std::string(c.name) + ".obj")).string() +
                                    ": " + c.problem)
        << c.name;
  }
}

TEST(SceneLimits, ObjFacesAreTriangulatedAndMayReferForward) {
  // A quad split along its shorter diagonal (1-3 here), a pentagon as a fan, a face before
  // its vertices, comments, normals and texture references, CRLF line ends.
  detail::ObjMesh mesh;
  std::string error;
  ASSERT_TRUE(detail::parse_obj("f 1/1/1 2//1 3/2 4 # quad\r\nv 0 0 0\r\nv 2 0 0\r\nv 2 0 2\r\nv 0 0 1\r\n"
                                "vn 0 1 0\nvt 0 0\no thing\ns off\nv +1 -0.5 1e-1 1\nf -5 -4 -3 -2 -1\n",
                                1e18, mesh, error))
      << error;
  ASSERT_EQ(mesh.vertices.size(), 15u);
  EXPECT_EQ(mesh.vertices[13], -0.5);
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3, 0, 1, 2, 0, 2, 3, 0, 3, 4}));
}

TEST(SceneLimits, GeometryBeyondTheRayTracersRangeIsRefused) {
  const auto scene = [](const std::string& name, const std::string& shape) {
    return write_scene(name + ".json", R"({"probes": [[0, 5, 0]], "effects": [], "geometry": [)" + shape + "]}");
  };
  // Embree skips primitives with a coordinate beyond 1.844e18: the plane was silently lost.
  EXPECT_EQ(load_error(scene("huge_plane", R"({"type": "plane", "position": [0, 0, 0], "right": [1, 0, 0],
              "up": [0, 0, 1], "size": [1e20, 1]})")),
            "geometry[0].size: 1e+20 puts vertices beyond 1.844e+18, the ray tracer's range");
  EXPECT_EQ(load_error(scene("far_plane", R"({"type": "plane", "position": [0, -1e19, 0], "right": [1, 0, 0],
              "up": [0, 0, 1], "size": [1, 1]})")),
            "geometry[0].position[1]: -1e+19 is beyond 1.844e+18, the ray tracer's range");
  EXPECT_EQ(load_error(scene("far_box", R"({"type": "box", "min": [-1e300, 0, 0], "max": [1, 1, 1]})")),
            "geometry[0].min[0]: -1e+300 is beyond 1.844e+18, the ray tracer's range");
  EXPECT_EQ(load_error(scene("huge_sphere", R"({"type": "sphere", "position": [0, 0, 0], "radius": 1e19})")),
            "geometry[0].radius: 1e+19 puts the sphere beyond 1.844e+18, the ray tracer's range");
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  EXPECT_EQ(load_error(mesh_scene("scaled", triangle, R"(, "scale": 1e30)")),
            "geometry[0].scale: 1e+30 puts vertices beyond 1.844e+18, the ray tracer's range");
  EXPECT_EQ(load_error(mesh_scene("moved", triangle, R"(, "position": [1.8e18, 0, 0], "scale": 1e17)")),
            "geometry[0].position: 1.8e+18 puts vertices beyond 1.844e+18, the ray tracer's range");
  EXPECT_EQ(load_error(mesh_scene("far_vertex", "v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")),
            "geometry[0].path: " + (scene_scratch() / "far_vertex.obj").string() +
                ": line 1: 1e+39 is beyond 1.844e+18, the ray tracer's range");
}

TEST(SceneLimits, ProbeListsAreCappedLikeGrids) {
  std::string probes;
  probes.reserve(8'000'100);
  for (int k = 0; k <= 1'000'000; ++k) probes += k ? ",[0,0,0]" : "[0,0,0]";
  EXPECT_EQ(load_error(write_scene("many_probes.json", R"({"effects": [], "probes": [)" + probes + "]}")),
            "probes: more than 1000000 probes");
  EXPECT_EQ(load_error(write_scene("big_grid.json",
                                   R"({"effects": [], "probes": {"min": [0, 0, 0], "max": [1, 1, 1],
                                       "counts": [1000, 1000, 2]}})")),
            "probes.counts: more than 1000000 probes");
}

TEST(SceneLimits, LongEffectListsAreRefusedBeforeTheQuadraticUniquenessCheck) {
  std::string effects;
  for (int k = 0; k < 20000; ++k) effects += (k ? ", \"x" : "\"x") + std::to_string(k) + "\"";
  EXPECT_EQ(load_error(write_scene("many_effects.json", R"({"probes": [[0, 0, 0]], "effects": [)" + effects + "]}")),
            "effects: more than 64 effects");
}

TEST(SceneLimits, SeedsCoverAllOf64Bits) {
  const auto seeded = [](const std::string& name, const std::string& seed) {
    return write_scene(name + ".json", R"({"probes": [[0, 0, 0]], "effects": [], "settings": {"seed": )" + seed +
                                           ", \"shadow_samples\": 4}}");
  };
  for (const std::string seed : {"0", "9223372036854775808", "18446744073709551615"}) {
    Scene scene;
    const io::IoStatus st = load_scene(seeded("seed_ok", seed), scene);
    ASSERT_TRUE(st.ok()) << seed << ": " << st.message;
    EXPECT_EQ(std::to_string(scene.settings.seed), seed);
    EXPECT_EQ(scene.settings.shadow_samples, 4);
  }
  for (const std::string seed : {"18446744073709551616", "-1", "1.5", "1e300"})
    EXPECT_EQ(load_error(seeded("seed_bad", seed)), "settings.seed: must be an integer from 0 to 18446744073709551615")
        << seed;
  EXPECT_EQ(load_error(seeded("seed_text", "\"7\"")), "settings.seed: has the wrong type");
}

}  // namespace
}  // namespace shpack::scene
