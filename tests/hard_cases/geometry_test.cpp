// geometry_test.cpp - the geometry of texels where it is hardest: pole rows (solid angles
// without cancellation), cube edges and corners, and the solid angles of every layout that
// exists summing to 4 pi to 1e-12 (equirect at every size up to 16384 x 8192, cubes up to
// N = 1000, the single-image cube layouts of docs/conventions.md cut as views by hand and by
// cube_layout.h, and the sphere maps of project_sphere_map.h; add each new io layout to
// LayoutsThroughTheCommandSumTo4Pi in cli_hard_cases_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "hard_cases/checks.h"
#include "hard_cases/hard_case_support.h"
#include "shpack/project.h"
#include "shpack/cube_layout.h"
#include "shpack/project_cube.h"
#include "shpack/project_sphere_map.h"
#include "support/test_util.h"

namespace shpack_hard {
namespace {

using shpack_test::describe;
constexpr double kFourPi = 4 * std::numbers::pi;
constexpr double kTargetRel = 1e-12;  // the hard cases' target: every layout sums to 4 pi to 1e-12

// The solid angle of row j of a 1 x H image, exactly 2 pi (cos theta0 - cos theta1), in
// long double and without cancellation: rows mirrored across the equator have equal solid
// angles, so it is computed for the northern one, j' = min(j, H-1-j), whose angles are
// accurate relative to their size, as 4 pi sin(pi (j' + 1/2) / H) sin(pi / 2H).
long double row_solid_angle(std::uint32_t j, std::uint32_t h) {
  const long double pi = std::numbers::pi_v<long double>;
  const std::uint32_t north = std::min(j, h - 1 - j);
  return 4 * pi * std::sin(pi * (north + 0.5L) / h) * std::sin(pi / (2.0L * h));
}

// |shpack's solid angle of row j of a 1 x H image - exact| / exact: L00 / k0 of the image
// that is 1 in that row only.
double row_solid_angle_error(std::uint32_t j, std::uint32_t h) {
  std::vector<float> rgb(std::size_t{3} * h, 0.0f);
  for (int c = 0; c < 3; ++c) rgb[std::size_t{3} * j + c] = 1.0f;
  ShL2 sh;
  EXPECT_TRUE(shpack::project_equirect(shpack::make_view(rgb.data(), 1, h, 3), {}, sh).ok());
  const long double want = row_solid_angle(j, h);
  return static_cast<double>(std::fabs(sh.c[0][0] / shpack::kY0 - want) / want);
}

// Tolerance of a row's solid angle: shpack's weight is 2 sin(theta_c) sin(h) dlon
// (equirect_weights.cpp), a few correctly rounded factors, <= 8u; k0 and the division by
// kY0 add 3u: 16u relative. The textbook 1 - cos(pi/H) loses ~u / (1 - cos) ~ 2 H^2 u / pi^2
// relative (1.5e-6 at H = 2^18), and a sin(theta_c) taken of a theta_c rounded near pi loses
// u pi / (pi / 2H) = 2 H u (1e-10 at H = 2^18).
constexpr double kRowRel = 16 * kU;

TEST(Geometry, PoleRowSolidAnglesHaveNoCancellation) {
  // The north pole row and its neighbour, up to H = 10^6 (the south pole row:
  // SouthPoleRowSolidAnglesRegression below).
  for (std::uint32_t h : {1u << 10, 1u << 18, 1000003u}) {
    for (std::uint32_t row : {0u, 1u, h / 2}) {
      const double rel = row_solid_angle_error(row, h);
      EXPECT_LE(rel, kRowRel) << "H=" << h << " row=" << row;
      if (row == 0) {
        const long double want = row_solid_angle(0, h);
        const double naive = 2 * std::numbers::pi * (1.0 - std::cos(std::numbers::pi / h));
        const double naive_rel = static_cast<double>(std::fabs(naive - want) / want);
        std::cout << "[ measure  ] north pole row H=" << h << ": relative error " << rel << " (tol " << kRowRel
                  << "); 1 - cos form: " << naive_rel << "\n";
        if (h >= (1u << 18)) {
          EXPECT_GT(naive_rel, 1000 * kRowRel) << "the cancelling form must be visibly worse";
        }
      }
    }
  }
}

// Regression for a bug this test found: lib/src/projection/equirect_weights.cpp took sin
// and cos of theta ~ pi in double near the south pole, where theta carries an absolute
// rounding error of ~u pi, so sin(theta_c) was off by a relative ~2 H u: the south pole
// row's solid angle (and every basis integral of its texels) was off by 1.8e-13 at H =
// 1024, 1.8e-12 at H = 8192, 5.6e-11 at H = 2^18. Southern rows are now mirror images of
// northern ones.
TEST(Geometry, SouthPoleRowSolidAnglesRegression) {
  for (std::uint32_t h : {1u << 10, 8192u, 1u << 18, 1000003u})
    for (std::uint32_t row : {h - 1, h - 2})
      EXPECT_LE(row_solid_angle_error(row, h), kRowRel) << "H=" << h << " row=" << row;
  // And all nine integrals of the south pole texels of a 3 x 65536 image (as
  // PoleTexelsOfWideImagesMatchTheOracle does for the north).
  const std::uint32_t w = 3, h = 65536;
  const EquirectOracle oracle(w, h);
  std::vector<float> rgb(std::size_t{3} * w * h, 0.0f);
  for (std::uint32_t i = 0; i < w; ++i) {
    std::fill(rgb.begin(), rgb.end(), 0.0f);
    for (int c = 0; c < 3; ++c) rgb[(std::size_t{h - 1} * w + i) * 3 + c] = 1.0f;
    ShL2 sh;
    ASSERT_TRUE(shpack::project_equirect(shpack::make_view(rgb.data(), w, h, 3), {}, sh).ok());
    const std::array<long double, 10> t = oracle.texel(i, h - 1);
    ShLd want{};
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 9; ++k) want[c][k] = t[k];
    expect_within(sh, want, relative_to_norm(want, kTargetRel), "south pole texel i=" + std::to_string(i));
  }
}

TEST(Geometry, PoleTexelsOfWideImagesMatchTheOracle) {
  // All nine integrals of pole and near-pole texels (tiny, thin slivers) against the
  // long-double oracle, 1e-12 of the coefficient norm (a lone texel: see suns_test.cpp).
  for (auto [w, h] : {std::pair<std::uint32_t, std::uint32_t>{8192, 4}, {16384, 2}, {3, 65536}}) {
    const EquirectOracle oracle(w, h);
    double worst = 0;
    std::vector<float> rgb(std::size_t{3} * w * h, 0.0f);
    const std::vector<std::uint32_t> rows = {0u, 1u, h - 2, h - 1};
    for (std::uint32_t j : rows) {
      for (std::uint32_t i : {0u, w / 2, w - 1}) {
        std::fill(rgb.begin(), rgb.end(), 0.0f);
        for (int c = 0; c < 3; ++c) rgb[(std::size_t{j} * w + i) * 3 + c] = 1.0f;
        ShL2 sh;
        ASSERT_TRUE(shpack::project_equirect(shpack::make_view(rgb.data(), w, h, 3), {}, sh).ok());
        const std::array<long double, 10> t = oracle.texel(i, j);
        ShLd want{};
        for (int c = 0; c < 3; ++c)
          for (int k = 0; k < 9; ++k) want[c][k] = t[k];
        const std::string what = std::to_string(w) + "x" + std::to_string(h) + " i=" + std::to_string(i) +
                                 " j=" + std::to_string(j);
        expect_within(sh, want, relative_to_norm(want, kTargetRel), what);
        worst = std::max(worst, rel_error(sh, want));
      }
    }
    std::cout << "[ measure  ] pole texels " << w << "x" << h << ": max |err|/norm = " << worst << " (tol " << kTargetRel
              << ")\n";
  }
}

TEST(Geometry, CubeEdgeAndCornerTexels) {
  // The texels along the edges where two faces meet and at the corners where three meet,
  // against the oracle, to the 32 u / h bound of cube_moments.h (h = 2/N) in units of
  // k_i Omega; cube_texel_basis_integrals is project_cube's arithmetic (project_cube.h).
  // Texels mirrored across the face's centre lines have equal solid angles (the corner
  // coordinates are exactly antisymmetric, cube_moments.h), and so do the two texels that
  // meet across a cube edge.
  for (std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 1000u}) {
    double worst = 0;
    for (int f = 0; f < 6; ++f) {
      const std::uint32_t m = n / 2, e = n - 1;
      for (auto [x, y] : {std::pair<std::uint32_t, std::uint32_t>{0, 0}, {e, 0}, {0, e}, {e, e}, {0, m}, {e, m}, {m, 0}, {m, e}}) {
        std::array<double, 9> got{};
        ASSERT_TRUE(shpack::cube_texel_basis_integrals(n, static_cast<shpack::CubeFace>(f), x, y, shpack::SamplingMethod::Exact, got).ok());
        const std::array<long double, 10> want = cube_texel_oracle(n, f, x, y);
        for (int i = 0; i < 9; ++i) {
          const double bound = 32 * kU * (n / 2.0) * shpack::kBasisScale[i] * static_cast<double>(want[9]);
          const double err = static_cast<double>(std::fabs(got[i] - want[i]));
          EXPECT_LE(err, bound) << "N=" << n << " face=" << f << " x=" << x << " y=" << y << " i=" << i;
          worst = std::max(worst, err / bound);
        }
        std::array<double, 9> mirrored{};
        ASSERT_TRUE(shpack::cube_texel_basis_integrals(n, static_cast<shpack::CubeFace>(f), e - x, e - y,
                                                       shpack::SamplingMethod::Exact, mirrored).ok());
        EXPECT_NEAR(mirrored[0], got[0], 4 * kU * got[0]) << "N=" << n << " mirrored solid angle";
      }
    }
    // +Z's right edge (x = N-1) meets +X's left edge (x = 0): same row, same solid angle.
    for (std::uint32_t y : {0u, n / 2, n - 1}) {
      std::array<double, 9> z{}, x{};
      ASSERT_TRUE(shpack::cube_texel_basis_integrals(n, shpack::CubeFace::PosZ, n - 1, y, shpack::SamplingMethod::Exact, z).ok());
      ASSERT_TRUE(shpack::cube_texel_basis_integrals(n, shpack::CubeFace::PosX, 0, y, shpack::SamplingMethod::Exact, x).ok());
      EXPECT_NEAR(z[0], x[0], 4 * kU * z[0]) << "N=" << n << " y=" << y;
    }
    std::cout << "[ measure  ] cube edge/corner texels N=" << n << ": max err / (32 u/h k_i Omega) = " << worst << "\n";
  }
}

