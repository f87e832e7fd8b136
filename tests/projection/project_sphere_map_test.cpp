// Tests of project_sphere_map.h: octahedral maps, angular maps and mirrored balls.
//
// Oracle: support/sphere_map_oracle.h, an independent transcription of each mapping and a
// slow integral over each texel in different coordinates (polar about the image centre for
// the disc maps, collapsed triangles of the unfolded octahedron for octahedral maps), plus
// closed forms for the octahedral solid angle and first moment. The measured errors are
// printed ("[ measure  ]") so the header's accuracy statement can be checked.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "shpack/project_sphere_map.h"
#include "shpack/sh_basis.h"
#include "support/sphere_map_oracle.h"
#include "support/test_util.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::array<SphereMap, 3> kMaps = {SphereMap::Octahedral, SphereMap::Angular, SphereMap::MirrorBall};

const char* name(SphereMap m) {
  return m == SphereMap::Octahedral ? "octahedral" : m == SphereMap::Angular ? "angular" : "mirrorball";
}

std::array<double, kShCount> integrals(SphereMap map, std::uint32_t n, std::uint32_t x, std::uint32_t y) {
  std::array<double, kShCount> out{};
  const Status st = sphere_map_texel_basis_integrals(n, map, x, y, out);
  EXPECT_TRUE(st.ok()) << shpack_test::describe(st);
  return out;
}

// The direction of the first moment int d dw of a texel, from its L1 integrals
// (Y_1 = k1 y, Y_2 = k1 z, Y_3 = k1 x).
Dir3 moment_direction(const std::array<double, kShCount>& y) {
  const double r = std::sqrt(y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
  return {y[3] / r, y[1] / r, y[2] / r};
}

TEST(SphereMap, SolidAnglesSumTo4Pi) {
  // Each texel's solid angle is accurate to ~1e-14 of the largest one (measured below), and
  // the errors do not add up coherently: 1e-12 absolute on 4 pi is the required accuracy.
  for (const SphereMap map : kMaps) {
    for (const std::uint32_t n : {1u, 2u, 3u, 4u, 5u, 8u, 17u, 64u, 255u}) {
      long double sum = 0;
      for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t x = 0; x < n; ++x) sum += integrals(map, n, x, y)[0] / kY0;
      const double error = static_cast<double>(sum - 4 * std::numbers::pi_v<long double>);
      EXPECT_LE(std::fabs(error), 1e-12) << name(map) << " n=" << n;
      if (n == 255) std::cout << "[ measure  ] " << name(map) << " n=255: sum of solid angles - 4 pi = " << error << "\n";
    }
  }
}

// Texels to compare with the oracle: all of small maps; of larger ones every `stride`-th,
// plus the rim texels where the chart works hardest: at u = -1 beside the line v = 0 (two
// square-root points a distance ~h^2/8 apart) and at the top of the centre column.
std::vector<std::array<std::uint32_t, 2>> sample(std::uint32_t n, std::uint32_t stride) {
  std::vector<std::array<std::uint32_t, 2>> texels;
  for (std::uint32_t y = 0; y < n; y += stride)
    for (std::uint32_t x = 0; x < n; x += stride) texels.push_back({x, y});
  if (stride > 1)
    for (std::uint32_t k = 0; k < 4; ++k) texels.push_back({0, n / 2 - 2 + k}), texels.push_back({1, n / 2 - 2 + k}),
                                           texels.push_back({n / 2 - 1 + k % 2, k / 2});
  return texels;
}

