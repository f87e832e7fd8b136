// Tests of rotate.h: the sense of Unity's Skybox `_Rotation`, the closed-form rotation
// about +Y, and the general rotation.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/rotate.h"
#include "shpack/sh_basis.h"
#include "support/test_util.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;
using shpack_test::kEps;

Dir3 rotated(const Matrix3& m, const Dir3& v) {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

// Unity's RotateAroundYInDegrees (DefaultResourcesExtra/Skybox-Panoramic.shader), statement
// by statement with HLSL's meaning spelled out, in double:
//   float alpha = degrees * UNITY_PI / 180.0;
//   sincos(alpha, sina, cosa);
//   float2x2 m = float2x2(cosa, -sina, sina, cosa);   // rows (cosa, -sina), (sina, cosa)
//   return float3(mul(m, vertex.xz), vertex.y).xzy;    // mul(matrix, vector): column vector
Dir3 unity_rotate_around_y_in_degrees(const Dir3& vertex, double degrees) {
  const double alpha = degrees * kPi / 180.0;
  const double sina = std::sin(alpha), cosa = std::cos(alpha);
  const double m[2][2] = {{cosa, -sina}, {sina, cosa}};
  const double xz[2] = {vertex.x, vertex.z};
  const double rotated[2] = {m[0][0] * xz[0] + m[0][1] * xz[1], m[1][0] * xz[0] + m[1][1] * xz[1]};
  const double f3[3] = {rotated[0], rotated[1], vertex.y};  // float3(mul(m, vertex.xz), vertex.y)
  return {f3[0], f3[2], f3[1]};                             // .xzy
}

// The SH of a unit delta in direction d: L_i = Y_i(d), filled into all channels.
ShL2 delta(const Dir3& d) {
  ShL2 sh;
  const std::array<double, kShCount> y = eval_basis(d.x, d.y, d.z);
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) sh.c[c][i] = (c + 1.0) * y[i];
  return sh;
}

double norm(const ShL2& sh) {
  double s = 0.0;
  for (const auto& ch : sh.c)
    for (double v : ch) s += v * v;
  return std::sqrt(s);
}

double max_diff(const ShL2& a, const ShL2& b) {
  double d = 0.0;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) d = std::max(d, std::fabs(a.c[c][i] - b.c[c][i]));
  return d;
}

ShL2 random_sh(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ShL2 sh;
  for (auto& ch : sh.c)
    for (double& v : ch) v = u(rng);
  return sh;
}

Dir3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  const Dir3 d{g(rng), g(rng), g(rng)};
  const double r = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return {d.x / r, d.y / r, d.z / r};
}

Matrix3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  double w = g(rng), x = g(rng), y = g(rng), z = g(rng);
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

TEST(Rotate, MatrixIsUnitysRotateAroundYInDegrees) {
  // Same formula evaluated two ways: agreement to a few roundings (4 eps), plus the
  // literal form's rounding of alpha = degrees pi/180 before sin and cos, up to
  // eps |alpha| (rotation_about_y reduces the angle exactly first).
  std::mt19937_64 rng(0x5eed);
  for (double degrees : {0.0, 17.0, 90.0, -45.5, 180.0, 271.25, 1000.0}) {
    const double tolerance = 4 * kEps + kEps * std::fabs(degrees * kPi / 180.0);
    for (int k = 0; k < 8; ++k) {
      const Dir3 v = random_direction(rng);
      const Dir3 want = unity_rotate_around_y_in_degrees(v, degrees);
      const Dir3 got = rotated(rotation_about_y(degrees), v);
      EXPECT_NEAR(got.x, want.x, tolerance) << degrees << " deg, v " << v;
      EXPECT_NEAR(got.y, want.y, tolerance) << degrees << " deg, v " << v;
      EXPECT_NEAR(got.z, want.z, tolerance) << degrees << " deg, v " << v;
    }
  }
  // +90 degrees: +X -> +Z -> -X, exactly.
  EXPECT_TRUE(rotated(rotation_about_y(90.0), Dir3{1, 0, 0}) == (Dir3{0, 0, 1}))
      << rotated(rotation_about_y(90.0), Dir3{1, 0, 0});
  EXPECT_TRUE(rotated(rotation_about_y(90.0), Dir3{0, 0, 1}) == (Dir3{-1, 0, 0}))
      << rotated(rotation_about_y(90.0), Dir3{0, 0, 1});
}

