// Tests of the OBJ reader's texture coordinates and normals (lib/scene/src/obj_mesh.h,
// parse_obj with with_uv): vertices split per distinct (vertex, texture, normal) corner, a
// missing texture index or no `vt` at all reported without failing, normals only when every
// corner has one, bad indices and `vt` / `vn` lines refused by line, and nothing of it looked
// at without with_uv. Values are copied: asserted exactly.
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

TEST(ObjUv, NormalsOnEveryCornerSplitVerticesPerCorner) {
  // Corner (1, 1, 2) shares position 1 and texture 1 with (1, 1, 1) but not its normal: a
  // vertex of its own; (3, 3, 2) is shared.
  const std::string text = kSquare + "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nvn 0 0 2\n"
                                     "f 1/1/1 2/2/1 3/3/2\nf 1/1/2 3/3/2 4/1/1\n";
  const ObjMesh m = parse_uv(text);
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0, 1, 0}));
  EXPECT_EQ(m.uv, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 0, 0, 0}));
  EXPECT_EQ(m.normals, (std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, 2, 0, 0, 2, 0, 0, 1}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 2, 4}));
  // One corner without a normal index: no normals, vertices per (vertex, texture) pair.
  const ObjMesh some = parse_uv(kSquare + "vt 0 0\nvt 1 0\nvn 0 0 1\nf 1/1/1 2/2 3/1/1\nf 1/1/1 3/1 4/2/1\n");
  EXPECT_TRUE(some.normals.empty());
  EXPECT_EQ(some.uv, (std::vector<double>{0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(some.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  // Normal indices but no vn: not checked, no normals.
  EXPECT_TRUE(parse_uv(kSquare + "vt 0 0\nf 1/1/7 2/1/7 3/1/7\n").normals.empty());
}

TEST(ObjUv, BadNormalIndicesAndVnLinesAreRefusedByLine) {
  const std::string vn = kSquare + "vt 0 0\nvn 0 1 0\nvn 1 0 0\n";  // lines 5-7
  EXPECT_EQ(uv_error(vn + "f 1/1/1 2/1/9 3/1/2\n"), "line 8: normal index 9 is out of range (the file has 2 normals)");
  EXPECT_EQ(uv_error(vn + "f 1/1/-3 2/1/1 3/1/2\n"), "line 8: normal index -3 is out of range (2 normals so far)");
  EXPECT_EQ(uv_error(vn + "f 1/1/0 2/1/1 3/1/2\n"), "line 8: normal index 0 (indices count from 1)");
  EXPECT_EQ(uv_error(vn + "f 1/1/x 2/1/1 3/1/2\n"), "line 8: '1/1/x' is not a vertex reference");
  EXPECT_EQ(uv_error(vn + "f 1/1/1/1 2/1/1 3/1/2\n"), "line 8: '1/1/1/1' is not a vertex reference");
  EXPECT_EQ(uv_error(kSquare + "vt 0 0\nvn 0 nan 1\nf 1/1/1 2/1/1 3/1/1\n"), "line 6: 'nan' is not a finite double");
  EXPECT_EQ(uv_error(kSquare + "vt 0 0\nvn 0 1\nf 1/1/1 2/1/1 3/1/1\n"), "line 6: a normal needs x, y and z");
  // Without with_uv normals are not looked at.
  ObjMesh m;
  std::string error;
  EXPECT_TRUE(parse_obj(vn + "f 1/1/9 2/1/x 3/1/2\n", kMaxAbs, m, error)) << error;
  EXPECT_TRUE(m.normals.empty());
}

}  // namespace
}  // namespace shpack::scene::detail