TEST(SphereMap, TexelIntegralsMatchTheOracle) {
  // The header promises every texel's nine integrals within 1e-12 of the image's largest
  // texel solid angle; the oracle itself is good to ~1e-15 of it (its header).
  for (const SphereMap map : kMaps) {
    double worst = 0;
    for (const std::uint32_t n : {1u, 2u, 3u, 4u, 5u, 7u, 8u, 16u, 33u, 128u, 255u}) {
      const std::uint32_t stride = n <= 8 ? 1 : n <= 33 ? 5 : 37;
      double omega_max = 0;
      std::vector<std::array<double, 10>> oracle;
      const auto texels = sample(n, stride);
      for (const auto& t : texels) {
        const std::array<long double, 10> o = shpack_test::sphere_map_texel_oracle(map, n, t[0], t[1]);
        std::array<double, 10> od;
        for (int i = 0; i < 10; ++i) od[i] = static_cast<double>(o[i]);
        oracle.push_back(od);
        omega_max = std::fmax(omega_max, od[9]);
      }
      // The largest texel of the image, wherever it is: the centre one for the disc maps.
      const std::array<long double, 10> centre = shpack_test::sphere_map_texel_oracle(map, n, n / 2, n / 2);
      omega_max = std::fmax(omega_max, static_cast<double>(centre[9]));
      for (std::size_t k = 0; k < texels.size(); ++k) {
        const std::array<double, kShCount> got = integrals(map, n, texels[k][0], texels[k][1]);
        for (int i = 0; i < kShCount; ++i) {
          const double error = std::fabs(got[i] - oracle[k][i]) / omega_max;
          worst = std::fmax(worst, error);
          EXPECT_LE(error, 1e-12) << name(map) << " n=" << n << " texel (" << texels[k][0] << ", "
                                  << texels[k][1] << ") i=" << i << " got " << got[i] << " oracle " << oracle[k][i];
        }
      }
    }
    std::cout << "[ measure  ] " << name(map) << ": worst texel integral error / largest texel solid angle = "
              << worst << "\n";
  }
}

TEST(SphereMap, OctahedralMatchesTheClosedForms) {
  // Van Oosterom-Strackee solid angles and Arvo's first moments (sphere_map_oracle.h), in
  // long double: 1e-13 of the largest texel solid angle is ~100 times the rounding of
  // either side.
  for (const std::uint32_t n : {1u, 2u, 3u, 5u, 8u, 16u}) {
    const double omega_max = static_cast<double>(shpack_test::octahedral_texel_closed_form(n, n / 2, n / 2).solid_angle);
    for (std::uint32_t y = 0; y < n; ++y) {
      for (std::uint32_t x = 0; x < n; ++x) {
        const std::array<double, kShCount> got = integrals(SphereMap::Octahedral, n, x, y);
        const shpack_test::OctahedralClosedForm want = shpack_test::octahedral_texel_closed_form(n, x, y);
        const double tol = 1e-13 * omega_max;
        EXPECT_NEAR(got[0] / kY0, static_cast<double>(want.solid_angle), tol) << "n=" << n << " x=" << x << " y=" << y;
        EXPECT_NEAR(got[3] / kY1, static_cast<double>(want.first_moment[0]), tol) << "n=" << n << " x=" << x << " y=" << y;
        EXPECT_NEAR(got[1] / kY1, static_cast<double>(want.first_moment[1]), tol) << "n=" << n << " x=" << x << " y=" << y;
        EXPECT_NEAR(got[2] / kY1, static_cast<double>(want.first_moment[2]), tol) << "n=" << n << " x=" << x << " y=" << y;
      }
    }
  }
}

TEST(SphereMap, MirrorBallSolidAngleIsFourTimesTheArea) {
  // dw = 4 du dv: a texel wholly inside the disc has the solid angle 4 (2/N)^2.
  const std::uint32_t n = 10;
  const double h = 2.0 / n;
  EXPECT_NEAR(integrals(SphereMap::MirrorBall, n, 4, 4)[0] / kY0, 4 * h * h, 4 * kPi * 1e-15);
  EXPECT_EQ(integrals(SphereMap::MirrorBall, n, 0, 0)[0], 0.0);  // the corner is outside the disc
}

// Which way each map faces: the first moment of a texel points where the header says.
struct Pin {
  std::uint32_t x, y;
  Dir3 axis;  // the dominant signed axis of the texel's direction
};

