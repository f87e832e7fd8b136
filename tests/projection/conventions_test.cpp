// conventions_test.cpp - pins every statement of conventions.h / docs/conventions.md:
// the equirect mapping (centre column +X, u = 0.25 +Z, u = 0.75 -Z, edges -X, top row +Y),
// seen both through equirect_direction and through what the projection lights up; the
// z-mirror sign vector; the cube-face table.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "shpack/conventions.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"
#include "support/equirect_oracle.h"
#include "support/rgb_image.h"
#include "support/sphere_points.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

using shpack::Dir3;
constexpr double kPi = std::numbers::pi;

// sin(pi) and cos(pi/2) are ~1.2e-16 and ~6e-17 in double, and the arguments carry one
// rounding: every component of equirect_direction at the key points is within 4u of the
// exact axis.
constexpr double kAxisTol = 4 * kU;

void expect_dir_near(const Dir3& want, const Dir3& got, double tol, const std::string& what) {
  EXPECT_NEAR(want.x, got.x, tol) << what << " got=" << got;
  EXPECT_NEAR(want.y, got.y, tol) << what << " got=" << got;
  EXPECT_NEAR(want.z, got.z, tol) << what << " got=" << got;
}

TEST(Conventions, EquirectAnglesFollowSkyboxPanoramic) {
  EXPECT_DOUBLE_EQ(shpack::equirect_theta(0.0), 0.0);
  EXPECT_DOUBLE_EQ(shpack::equirect_theta(0.5), kPi / 2);
  EXPECT_DOUBLE_EQ(shpack::equirect_theta(1.0), kPi);
  EXPECT_DOUBLE_EQ(shpack::equirect_lon(0.0), kPi);
  EXPECT_DOUBLE_EQ(shpack::equirect_lon(0.25), kPi / 2);
  EXPECT_DOUBLE_EQ(shpack::equirect_lon(0.75), -kPi / 2);
  EXPECT_DOUBLE_EQ(shpack::equirect_lon(1.0), -kPi);
  EXPECT_EQ(shpack::equirect_lon(0.5), 0.0);
}

TEST(Conventions, EquirectDirectionOfKeyPoints) {
  expect_dir_near({1, 0, 0}, shpack::equirect_direction(0.5, 0.5), kAxisTol, "centre column -> +X");
  expect_dir_near({0, 0, 1}, shpack::equirect_direction(0.25, 0.5), kAxisTol, "u=0.25 -> +Z");
  expect_dir_near({0, 0, -1}, shpack::equirect_direction(0.75, 0.5), kAxisTol, "u=0.75 -> -Z");
  expect_dir_near({-1, 0, 0}, shpack::equirect_direction(0.0, 0.5), kAxisTol, "left edge -> -X");
  expect_dir_near({-1, 0, 0}, shpack::equirect_direction(1.0, 0.5), kAxisTol, "right edge -> -X");
  for (double u : {0.0, 0.3, 0.5, 0.9}) {
    expect_dir_near({0, 1, 0}, shpack::equirect_direction(u, 0.0), kAxisTol, "top row -> +Y");
    expect_dir_near({0, -1, 0}, shpack::equirect_direction(u, 1.0), kAxisTol, "bottom row -> -Y");
  }
}

TEST(Conventions, EquirectDirectionAgreesWithOracle) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 500; ++k) {
    const double u = unit(rng), t = unit(rng);
    const Dir3 got = shpack::equirect_direction(u, t);
    const Dir3 want = direction_of(kPi * t, (0.5 - u) * 2.0 * kPi);
    // Same formula from the doc, evaluated independently: a few roundings apart.
    expect_dir_near(want, got, 8 * kU, "u=" + std::to_string(u) + " t=" + std::to_string(t));
    EXPECT_NEAR(1.0, got.x * got.x + got.y * got.y + got.z * got.z, 8 * kU) << "u=" << u << " t=" << t;
  }
}

// Projects an image that is black except where `lit` says, and returns the radiance
// coefficients of channel 0.
template <class Lit>
std::array<double, 9> project_lit(std::uint32_t w, std::uint32_t h, Lit lit) {
  RgbImage img(w, h);
  for (std::uint32_t j = 0; j < h; ++j)
    for (std::uint32_t i = 0; i < w; ++i)
      if (lit(i, j)) img.set(i, j, 1.0f, 1.0f, 1.0f);
  shpack::ShL2 sh;
  const shpack::Status st = shpack::project_equirect(img.view(), {}, sh);
  EXPECT_TRUE(st.ok()) << describe(st);
  return sh.c[0];
}