TEST(Geometry, EquirectSolidAnglesSumTo4PiAtEverySize) {
  // A unit image has L00 / k0 = sum of the texel solid angles. Derived: the column sums of
  // ones are exact integers, so the error is that of the row weights (<= 8u), k0 and the
  // division (3u), and the compensated row sum (2u): ~16u ~ 2e-15, asserted at the required
  // 1e-12. Streamed in bands from one 64-row buffer of ones, so 16384 x 8192 needs 12 MB.
  struct Size {
    std::uint32_t w, h;
  };
  double worst = 0;
  for (const Size s : {Size{1, 1}, Size{2, 1}, Size{1, 2}, Size{3, 1}, Size{7, 3}, Size{1, 8192}, Size{16384, 1},
                       Size{1023, 511}, Size{4096, 2048}, Size{16384, 8192}}) {
    const std::uint32_t band = std::min(s.h, 64u);
    const std::vector<float> ones(std::size_t{3} * s.w * band, 1.0f);
    shpack::ProjectOptions options;
    options.threads = 2;
    shpack::EquirectProjector projector;
    ASSERT_TRUE(projector.begin(s.w, s.h, options).ok());
    for (std::uint32_t y = 0; y < s.h; y += band) {
      const shpack::Status st = projector.add_rows(shpack::make_view(ones.data(), s.w, std::min(band, s.h - y), 3), y);
      ASSERT_TRUE(st.ok()) << describe(st);
    }
    ShL2 sh;
    ASSERT_TRUE(projector.finish(sh).ok());
    const double sum = sh.c[0][0] / shpack::kY0;
    EXPECT_NEAR(sum, kFourPi, kTargetRel * kFourPi) << s.w << "x" << s.h;
    worst = std::max(worst, std::fabs(sum - kFourPi) / kFourPi);
  }
  std::cout << "[ measure  ] equirect solid angles, 1x1 .. 16384x8192: max |sum - 4 pi| / 4 pi = " << worst << " (tol "
            << kTargetRel << ")\n";
}

