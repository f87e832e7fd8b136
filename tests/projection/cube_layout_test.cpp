// Tests of cube_layout.h (six faces as views of one image) and of the cube frames of
// conventions.h (CubeFrame): every cell and its orientation, pinned texel by texel.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/cube_layout.h"
#include "shpack/project_cube.h"
#include "shpack/sh_basis.h"
#include "support/test_util.h"

namespace shpack {
namespace {

constexpr std::array<CubeLayout, 4> kLayouts = {CubeLayout::HorizontalCross, CubeLayout::VerticalCross,
                                                CubeLayout::HorizontalStrip, CubeLayout::VerticalStrip};
const char* name(CubeLayout l) {
  switch (l) {
    case CubeLayout::HorizontalCross: return "hcross";
    case CubeLayout::VerticalCross: return "vcross";
    case CubeLayout::HorizontalStrip: return "hstrip";
    case CubeLayout::VerticalStrip: return "vstrip";
  }
  return "?";
}

// docs/conventions.md's table, written out again: the cell (column, row) of each face in
// CubeFace order, and whether the face is stored rotated by 180 degrees.
struct Expected {
  std::uint32_t columns, rows;
  std::array<std::array<std::uint32_t, 2>, 6> cell;
  std::array<bool, 6> rotated;
};
Expected expected(CubeLayout l) {
  switch (l) {
    case CubeLayout::HorizontalCross:
      return {4, 3, {{{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}}}, {}};
    case CubeLayout::VerticalCross:
      return {3, 4, {{{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {1, 3}}}, {false, false, false, false, false, true}};
    case CubeLayout::HorizontalStrip:
      return {6, 1, {{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}}}, {}};
    case CubeLayout::VerticalStrip:
      return {1, 6, {{{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5}}}, {}};
  }
  return {};
}

struct Image {
  std::uint32_t width, height;
  std::vector<float> rgb;
  Image(std::uint32_t w, std::uint32_t h) : width(w), height(h), rgb(std::size_t{3} * w * h, 0.0f) {}
  float* at(std::uint32_t x, std::uint32_t y) { return rgb.data() + 3 * (std::size_t{y} * width + x); }
  ImageView view() const { return make_view(rgb.data(), width, height, 3); }
};

TEST(CubeLayout, EveryFaceTexelIsAViewOfItsCell) {
  // Each image texel holds its own index; each face texel must read the index of the image
  // texel the table names (the -Z face of the vertical cross: (N-1-x, N-1-y) of its cell).
  const std::uint32_t n = 3;
  for (const CubeLayout layout : kLayouts) {
    const Expected e = expected(layout);
    Image image(e.columns * n, e.rows * n);
    for (std::uint32_t y = 0; y < image.height; ++y)
      for (std::uint32_t x = 0; x < image.width; ++x) image.at(x, y)[0] = static_cast<float>(y * image.width + x);
    std::array<ImageView, kCubeFaceCount> faces;
    ASSERT_TRUE(cube_face_views(image.view(), layout, faces).ok()) << name(layout);
    for (int f = 0; f < kCubeFaceCount; ++f) {
      EXPECT_EQ(faces[f].width, n);
      EXPECT_EQ(faces[f].height, n);
      const CubeCell cell = cube_layout_cell(layout, static_cast<CubeFace>(f));
      EXPECT_EQ(cell.column, e.cell[f][0]) << name(layout) << " face " << f;
      EXPECT_EQ(cell.row, e.cell[f][1]) << name(layout) << " face " << f;
      EXPECT_EQ(cell.rotated_180, e.rotated[f]) << name(layout) << " face " << f;
      for (std::uint32_t y = 0; y < n; ++y) {
        for (std::uint32_t x = 0; x < n; ++x) {
          const std::uint32_t ix = e.cell[f][0] * n + (e.rotated[f] ? n - 1 - x : x);
          const std::uint32_t iy = e.cell[f][1] * n + (e.rotated[f] ? n - 1 - y : y);
          float got;
          std::memcpy(&got, faces[f].pixel(x, y), sizeof got);
          EXPECT_EQ(got, static_cast<float>(iy * image.width + ix))
              << name(layout) << " face " << f << " texel (" << x << ", " << y << ")";
        }
      }
    }
  }
}

// cube_layout.h promises views, not copies: every texel of every face (its first and last
// pixel bound the rest, strides being constant) lies in the caller's buffer; the vertical
// cross's -Z face, stored rotated by 180 degrees, runs backwards along both axes (negative
// pixel and row strides), and every other face forwards.
TEST(CubeLayout, FacesAliasTheImageAndTheFlippedFaceRunsBackwards) {
  const std::uint32_t n = 3;
  for (const CubeLayout layout : kLayouts) {
    const Expected e = expected(layout);
    const Image image(e.columns * n, e.rows * n);
    const auto* begin = reinterpret_cast<const std::byte*>(image.rgb.data());
    const auto* end = reinterpret_cast<const std::byte*>(image.rgb.data() + image.rgb.size());
    std::array<ImageView, kCubeFaceCount> faces;
    ASSERT_TRUE(cube_face_views(image.view(), layout, faces).ok()) << name(layout);
    for (int f = 0; f < kCubeFaceCount; ++f) {
      for (const std::byte* p : {faces[f].data, faces[f].pixel(n - 1, n - 1)}) {
        EXPECT_TRUE(p >= begin && p + 3 * sizeof(float) <= end) << name(layout) << " face " << f;
      }
      const bool backwards = layout == CubeLayout::VerticalCross && static_cast<CubeFace>(f) == CubeFace::NegZ;
      EXPECT_EQ(faces[f].pixel_stride < 0, backwards) << name(layout) << " face " << f;
      EXPECT_EQ(faces[f].row_stride < 0, backwards) << name(layout) << " face " << f;
    }
  }
}

// The unit direction of the first moment of an SH's L1 part (channel 0).
Dir3 l1_direction(const ShL2& sh) {
  const double r = std::hypot(sh.c[0][1], sh.c[0][2], sh.c[0][3]);
  return {sh.c[0][3] / r, sh.c[0][1] / r, sh.c[0][2] / r};
}

Dir3 corner_direction(int face, double a, double b) {
  const CubeFaceAxes& f = kCubeFaceAxes[face];
  const Dir3 p{f.normal.x + a * f.u_axis.x + b * f.v_axis.x, f.normal.y + a * f.u_axis.y + b * f.v_axis.y,
               f.normal.z + a * f.u_axis.z + b * f.v_axis.z};
  const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  return {p.x / r, p.y / r, p.z / r};
}

TEST(CubeLayout, BrightTexelPinsTheFaceAndWhichCornerIsUp) {
  // A bright texel in each face's top-left texel, as the face sees it (a = b = -1 + 1/N):
  // the projection through the layout's views equals the cube texel's own integrals, and
  // points towards normal - U - V (the top-left corner of the face table), so the face and
  // its orientation in the image are both pinned. N = 4.
  const std::uint32_t n = 4;
  for (const CubeLayout layout : kLayouts) {
    const Expected e = expected(layout);
    for (int f = 0; f < kCubeFaceCount; ++f) {
      Image image(e.columns * n, e.rows * n);
      const std::uint32_t ix = e.cell[f][0] * n + (e.rotated[f] ? n - 1 : 0);
      const std::uint32_t iy = e.cell[f][1] * n + (e.rotated[f] ? n - 1 : 0);
      image.at(ix, iy)[0] = image.at(ix, iy)[1] = image.at(ix, iy)[2] = 1.0f;
      std::array<ImageView, kCubeFaceCount> faces;
      ASSERT_TRUE(cube_face_views(image.view(), layout, faces).ok());
      ShL2 sh;
      ASSERT_TRUE(project_cube(faces, {}, sh).ok());
      std::array<double, kShCount> want{};
      ASSERT_TRUE(cube_texel_basis_integrals(n, static_cast<CubeFace>(f), 0, 0, SamplingMethod::Exact, want).ok());
      for (int i = 0; i < kShCount; ++i) EXPECT_EQ(sh.c[0][i], want[i]) << name(layout) << " face " << f << " i=" << i;
      const Dir3 got = l1_direction(sh), corner = corner_direction(f, -1.0 + 1.0 / n, -1.0 + 1.0 / n);
      EXPECT_GT(got.x * corner.x + got.y * corner.y + got.z * corner.z, 0.999)
          << name(layout) << " face " << f << ": " << got << " vs " << corner;
    }
  }
}

TEST(CubeLayout, WrongShapesAreRefused) {
  std::array<ImageView, kCubeFaceCount> faces;
  const std::vector<std::array<std::uint32_t, 2>> bad = {{13, 9}, {12, 10}, {4, 4}, {6, 2}, {2, 6}};
  for (const CubeLayout layout : kLayouts) {
    for (const auto& size : bad) {
      Image image(size[0], size[1]);
      EXPECT_EQ(cube_face_views(image.view(), layout, faces).code, Errc::InvalidArgument)
          << name(layout) << " " << size[0] << "x" << size[1];
    }
  }
}

TEST(CubeLayout, OneTexelIsAUniformEnvironment) {
  Image image(1, 1);
  image.at(0, 0)[0] = 2.0f;
  for (const CubeLayout layout : kLayouts) {
    std::array<ImageView, kCubeFaceCount> faces;
    ASSERT_TRUE(cube_face_views(image.view(), layout, faces).ok()) << name(layout);
    ShL2 sh;
    ASSERT_TRUE(project_cube(faces, {}, sh).ok());
    // L00 = 2 sqrt(pi) * 2; the cube's six exact faces sum to 4 pi within a few ulp.
    EXPECT_NEAR(sh.c[0][0], 4.0 * std::sqrt(std::numbers::pi), 1e-14) << name(layout);
    for (int i = 1; i < kShCount; ++i) EXPECT_NEAR(sh.c[0][i], 0.0, 1e-14) << name(layout) << " i=" << i;
  }
}

TEST(CubeFrame, SignsAreThoseOfTheDirectionMap) {
  // P_i(M d) = sign_i P_i(d) for the frame's map M, at random directions.
  std::mt19937_64 rng(0x5eed);
  std::normal_distribution<double> g;
  for (const CubeFrame frame : {CubeFrame::Unity, CubeFrame::Gl, CubeFrame::ThreeJs}) {
    for (int k = 0; k < 20; ++k) {
      Dir3 d{g(rng), g(rng), g(rng)};
      const Dir3 m = cube_frame_to_unity(frame, d);
      const auto before = basis_polynomials(d.x, d.y, d.z), after = basis_polynomials(m.x, m.y, m.z);
      for (int i = 0; i < kShCount; ++i)
        EXPECT_EQ(after[i], cube_frame_sign(frame)[i] * before[i]) << "frame " << static_cast<int>(frame) << " i=" << i;
    }
  }
}

TEST(CubeFrame, MarkersLandWhereTheConventionsSay) {
  // docs/conventions.md: gl faces show d at Unity's (d.x, d.y, -d.z); three.js faces at
  // (-d.x, d.y, -d.z). A bright texel at the centre of the +Z face (as the table reads it)
  // lands at -Z for gl and three.js; one at the centre of +X lands at +X (gl) and -X (three.js);
  // the +Z face's top-left texel (towards -x, +y) lands towards (-x, +y, -z) for gl and
  // (+x, +y, -z) for three.js.
  const std::uint32_t n = 4;
  struct Marker {
    int face;
    std::uint32_t x, y;
    CubeFrame frame;
    Dir3 want_sign;  // the signs of the landing direction's components (0: about zero)
  };
  const std::vector<Marker> markers = {
      {4, 1, 1, CubeFrame::Unity, {-1, 1, 1}}, {4, 1, 1, CubeFrame::Gl, {-1, 1, -1}},
      {4, 1, 1, CubeFrame::ThreeJs, {1, 1, -1}}, {0, 2, 2, CubeFrame::Gl, {1, -1, 1}},
      {0, 2, 2, CubeFrame::ThreeJs, {-1, -1, 1}},
  };
  for (const Marker& m : markers) {
    std::array<double, kShCount> y{};
    ASSERT_TRUE(cube_texel_basis_integrals(n, static_cast<CubeFace>(m.face), m.x, m.y, SamplingMethod::Exact, y).ok());
    ShL2 sh;
    for (int i = 0; i < kShCount; ++i) sh.c[0][i] = cube_frame_sign(m.frame)[i] * y[i];
    const Dir3 d = l1_direction(sh);
    const double got[3] = {d.x, d.y, d.z}, want[3] = {m.want_sign.x, m.want_sign.y, m.want_sign.z};
    for (int k = 0; k < 3; ++k)
      EXPECT_GT(got[k] * want[k], 0.05) << "face " << m.face << " (" << m.x << ", " << m.y << ") frame "
                                        << static_cast<int>(m.frame) << " lands at " << d;
  }
}

}  // namespace
}  // namespace shpack