// The L1 coefficients are k1 (int y, int z, int x) at indices 1, 2, 3. A lit set that is
// symmetric about an axis has the other two integrals exactly 0; the projection computes
// them from O(u)-accurate texel terms whose absolute values sum to at most ~the lit solid
// angle, while the lit axis' integral is >= (2/pi) of it for the cases below. So a
// "zero" component is within 64u of the lit one (more than 2x margin on 32u).
constexpr double kZeroL1Rel = 64 * kU;

TEST(Conventions, CentreColumnLightsPlusX) {
  // W = 33: column 16 is centred on u = 16.5/33 = 0.5 exactly.
  const auto l = project_lit(33, 16, [](auto i, auto) { return i == 16; });
  EXPECT_GT(l[3], 0.0) << "x coefficient (index 3) must be positive";
  EXPECT_LE(std::fabs(l[1]), kZeroL1Rel * l[3]) << "y";
  EXPECT_LE(std::fabs(l[2]), kZeroL1Rel * l[3]) << "z";
}

TEST(Conventions, EdgeColumnsLightMinusX) {
  const auto l = project_lit(33, 16, [](auto i, auto) { return i == 0 || i == 32; });
  EXPECT_LT(l[3], 0.0) << "x coefficient (index 3) must be negative";
  EXPECT_LE(std::fabs(l[1]), kZeroL1Rel * -l[3]) << "y";
  EXPECT_LE(std::fabs(l[2]), kZeroL1Rel * -l[3]) << "z";
}

TEST(Conventions, QuarterColumnLightsPlusZ) {
  // W = 34: column 8 is centred on u = 8.5/34 = 0.25.
  const auto l = project_lit(34, 16, [](auto i, auto) { return i == 8; });
  EXPECT_GT(l[2], 0.0) << "z coefficient (index 2) must be positive";
  EXPECT_LE(std::fabs(l[1]), kZeroL1Rel * l[2]) << "y";
  EXPECT_LE(std::fabs(l[3]), kZeroL1Rel * l[2]) << "x";
}

TEST(Conventions, ThreeQuarterColumnLightsMinusZ) {
  // W = 34: column 25 is centred on u = 25.5/34 = 0.75.
  const auto l = project_lit(34, 16, [](auto i, auto) { return i == 25; });
  EXPECT_LT(l[2], 0.0) << "z coefficient (index 2) must be negative";
  EXPECT_LE(std::fabs(l[1]), kZeroL1Rel * -l[2]) << "y";
  EXPECT_LE(std::fabs(l[3]), kZeroL1Rel * -l[2]) << "x";
}

TEST(Conventions, TopRowLightsPlusYBottomRowMinusY) {
  // A full row: the x and z integrals are sums of W equally spaced cosines / sines, zero
  // analytically, with rounding <= W u per column sum relative to the row's |terms|; the
  // row's x-weight int sin^2 is below its y-weight int sin cos for the top row of 8.
  const std::uint32_t w = 16, h = 8;
  const double tol = (8.0 * w + 64.0) * kU;
  const auto top = project_lit(w, h, [](auto, auto j) { return j == 0; });
  EXPECT_GT(top[1], 0.0) << "y coefficient (index 1) must be positive";
  EXPECT_LE(std::fabs(top[2]), tol * top[1]) << "z";
  EXPECT_LE(std::fabs(top[3]), tol * top[1]) << "x";
  const auto bottom = project_lit(w, h, [h](auto, auto j) { return j == h - 1; });
  EXPECT_LT(bottom[1], 0.0) << "y coefficient (index 1) must be negative";
  EXPECT_LE(std::fabs(bottom[2]), tol * -bottom[1]) << "z";
  EXPECT_LE(std::fabs(bottom[3]), tol * -bottom[1]) << "x";
}

TEST(Conventions, SingleTexelL1PointsAtItsCentreDirection) {
  // (L3, L1, L2)/k1 = int_t w dw = Omega_t d_c + O(h^2): its direction is within the
  // texel's angular radius (h = pi/H in theta, sin(theta) 2pi/W in lon) of the centre
  // direction that equirect_direction gives. This pins the whole mapping, not just axes.
  const std::uint32_t w = 64, h = 32;
  for (std::uint32_t j : {0u, 5u, 15u, 16u, 27u, 31u})
    for (std::uint32_t i : {0u, 9u, 16u, 31u, 32u, 48u, 63u}) {
      const auto l = project_lit(w, h, [&](auto x, auto y) { return x == i && y == j; });
      const Dir3 v{l[3], l[1], l[2]};
      const double len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
      ASSERT_GT(len, 0.0) << "i=" << i << " j=" << j;
      const Dir3 c = shpack::equirect_direction((i + 0.5) / w, (j + 0.5) / h);
      const double cos_angle = (v.x * c.x + v.y * c.y + v.z * c.z) / len;
      const double radius = kPi / h + 2 * kPi / w;
      EXPECT_GT(cos_angle, std::cos(radius)) << "i=" << i << " j=" << j << " centre=" << c << " L1=" << v;
    }
}