// Six face views cut from one float RGB image of a single-image cube layout
// (docs/conventions.md section 2): cell (col, row) of N x N texels, optionally upside down.
struct Cell {
  std::uint32_t col, row;
  bool rotated;
};
std::array<shpack::ImageView, 6> cut(const std::vector<float>& image, std::uint32_t image_width, std::uint32_t n,
                                     const std::array<Cell, 6>& cells) {
  std::array<shpack::ImageView, 6> views;
  for (int f = 0; f < 6; ++f) {
    const Cell c = cells[f];
    const std::int64_t pixel = 12, row = std::int64_t{12} * image_width;
    const std::int64_t first = (std::int64_t{c.row} * n * image_width + std::int64_t{c.col} * n) * 12;
    views[f] = {reinterpret_cast<const std::byte*>(image.data()) + first, shpack::PixelType::F32, n, n, 3, pixel, row};
    if (c.rotated) {  // start at the cell's last texel and walk backwards
      views[f].data += (n - 1) * row + (n - 1) * pixel;
      views[f].pixel_stride = -pixel;
      views[f].row_stride = -row;
    }
  }
  return views;
}

TEST(Geometry, CubeLayoutsSolidAnglesSumTo4Pi) {
  // Six constant faces, alone and as the views of each single-image layout whose unused
  // cells hold NaN (which must never be read: NonFinite::Error would fail). Derived bound as
  // for equirect: the texel weights telescope along rows and columns (cube_moments.h: "sums
  // over many texels ... accurate to a few u whatever N"), the row sums of ones are exact
  // up to the weights' rounding, so ~N u at worst: 1e-13 at N = 1000; asserted at 1e-12.
  double worst = 0;
  for (std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 255u, 1000u}) {
    const std::vector<float> face(std::size_t{3} * n * n, 1.0f);
    std::array<shpack::ImageView, 6> views;
    views.fill(shpack::make_view(face.data(), n, n, 3));
    ShL2 sh;
    shpack::ProjectOptions options;
    options.threads = 2;
    ASSERT_TRUE(shpack::project_cube(views, options, sh).ok());
    const double sum = sh.c[0][0] / shpack::kY0;
    EXPECT_NEAR(sum, kFourPi, kTargetRel * kFourPi) << "N=" << n;
    worst = std::max(worst, std::fabs(sum - kFourPi) / kFourPi);
  }
  std::cout << "[ measure  ] cube solid angles N=1..1000: max |sum - 4 pi| / 4 pi = " << worst << " (tol " << kTargetRel
            << ")\n";

  // Face order +X -X +Y -Y +Z -Z.
  struct Layout {
    const char* name;
    std::uint32_t cols, rows;
    std::array<Cell, 6> cells;
  };
  const Layout layouts[] = {
      {"horizontal strip", 6, 1, {{{0, 0, false}, {1, 0, false}, {2, 0, false}, {3, 0, false}, {4, 0, false}, {5, 0, false}}}},
      {"vertical strip", 1, 6, {{{0, 0, false}, {0, 1, false}, {0, 2, false}, {0, 3, false}, {0, 4, false}, {0, 5, false}}}},
      {"horizontal cross", 4, 3, {{{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {3, 1, false}}}},
      {"vertical cross", 3, 4, {{{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {1, 3, true}}}},
  };
  for (const Layout& layout : layouts) {
    for (std::uint32_t n : {1u, 5u, 64u}) {
      const std::uint32_t w = layout.cols * n, h = layout.rows * n;
      std::vector<float> image(std::size_t{3} * w * h, std::numeric_limits<float>::quiet_NaN());
      for (const Cell c : layout.cells)
        for (std::uint32_t y = 0; y < n; ++y)
          for (std::uint32_t x = 0; x < n; ++x)
            for (int k = 0; k < 3; ++k) image[((std::size_t{c.row} * n + y) * w + c.col * n + x) * 3 + k] = 1.0f;
      ShL2 sh;
      const shpack::Status st = shpack::project_cube(cut(image, w, n, layout.cells), {}, sh);
      ASSERT_TRUE(st.ok()) << layout.name << " N=" << n << ": " << describe(st);
      EXPECT_NEAR(sh.c[0][0] / shpack::kY0, kFourPi, kTargetRel * kFourPi) << layout.name << " N=" << n;
    }
  }
}

TEST(Geometry, CubeLayoutViewsAndSphereMapsSumTo4Pi) {
  // The layouts of cube_layout.h (the library's own cutting of one image into six faces)
  // and the sphere maps of project_sphere_map.h (octahedral, angular, mirror ball), each a
  // unit image: L00 / k0 = 4 pi to 1e-12. Derived: cube as above; the sphere maps' texel
  // integrals are Gauss-Legendre quadrature to ~1e-20 of the integrand's scale
  // (project_sphere_map.h: measured sums within 5e-15 of 4 pi), plus ~N u of row summation.
  double worst = 0;
  for (shpack::CubeLayout layout : {shpack::CubeLayout::HorizontalCross, shpack::CubeLayout::VerticalCross,
                                    shpack::CubeLayout::HorizontalStrip, shpack::CubeLayout::VerticalStrip}) {
    const shpack::CubeGrid grid = shpack::cube_layout_grid(layout);
    for (std::uint32_t n : {1u, 3u, 64u}) {
      const std::uint32_t w = grid.columns * n, h = grid.rows * n;
      std::vector<float> image(std::size_t{3} * w * h, std::numeric_limits<float>::quiet_NaN());
      for (int f = 0; f < 6; ++f) {
        const shpack::CubeCell cell = shpack::cube_layout_cell(layout, static_cast<shpack::CubeFace>(f));
        for (std::uint32_t y = 0; y < n; ++y)
          for (std::uint32_t x = 0; x < n; ++x)
            for (int k = 0; k < 3; ++k) image[((std::size_t{cell.row} * n + y) * w + cell.column * n + x) * 3 + k] = 1.0f;
      }
      std::array<shpack::ImageView, 6> faces;
      ASSERT_TRUE(shpack::cube_face_views(shpack::make_view(image.data(), w, h, 3), layout, faces).ok());
      ShL2 sh;
      const shpack::Status st = shpack::project_cube(faces, {}, sh);
      ASSERT_TRUE(st.ok()) << "layout " << static_cast<int>(layout) << " N=" << n << ": " << describe(st);
      const double sum = sh.c[0][0] / shpack::kY0;
      EXPECT_NEAR(sum, kFourPi, kTargetRel * kFourPi) << "layout " << static_cast<int>(layout) << " N=" << n;
      worst = std::max(worst, std::fabs(sum - kFourPi) / kFourPi);
    }
  }
  for (shpack::SphereMap map : {shpack::SphereMap::Octahedral, shpack::SphereMap::Angular, shpack::SphereMap::MirrorBall}) {
    for (std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 255u}) {
      const std::vector<float> ones(std::size_t{3} * n * n, 1.0f);
      ShL2 sh;
      shpack::ProjectOptions options;
      options.threads = 2;
      const shpack::Status st = shpack::project_sphere_map(shpack::make_view(ones.data(), n, n, 3), map, options, sh);
      ASSERT_TRUE(st.ok()) << "map " << static_cast<int>(map) << " N=" << n << ": " << describe(st);
      const double sum = sh.c[0][0] / shpack::kY0;
      EXPECT_NEAR(sum, kFourPi, kTargetRel * kFourPi) << "map " << static_cast<int>(map) << " N=" << n;
      worst = std::max(worst, std::fabs(sum - kFourPi) / kFourPi);
    }
  }
  std::cout << "[ measure  ] cube layouts (cube_layout.h) and sphere maps: max |sum - 4 pi| / 4 pi = " << worst
            << " (tol " << kTargetRel << ")\n";
}

}  // namespace
}  // namespace shpack_hard