TEST(Rotate, PositiveAngleTurnsPlusXTowardsPlusZ) {
  // The skybox shows the texel of direction v at R v. A delta seen at +X (the centre of
  // an equirect) is seen at +Z (straight ahead) after _Rotation = 90.
  const ShL2 got = rotate_about_y(delta({1, 0, 0}), 90.0);
  const ShL2 want = delta({0, 0, 1});
  EXPECT_LE(max_diff(got, want), 4 * kEps * norm(want));
}

TEST(Rotate, DeltaGoesToTheRotatedDirection) {
  // Y_i(R v) = sum_j M_ij Y_j(v): rotating the SH of a delta at d gives the SH of a delta at
  // R d. A handful of roundings on coefficients of size <= 3 k2: 16 eps * norm.
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> angle(-720.0, 720.0);
  for (int k = 0; k < 50; ++k) {
    const Dir3 d = random_direction(rng);
    const double degrees = angle(rng);
    const ShL2 want = delta(rotated(rotation_about_y(degrees), d));
    const ShL2 got = rotate_about_y(delta(d), degrees);
    EXPECT_LE(max_diff(got, want), 16 * kEps * norm(want)) << degrees << " deg, d " << d;

    const Matrix3 r = random_rotation(rng);
    ShL2 general;
    ASSERT_TRUE(rotate(delta(d), r, general).ok());
    EXPECT_LE(max_diff(general, delta(rotated(r, d))), 64 * kEps * norm(want)) << "random R, d " << d;
  }
}

TEST(Rotate, QuarterTurnsAndFullTurns) {
  std::mt19937_64 rng(0x5eed);
  const ShL2 sh = random_sh(rng);
  // 90 degrees has exact sin and cos (0, 1, -1); the band-2 matrix has sqrt(3)/2 entries,
  // rounded once, so four turns are the identity to a few eps.
  ShL2 turned = sh;
  for (int k = 0; k < 4; ++k) turned = rotate_about_y(turned, 90.0);
  EXPECT_LE(max_diff(turned, sh), 1e-15 * norm(sh));
  // Whole turns reduce to 0 degrees exactly: the identity, bit for bit.
  for (double degrees : {0.0, 360.0, -360.0, 720.0, 3600.0}) EXPECT_EQ(rotate_about_y(sh, degrees), sh) << degrees;
  // Composition: R(a) R(b) = R(a + b), to a few roundings.
  for (auto [a, b] : {std::pair{30.0, 45.0}, {-100.0, 250.5}, {0.1, 359.9}}) {
    EXPECT_LE(max_diff(rotate_about_y(rotate_about_y(sh, a), b), rotate_about_y(sh, a + b)), 16 * kEps * norm(sh))
        << a << " + " << b;
  }
}

TEST(Rotate, BandEnergiesArePreserved) {
  // Each band's matrix is orthogonal: sum_m L_lm^2 is preserved to a few roundings.
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> angle(-360.0, 360.0);
  for (int k = 0; k < 20; ++k) {
    const ShL2 sh = random_sh(rng);
    const double degrees = angle(rng);
    ShL2 general;
    ASSERT_TRUE(rotate(sh, random_rotation(rng), general).ok());
    for (const ShL2& out : {rotate_about_y(sh, degrees), general}) {
      for (int c = 0; c < kChannelCount; ++c) {
        double before[3] = {}, after[3] = {};
        for (int i = 0; i < kShCount; ++i) {
          before[kBand[i]] += sh.c[c][i] * sh.c[c][i];
          after[kBand[i]] += out.c[c][i] * out.c[c][i];
        }
        for (int l = 0; l < 3; ++l) EXPECT_NEAR(after[l], before[l], 32 * kEps * before[l]) << "l=" << l << " " << degrees;
      }
    }
  }
}