TEST(SphereMap, BrightTexelsLandWhereTheHeaderSays) {
  // N = 9: texel 4 is the centre column/row; texels 2 and 6 are half-way to the edges
  // (u or v = -+0.444), where all three maps are still near the named axis.
  const std::uint32_t n = 9;
  const Dir3 px{1, 0, 0}, nx{-1, 0, 0}, py{0, 1, 0}, ny{0, -1, 0}, pz{0, 0, 1}, nz{0, 0, -1};
  const std::vector<std::pair<SphereMap, std::vector<Pin>>> pins = {
      // Octahedral: centre +Z; top, right, bottom, left of the diamond +Y, +X, -Y, -X;
      // the image corners -Z.
      {SphereMap::Octahedral, {{4, 4, pz}, {4, 1, py}, {7, 4, px}, {4, 7, ny}, {1, 4, nx}, {0, 0, nz}, {8, 8, nz}}},
      // Angular: centre +Z (forward), right +X, top +Y; the rim -Z (texel (8, 4): psi = 160 degrees).
      {SphereMap::Angular, {{4, 4, pz}, {6, 4, px}, {4, 2, py}, {2, 4, nx}, {4, 6, ny}, {8, 4, nz}}},
      // Mirror ball: centre -Z (the camera), right +X, top +Y; near the rim +Z.
      {SphereMap::MirrorBall, {{4, 4, nz}, {6, 4, px}, {4, 2, py}, {2, 4, nx}, {4, 6, ny}, {8, 4, px}}},
  };
  for (const auto& [map, list] : pins) {
    for (const Pin& pin : list) {
      const Dir3 d = moment_direction(integrals(map, n, pin.x, pin.y));
      const double along = d.x * pin.axis.x + d.y * pin.axis.y + d.z * pin.axis.z;
      EXPECT_GT(along, 0.5) << name(map) << " texel (" << pin.x << ", " << pin.y << ") points to " << d;
      // The moment's direction is near the mapping of the texel centre (the oracle's
      // transcription): within the texel's angular size, at most 2 pi / 9 here.
      Dir3 centre;
      ASSERT_TRUE(shpack_test::sphere_map_direction(map, 2.0 * (pin.x + 0.5) / n - 1.0, 1.0 - 2.0 * (pin.y + 0.5) / n, centre));
      EXPECT_GT(d.x * centre.x + d.y * centre.y + d.z * centre.z, std::cos(2 * kPi / n))
          << name(map) << " texel (" << pin.x << ", " << pin.y << "): " << d << " vs centre " << centre;
    }
  }
  // The mirror ball's texel (8, 4) at u = 0.89 looks ahead past the ball: z > 0.
  EXPECT_GT(moment_direction(integrals(SphereMap::MirrorBall, n, 8, 4)).z, 0.3);
}

struct Image {
  std::uint32_t n;
  std::vector<float> rgb;
  explicit Image(std::uint32_t size) : n(size), rgb(std::size_t{3} * size * size, 0.0f) {}
  float* at(std::uint32_t x, std::uint32_t y) { return rgb.data() + 3 * (std::size_t{y} * n + x); }
  ImageView view() const { return make_view(rgb.data(), n, n, 3); }
};

TEST(SphereMap, ProjectionIsTheSumOfTheTexelIntegrals) {
  // Every texel value times its integrals, summed in long double. The projection sums a row
  // in double (error <= n u sum |terms|) and rows with Neumaier's sum: 2 n u sum |terms|.
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<float> value(0.0f, 4.0f);
  for (const SphereMap map : kMaps) {
    const std::uint32_t n = 13;
    Image image(n);
    for (float& v : image.rgb) v = value(rng);
    ShL2 got;
    ASSERT_TRUE(project_sphere_map(image.view(), map, {}, got).ok());
    std::array<std::array<long double, kShCount>, 3> want{}, scale{};
    for (std::uint32_t y = 0; y < n; ++y) {
      for (std::uint32_t x = 0; x < n; ++x) {
        const std::array<double, kShCount> w = integrals(map, n, x, y);
        for (int c = 0; c < 3; ++c)
          for (int i = 0; i < kShCount; ++i) {
            want[c][i] += static_cast<long double>(image.at(x, y)[c]) * w[i];
            scale[c][i] += std::fabs(static_cast<long double>(image.at(x, y)[c]) * w[i]);
          }
      }
    }
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < kShCount; ++i)
        EXPECT_NEAR(got.c[c][i], static_cast<double>(want[c][i]), 2.0 * n * shpack_test::kEps * static_cast<double>(scale[c][i]))
            << name(map) << " c=" << c << " i=" << i;
  }
}