TEST(Conventions, MirrorZSignVector) {
  // docs/conventions.md section 2: s = (+,+,-,+,+,-,+,-,+).
  const std::array<double, 9> want = {1, 1, -1, 1, 1, -1, 1, -1, 1};
  for (int i = 0; i < 9; ++i) EXPECT_EQ(shpack::kMirrorZSign[i], want[i]) << "i=" << i;
  // And it is what z -> -z does to the basis (each P_i is a monomial expression, so the
  // flip is exact).
  std::mt19937_64 rng(0x5eed);
  for (int k = 0; k < 200; ++k) {
    const Dir3 d = random_direction(rng);
    const Dir3 m = shpack::from_right_handed_y_up(d);
    EXPECT_EQ(m, (Dir3{d.x, d.y, -d.z}));
    const auto y = shpack::eval_basis(d.x, d.y, d.z);
    const auto ym = shpack::eval_basis(m.x, m.y, m.z);
    for (int i = 0; i < 9; ++i) EXPECT_EQ(ym[i], shpack::kMirrorZSign[i] * y[i]) << "i=" << i << " d=" << d;
  }
}

TEST(Conventions, CubeFaceTableMatchesTheDoc) {
  EXPECT_EQ(static_cast<int>(shpack::CubeFace::PosX), 0);
  EXPECT_EQ(static_cast<int>(shpack::CubeFace::NegX), 1);
  EXPECT_EQ(static_cast<int>(shpack::CubeFace::PosY), 2);
  EXPECT_EQ(static_cast<int>(shpack::CubeFace::NegY), 3);
  EXPECT_EQ(static_cast<int>(shpack::CubeFace::PosZ), 4);
  EXPECT_EQ(static_cast<int>(shpack::CubeFace::NegZ), 5);
  // docs/conventions.md, "Cubemaps": U (a), V (b), N_f per face.
  const shpack::CubeFaceAxes want[6] = {
      {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}},  {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},
      {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
      {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},   {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
  };
  for (int f = 0; f < 6; ++f) {
    const shpack::CubeFaceAxes& got = shpack::kCubeFaceAxes[f];
    EXPECT_EQ(got.u_axis, want[f].u_axis) << "face=" << f;
    EXPECT_EQ(got.v_axis, want[f].v_axis) << "face=" << f;
    EXPECT_EQ(got.normal, want[f].normal) << "face=" << f;
  }
}

TEST(Conventions, CubeFaceAxesAreOrthonormalWithNormalMinusUCrossV) {
  auto dot = [](const Dir3& a, const Dir3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; };
  auto cross = [](const Dir3& a, const Dir3& b) {
    return Dir3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  };
  for (int f = 0; f < 6; ++f) {
    const shpack::CubeFaceAxes& a = shpack::kCubeFaceAxes[f];
    EXPECT_EQ(dot(a.u_axis, a.u_axis), 1.0) << "face=" << f;
    EXPECT_EQ(dot(a.v_axis, a.v_axis), 1.0) << "face=" << f;
    EXPECT_EQ(dot(a.normal, a.normal), 1.0) << "face=" << f;
    EXPECT_EQ(dot(a.u_axis, a.v_axis), 0.0) << "face=" << f;
    EXPECT_EQ(dot(a.u_axis, a.normal), 0.0) << "face=" << f;
    EXPECT_EQ(dot(a.v_axis, a.normal), 0.0) << "face=" << f;
    // D3D's table: on every face N = -(U x V), the same handedness for all six.
    const Dir3 c = cross(a.u_axis, a.v_axis);
    EXPECT_EQ((Dir3{-c.x, -c.y, -c.z}), a.normal) << "face=" << f;
  }
  // The face centre of +X is the equirect centre column, of +Z the u = 0.25 column.
  expect_dir_near(shpack::kCubeFaceAxes[0].normal, shpack::equirect_direction(0.5, 0.5), kAxisTol, "+X");
  expect_dir_near(shpack::kCubeFaceAxes[4].normal, shpack::equirect_direction(0.25, 0.5), kAxisTol, "+Z");
  expect_dir_near(shpack::kCubeFaceAxes[2].normal, shpack::equirect_direction(0.5, 0.0), kAxisTol, "+Y");
}

}  // namespace
}  // namespace shpack_test