TEST(Rotate, GeneralRotationAgreesWithClosedForm) {
  std::mt19937_64 rng(0x5eed);
  const ShL2 sh = random_sh(rng);
  for (double degrees : {0.0, 12.5, 90.0, 135.0, -200.0}) {
    ShL2 general;
    ASSERT_TRUE(rotate(sh, rotation_about_y(degrees), general).ok());
    EXPECT_LE(max_diff(general, rotate_about_y(sh, degrees)), 32 * kEps * norm(sh)) << degrees;
  }
  // The z mirror (a reflection) flips indices 2, 5, 7: kMirrorZSign, exactly.
  ShL2 mirrored;
  ASSERT_TRUE(rotate(sh, Matrix3{{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}}, mirrored).ok());
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) EXPECT_EQ(mirrored.c[c][i], kMirrorZSign[i] * sh.c[c][i]) << "i=" << i;
  // Not orthogonal, or not finite: refused.
  ShL2 out;
  EXPECT_EQ(rotate(sh, Matrix3{{{1, 0, 0}, {0, 1.001, 0}, {0, 0, 1}}}, out).code, Errc::InvalidArgument);
  EXPECT_EQ(rotate(sh, Matrix3{{{std::nan(""), 0, 0}, {0, 1, 0}, {0, 0, 1}}}, out).code, Errc::InvalidArgument);
}

// An equirect test image: random values plus a few bright blobs, so bands 1 and 2 carry
// much of the energy and a turn in the wrong sense is far off.
std::vector<float> test_equirect(std::uint32_t w, std::uint32_t h) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> img(std::size_t{3} * w * h);
  for (std::uint32_t j = 0; j < h; ++j)
    for (std::uint32_t i = 0; i < w; ++i)
      for (int c = 0; c < 3; ++c) {
        float v = u(rng);
        if ((i > w / 8 && i < w / 4 && j > h / 3 && j < h / 2) || (i > 3 * w / 5 && i < 2 * w / 3 && j < h / 5))
          v += 20.0f * (c + 1);
        img[3 * (std::size_t{j} * w + i) + c] = v;
      }
  return img;
}

// The image turned left by k columns: column i shows old column (i + k) mod W.
std::vector<float> shifted_left(const std::vector<float>& img, std::uint32_t w, std::uint32_t h, std::int64_t k) {
  std::vector<float> out(img.size());
  for (std::uint32_t j = 0; j < h; ++j)
    for (std::uint32_t i = 0; i < w; ++i) {
      const auto from = static_cast<std::uint32_t>(((i + k) % w + w) % w);
      for (int c = 0; c < 3; ++c) out[3 * (std::size_t{j} * w + i) + c] = img[3 * (std::size_t{j} * w + from) + c];
    }
  return out;
}

TEST(Rotate, MatchesProjectionOfTheColumnShiftedEquirect) {
  // Skybox/Panoramic with _Rotation = 360 k / W shows the equirect shifted LEFT by k columns
  // (rotate.h). Turning by whole columns maps texels onto texels, so the exact projection
  // of the shifted image equals the rotated coefficients up to rounding of the projection
  // sums and the 3x3/5x5 products: 1e-13 of the norm. The opposite sense must miss by far.
  const std::uint32_t w = 64, h = 32;
  const std::vector<float> img = test_equirect(w, h);
  ShL2 sh;
  ASSERT_TRUE(project_equirect(make_view(img.data(), w, h, 3), ProjectOptions{}, sh).ok());
  for (std::int64_t k : {16, 5, -3, 48, 32}) {
    const double degrees = 360.0 * static_cast<double>(k) / w;
    const std::vector<float> moved = shifted_left(img, w, h, k);
    ShL2 want;
    ASSERT_TRUE(project_equirect(make_view(moved.data(), w, h, 3), ProjectOptions{}, want).ok());
    EXPECT_LE(max_diff(rotate_about_y(sh, degrees), want), 1e-13 * norm(want)) << "k=" << k << " deg=" << degrees;
    if (k != 32) {  // 180 degrees is its own inverse
      EXPECT_GT(max_diff(rotate_about_y(sh, -degrees), want), 1e-2 * norm(want)) << "k=" << k << " (wrong sense)";
    }
  }
}

}  // namespace
}  // namespace shpack
