// sampling_variance_test.cpp - the closed-form variance of mc and is (sampling_variance.h)
// against identities and against the variance of the estimators over many seeds.
#include "shpack/sampling_variance.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "shpack/sampling_methods.h"
#include "support/rgb_image.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;

ProjectOptions policies() {
  ProjectOptions options;
  options.nonfinite = NonFinite::Zero;
  options.negative = Negative::Keep;
  return options;
}

// A constant map L: E[X^2] = 4 pi L^2 int Y_i^2 = 4 pi L^2 (orthonormality, and the texel
// integrals sum to the sphere's exactly), L_0 = L int Y_0 = sqrt(4 pi) L, L_i = 0 for i > 0.
// So Var = 0 for i = 0 and 4 pi L^2 otherwise, for mc, and for is, whose constant
// luminance makes it uniform. Rounding: a few hundred additions of terms <= 4 pi L^2, each
// off by ~1e-16 relative, so 1e-12 relative is far above it; a wrong weight, basis constant
// or missing term is off by O(1).
TEST(SampleVariance, ConstantMapHasTheOrthonormalBasisVariance) {
  shpack_test::RgbImage map(16, 8);
  const std::array<float, 3> value = {1.0f, 2.0f, 0.5f};
  for (std::uint32_t y = 0; y < map.height; ++y)
    for (std::uint32_t x = 0; x < map.width; ++x) map.set(x, y, value[0], value[1], value[2]);
  for (const SamplingMethod method : {SamplingMethod::MonteCarlo, SamplingMethod::Importance}) {
    ShL2 var;
    ASSERT_TRUE(sample_variance(map.view(), method, policies(), var).ok());
    for (int c = 0; c < kChannelCount; ++c) {
      const double scale = 4.0 * kPi * value[c] * value[c];
      EXPECT_NEAR(var.c[c][0], 0.0, 1e-12 * scale);
      for (int i = 1; i < kShCount; ++i) EXPECT_NEAR(var.c[c][i], scale, 1e-12 * scale) << c << " " << i;
    }
  }
}

TEST(SampleVariance, OtherMethodsHaveNoClosedForm) {
  shpack_test::RgbImage map(4, 2);
  ShL2 var;
  EXPECT_FALSE(sample_variance(map.view(), SamplingMethod::QuasiMonteCarlo, policies(), var).ok());
  EXPECT_FALSE(sample_variance(map.view(), SamplingMethod::Fibonacci, policies(), var).ok());
}

// Over M seeds, the sample variance s^2 of L'_c,i of mc:N (is:N) estimates Var(X)_c,i / N.
// For i.i.d. draws Var(s^2) = (mu4 - sigma^4 (M - 3)/(M - 1)) / M ~ (mu4 - sigma^4) / M, mu4
// the fourth central moment, estimated from the same draws. A correct formula puts
// |s^2 - sigma^2| within 5 of these standard deviations (two-sided normal tail 6e-7 per
// coefficient, 1e-4 over the 2 x 27; the seeds are fixed, so the test is deterministic). The
// test also checks that 5 standard deviations are under 10% of sigma^2, so s^2 is within 2%
// of the true variance and a formula off by a factor of 1.15 or more, or missing a term
// (the - L^2, the 1/N, the is weight), fails. A random 8 x 4 map with a bright texel: is's
// density differs from uniform.
TEST(SampleVariance, MatchesTheVarianceOverSeeds) {
  shpack_test::RgbImage map = shpack_test::uniform_random_image(8, 4, 11, 0.2f, 2.0f);
  map.set(5, 1, 4.0f, 3.0f, 1.0f);
  constexpr std::uint32_t kN = 2;
  constexpr int kSeeds = 32000;
  for (const SamplingMethod method : {SamplingMethod::MonteCarlo, SamplingMethod::Importance}) {
    ShL2 var;
    ASSERT_TRUE(sample_variance(map.view(), method, policies(), var).ok());
    std::vector<ShL2> draws(kSeeds);
    for (int k = 0; k < kSeeds; ++k)
      ASSERT_TRUE(project_with_method(map.view(), {method, kN, 1000u + k}, policies(), draws[k]).ok());
    for (int c = 0; c < kChannelCount; ++c) {
      for (int i = 0; i < kShCount; ++i) {
        double mean = 0;
        for (const ShL2& d : draws) mean += d.c[c][i];
        mean /= kSeeds;
        double m2 = 0, m4 = 0;
        for (const ShL2& d : draws) {
          const double e2 = (d.c[c][i] - mean) * (d.c[c][i] - mean);
          m2 += e2;
          m4 += e2 * e2;
        }
        const double s2 = m2 / (kSeeds - 1);
        m4 /= kSeeds;
        const double sigma2 = var.c[c][i] / kN;
        const double tolerance = 5.0 * std::sqrt((m4 - s2 * s2) / kSeeds);
        EXPECT_LT(tolerance, 0.1 * sigma2) << c << " " << i;
        EXPECT_NEAR(s2, sigma2, tolerance) << (method == SamplingMethod::MonteCarlo ? "mc " : "is ") << c << " " << i;
      }
    }
  }
}

}  // namespace
}  // namespace shpack
