// Tests of the OBJ reader's texture coordinates (lib/scene/src/obj_mesh.h, parse_obj with
// with_uv): vertices split per distinct (vertex, texture) pair, a missing texture index or
// no `vt` at all reported without failing, bad texture indices and `vt` lines refused by
// line, and nothing of it looked at without with_uv. Values are copied: asserted exactly.
// (The glTF reader's TEXCOORD_1 and NORMAL are tested in gltf_test.cpp.)
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "obj_mesh.h"

namespace shpack::scene::detail {
namespace {

constexpr double kMaxAbs = 1e18;

ObjMesh parse_uv(const std::string& text) {
  ObjMesh mesh;
  std::string error;
  EXPECT_TRUE(parse_obj(text, kMaxAbs, mesh, error, /*with_uv=*/true)) << error;
  return mesh;
}

std::string uv_error(const std::string& text) {
  ObjMesh mesh;
  std::string error;
  EXPECT_FALSE(parse_obj(text, kMaxAbs, mesh, error, /*with_uv=*/true));
  return error;
}

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";  // lines 1-4

TEST(ObjUv, SharedPositionsWithDistinctUvsBecomeDistinctVertices) {
  const std::string text = kSquare +
                           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1 0.5\n"  // lines 5-8 (a third number ignored)
                           "vt 0.5 -0.25\n"                       // line 9: vt 5, for position 1 again
                           "f 1/1 2/2 3/3\n"                      // the first use of each pair
                           "f 1/1/1 3/3/1 4/4/1\n"                // (1,1) and (3,3) again: shared
                           "f -4/-1 2/2 4/-2\n";                  // (1,5) new; (4,4) shared
  const ObjMesh m = parse_uv(text);
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 0}));
  EXPECT_EQ(m.uv, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1, 0.5, -0.25}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 4, 1, 3}));
  EXPECT_EQ(m.uv_missing_line, 0u);
  // Without with_uv: the positions as written, the same faces.
  ObjMesh plain;
  std::string error;
  ASSERT_TRUE(parse_obj(text, kMaxAbs, plain, error)) << error;
  EXPECT_EQ(plain.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));
  EXPECT_EQ(plain.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 1, 3}));
  EXPECT_TRUE(plain.uv.empty());
}

TEST(ObjUv, QuadsAreSplitByTheirPositionsAndForwardTextureIndicesAreRead) {
  // The quad's diagonal 2-4 is shorter (positions), so it splits along it; its texture
  // coordinates come after it, and a vt with only u has v 0.
  const ObjMesh m = parse_uv("f 1/4 2/3 3/2 4/1\nv 0 0 0\nv 2 0 0\nv 2 0 2\nv 0 0 1\nvt 0.125\nvt 0.25 1\nvt 0.5 1\nvt 1 1\n");
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 2, 0, 0, 2, 0, 2, 0, 0, 1}));
  EXPECT_EQ(m.uv, (std::vector<double>{1, 1, 0.5, 1, 0.25, 1, 0.125, 0}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3}));
}

TEST(ObjUv, AReferenceWithoutATextureIndexOrNoVtLeavesUvEmpty) {
  // Line 7's `3` and line 8's `4//1` lack texture indices: the first such line is reported.
  const std::string text = kSquare + "vt 0 0\nf 1/1 2/1 3/1\nf 1/1 3 4//1\nf 1//1 3 4\n";
  const ObjMesh m = parse_uv(text);
  EXPECT_TRUE(m.uv.empty());
  EXPECT_EQ(m.uv_missing_line, 7u);
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));  // as written
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 2, 3}));
  // No vt at all: uv empty, line 0, texture indices not checked.
  const ObjMesh none = parse_uv(kSquare + "f 1/1 2/2 3/9\n");
  EXPECT_TRUE(none.uv.empty());
  EXPECT_EQ(none.uv_missing_line, 0u);
  EXPECT_EQ(none.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(ObjUv, BadTextureIndicesAndVtLinesAreRefusedByLine) {
  const std::string vt = kSquare + "vt 0 0\nvt 1 0\n";  // lines 5-6
  EXPECT_EQ(uv_error(vt + "f 1/1 2/2 3/3\nvt 1 1\nf 1/9 2/2 3/1\n"),
            "line 9: texture index 9 is out of range (the file has 3 texture coordinates)");
  EXPECT_EQ(uv_error(vt + "f 1/-3 2/1 3/2\nvt 1 1\n"), "line 7: texture index -3 is out of range (2 texture coordinates so far)");
  EXPECT_EQ(uv_error(vt + "f 1/0 2/1 3/2\n"), "line 7: texture index 0 (indices count from 1)");
  EXPECT_EQ(uv_error(vt + "f 1/x 2/1 3/2\n"), "line 7: '1/x' is not a vertex reference");
  EXPECT_EQ(uv_error(vt + "f 1/99999999999999999999 2/1 3/2\n"), "line 7: texture index '99999999999999999999' is out of range");
  EXPECT_EQ(uv_error(kSquare + "vt 0 nan\nf 1/1 2/1 3/1\n"), "line 5: 'nan' is not a finite double");
  EXPECT_EQ(uv_error(kSquare + "vt 0 1e999\nf 1/1 2/1 3/1\n"), "line 5: '1e999' is not a finite double");
  EXPECT_EQ(uv_error(kSquare + "vt u v\nf 1/1 2/1 3/1\n"), "line 5: 'u' is not a number");
  EXPECT_EQ(uv_error(kSquare + "vt\nf 1/1 2/1 3/1\n"), "line 5: a texture coordinate needs u (and v)");
  // A vertex index is still checked first, as without with_uv.
  EXPECT_EQ(uv_error(vt + "f 1/1 2/1 9/2\n"), "line 7: vertex index 9 is out of range (the file has 4 vertices)");
  // Without with_uv none of this is looked at.
  for (const std::string& text : {vt + "f 1/9 2/2 3/3\n", vt + "f 1/x 2/1 3/2\n", kSquare + "vt u v\nf 1/1 2/1 3/1\n"}) {
    ObjMesh m;
    std::string error;
    EXPECT_TRUE(parse_obj(text, kMaxAbs, m, error)) << text << error;
    EXPECT_TRUE(m.uv.empty());
  }
}

}  // namespace
}  // namespace shpack::scene::detail