TEST(SphereMap, TexelsOutsideTheDiscAreNeverRead) {
  // Garbage (NaN) in every texel outside the disc: no error, nothing counted, and the same
  // result as zeros there. A NaN inside is found, at its place.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const SphereMap map : {SphereMap::Angular, SphereMap::MirrorBall}) {
    const std::uint32_t n = 16;
    Image garbage(n), clean(n);
    for (std::uint32_t y = 0; y < n; ++y) {
      for (std::uint32_t x = 0; x < n; ++x) {
        const bool outside = integrals(map, n, x, y)[0] == 0.0;
        for (int c = 0; c < 3; ++c) {
          garbage.at(x, y)[c] = outside ? nan : 1.0f + c;
          clean.at(x, y)[c] = outside ? 0.0f : 1.0f + c;
        }
      }
    }
    ShL2 a, b;
    ProjectStats stats;
    const Status st = project_sphere_map(garbage.view(), map, {}, a, &stats);
    ASSERT_TRUE(st.ok()) << name(map) << " " << shpack_test::describe(st);
    EXPECT_EQ(stats.nonfinite_texels, 0u) << name(map);
    ASSERT_TRUE(project_sphere_map(clean.view(), map, {}, b).ok());
    EXPECT_EQ(a, b) << name(map);
    // Uniform radiance 1 + c inside: L00 = 2 sqrt(pi) (1 + c), to the texel integrals' accuracy.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.c[c][0], 2.0 * std::sqrt(kPi) * (1 + c), 1e-12) << name(map);

    clean.at(9, 3)[1] = nan;
    const Status bad = project_sphere_map(clean.view(), map, {}, b);
    EXPECT_EQ(bad.code, Errc::NonFiniteTexel) << name(map);
    EXPECT_EQ(bad.x, 9u);
    EXPECT_EQ(bad.y, 3u);
  }
}

TEST(SphereMap, ThreadCountDoesNotChangeTheResult) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  Image image(150);  // three tiles of kTileRows rows
  for (float& v : image.rgb) v = value(rng);
  for (const SphereMap map : kMaps) {
    ProjectOptions one, three;
    three.threads = 3;
    ShL2 a, b;
    ASSERT_TRUE(project_sphere_map(image.view(), map, one, a).ok());
    ASSERT_TRUE(project_sphere_map(image.view(), map, three, b).ok());
    EXPECT_EQ(a, b) << name(map);
  }
}

TEST(SphereMap, BadInputsAreRefused) {
  std::vector<float> rgb(3 * 8 * 4, 1.0f);
  ShL2 sh;
  EXPECT_EQ(project_sphere_map(make_view(rgb.data(), 8, 4, 3), SphereMap::Angular, {}, sh).code, Errc::BadView);
  ProjectOptions center;
  center.method = SamplingMethod::Center;
  EXPECT_EQ(project_sphere_map(make_view(rgb.data(), 4, 4, 3), SphereMap::Angular, center, sh).code,
            Errc::InvalidArgument);
  std::array<double, kShCount> out{};
  EXPECT_EQ(sphere_map_texel_basis_integrals(0, SphereMap::Angular, 0, 0, out).code, Errc::InvalidArgument);
  EXPECT_EQ(sphere_map_texel_basis_integrals(4, SphereMap::Angular, 4, 0, out).code, Errc::InvalidArgument);
}

}  // namespace
}  // namespace shpack
