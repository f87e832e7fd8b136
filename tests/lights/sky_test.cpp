// Tests of sky.h: the Preetham sky's formulas at the zenith, and its projection against
// brute-force quadrature of the same radiance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "lights/light_oracle.h"
#include "shpack/sky.h"
#include "support/test_util.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PreethamSky, ZenithLuminanceIsPreethamsFormula) {
  // At the zenith F(0, theta_s) / F(0, theta_s) = 1, so the luminance is Y_z of [1] A.2, and
  // the Rec. 709 luminance of the RGB (0.2126729 R + 0.7151522 G + 0.0721750 B, the Y row of
  // the inverse matrix) gives it back to the matrix's 7 digits.
  for (const double t : {2.0, 3.0, 6.0})
    for (const double elevation_deg : {10.0, 45.0, 80.0}) {
      const double e = elevation_deg * kPi / 180, theta_s = kPi / 2 - e;
      const PreethamSky sky{{std::cos(e), std::sin(e), 0}, t, {0, 0, 0}, 1};
      Rgb zenith;
      ASSERT_TRUE(preetham_radiance(sky, {0, 1, 0}, zenith).ok());
      const double chi = (4.0 / 9 - t / 120) * (kPi - 2 * theta_s);
      const double y_z = (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
      const double lum = 0.2126729 * zenith[0] + 0.7151522 * zenith[1] + 0.0721750 * zenith[2];
      EXPECT_NEAR(lum, y_z, 1e-6 * y_z) << "T=" << t << " elevation " << elevation_deg;
      Rgb below;
      ASSERT_TRUE(preetham_radiance({sky.sun, t, {0.1, 0.2, 0.3}, 1}, {0.3, -0.5, 0.1}, below).ok());
      EXPECT_EQ(below, (Rgb{0.1, 0.2, 0.3})) << "the ground below the horizon";
    }
}

TEST(PreethamSky, ProjectionMatchesBruteForce) {
  double worst = 0, worst_estimate = 0;
  for (const double t : {2.0, 4.0, 8.0})
    for (const double elevation_deg : {3.0, 30.0, 70.0}) {
      const double e = elevation_deg * kPi / 180;
      const PreethamSky sky{{std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8}, t, {0.05, 0.04, 0.03}, 1};
      ShL2 got;
      double estimate = 0;
      ASSERT_TRUE(add_preetham_sky(sky, got, &estimate).ok());
      worst_estimate = std::max(worst_estimate, estimate);
      for (int c = 0; c < kChannelCount; ++c) {
        const shpack_test::OracleSh upper = shpack_test::upper_hemisphere_oracle(
            [&](double x, double y, double z) {
              Rgb l;
              EXPECT_TRUE(preetham_radiance(sky, {x, y, z}, l).ok());
              return l[c];
            },
            4);
        // The ground half: a hemisphere light of radiance `ground` below, nothing above.
        ShL2 ground;
        ASSERT_TRUE(add_hemisphere_light({0, 0, 0}, sky.ground, ground).ok());
        // Tolerance: the oracle's refinement estimate (x8) and rounding, plus shpack's own
        // estimate of its rule's error (relative to |L_0|).
        const double tol = 8 * upper.error + upper.rounding + 1.1 * estimate * std::fabs(got.c[c][0]) + 1e-14 * upper.scale;
        for (int i = 0; i < kShCount; ++i) {
          const double want = upper.value[i] + ground.c[c][i];
          EXPECT_NEAR(got.c[c][i], want, tol) << "T=" << t << " elevation " << elevation_deg << " c=" << c << " i=" << i;
          worst = std::max(worst, std::fabs(got.c[c][i] - want) / std::fabs(got.c[c][0]));
        }
      }
    }
  std::printf("[ measured ] preetham: max |shpack - oracle| / |L_0| = %.3g, largest self-estimate %.3g\n", worst,
              worst_estimate);
}

TEST(PreethamSky, RejectsASunBelowTheHorizonAndOddTurbidity) {
  ShL2 out;
  EXPECT_EQ(add_preetham_sky({{0, -0.1, 1}, 3, {}, 1}, out).code, Errc::InvalidArgument);
  EXPECT_EQ(add_preetham_sky({{0, 1, 1}, 1.0, {}, 1}, out).code, Errc::InvalidArgument);
  EXPECT_EQ(add_preetham_sky({{0, 1, 1}, 11.0, {}, 1}, out).code, Errc::InvalidArgument);
  EXPECT_EQ(out, ShL2{});
}

}  // namespace
}  // namespace shpack
