// Tests of the loader's triangle winding: each triangle's normal (v1 - v0) x (v2 - v0), its
// front side for the ray tracer (lib/bake/src/tracer.h), points out of a box, towards
// right x up for a plane, and out of a closed mesh written counter-clockwise, mirrored or not.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "scene_files.h"
#include "shpack/scene/scene_loader.h"

namespace shpack::scene {
namespace {

using V = std::array<double, 3>;

V vertex(const SceneShape& s, std::uint32_t i) {
  return {s.vertices[3 * i], s.vertices[3 * i + 1], s.vertices[3 * i + 2]};
}

// For every triangle: the normal's dot product with (its centroid - centre), which is > 0
// when it faces away from `centre`.
void expect_facing_away(const SceneShape& s, const V& centre, const std::string& what) {
  ASSERT_FALSE(s.indices.empty()) << what;
  for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3) {
    const V a = vertex(s, s.indices[t]), b = vertex(s, s.indices[t + 1]), c = vertex(s, s.indices[t + 2]);
    const V e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const V n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    double out = 0;
    for (int k = 0; k < 3; ++k) out += n[k] * ((a[k] + b[k] + c[k]) / 3 - centre[k]);
    EXPECT_GT(out, 0.0) << what << ": triangle " << t / 3;
  }
}

Scene load(const std::string& name, const std::string& geometry) {
  Scene scene;
  const io::IoStatus st = load_scene(
      shpack_test::write_scene(name + ".json", R"({"probes": [[0, 0, 0]], "effects": [], "geometry": )" + geometry + "}"),
      scene);
  EXPECT_TRUE(st.ok()) << st.message;
  return scene;
}

TEST(SceneWinding, BoxesFaceOutPlanesFaceRightCrossUpMeshesKeepTheirFileFront) {
  const Scene box = load("box_winding", R"([{"type": "box", "min": [1, 2, 3], "max": [2, 4, 7]}])");
  expect_facing_away(box.geometry.at(0), {1.5, 3, 5}, "box");
  // right = +X, up = +Z: right x up = -Y, so the front is below.
  const Scene plane = load("plane_winding", R"([{"type": "plane", "position": [0, 1, 0], "right": [1, 0, 0],
    "up": [0, 0, 1], "size": [2, 2]}])");
  expect_facing_away(plane.geometry.at(0), {0, 2, 0}, "plane");
  // A tetrahedron written counter-clockwise seen from outside (right-handed file).
  shpack_test::write_scene("tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const V centroid{0.25, 0.25, 0.25};
  expect_facing_away(load("tetra", R"([{"type": "mesh", "path": "tetra.obj"}])").geometry.at(0), centroid, "obj");
  expect_facing_away(load("tetra_mirrored", R"([{"type": "mesh", "path": "tetra.obj", "mirror_z": true}])").geometry.at(0),
                     {0.25, 0.25, -0.25}, "obj mirrored");
}

}  // namespace
}  // namespace shpack::scene
