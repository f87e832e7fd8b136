// constants_test.cpp - every constant in sh_basis.h recomputed from std::numbers.
//
// EXPECT_DOUBLE_EQ allows 4 ulp: the literals carry 18 significant digits (correctly
// rounded to double) and the recomputations below take at most 3 roundings (sqrt, two
// products), so a correct constant is within 2 ulp and a truncated one (a 6-digit
// literal, a wrong formula) is off by ~1e-7 relative or more.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "shpack/sh_basis.h"
#include "support/sh_oracle.h"

namespace {

using namespace shpack;
constexpr double kInvSqrtPi = std::numbers::inv_sqrtpi;

TEST(Constants, BasisScalesFromStdNumbers) {
  EXPECT_DOUBLE_EQ(kY0, 0.5 * kInvSqrtPi);                    // 1/(2 sqrt(pi))
  EXPECT_DOUBLE_EQ(kY1, 0.5 * std::numbers::sqrt3 * kInvSqrtPi);  // sqrt(3)/(2 sqrt(pi))
  EXPECT_DOUBLE_EQ(kY2, 0.5 * std::sqrt(15.0) * kInvSqrtPi);  // sqrt(15)/(2 sqrt(pi))
  EXPECT_DOUBLE_EQ(kY20, 0.25 * std::sqrt(5.0) * kInvSqrtPi); // sqrt(5)/(4 sqrt(pi))
  EXPECT_DOUBLE_EQ(kY22, 0.25 * std::sqrt(15.0) * kInvSqrtPi);// sqrt(15)/(4 sqrt(pi))
}

TEST(Constants, BasisScalesMatchTheNormativeDecimals) {
  // docs/conventions.md section 3.
  EXPECT_DOUBLE_EQ(kY0, 0.282094791773878143);
  EXPECT_DOUBLE_EQ(kY1, 0.488602511902919922);
  EXPECT_DOUBLE_EQ(kY2, 1.09254843059207907);
  EXPECT_DOUBLE_EQ(kY20, 0.315391565252520006);
  EXPECT_DOUBLE_EQ(kY22, 0.546274215296039535);
}

TEST(Constants, IndexTablesFollowUnityOrder) {
  // i:      0    1    2    3    4    5    6    7    8
  // k_i:    k0   k1   k1   k1   k2   k2   k3   k2   k4
  const std::array<double, 9> want_k = {kY0, kY1, kY1, kY1, kY2, kY2, kY20, kY2, kY22};
  const std::array<int, 9> want_band = {0, 1, 1, 1, 2, 2, 2, 2, 2};
  for (int i = 0; i < kShCount; ++i) {
    EXPECT_EQ(kBasisScale[i], want_k[i]) << "i=" << i;
    EXPECT_EQ(kBand[i], want_band[i]) << "i=" << i;
  }
  EXPECT_EQ(kShCount, 9);
  EXPECT_EQ(kChannelCount, 3);
  for (int l = 0; l <= 2; ++l)
    for (int m = -l; m <= l; ++m) {
      EXPECT_EQ(sh_index(l, m), l * l + l + m) << "l=" << l << " m=" << m;
      EXPECT_EQ(kBand[sh_index(l, m)], l) << "l=" << l << " m=" << m;
    }
}

TEST(Constants, CosineLobeOverPi) {
  // A_l / pi from the general zonal formula (support/sh_oracle.h): 1, 2/3, 1/4.
  for (int l = 0; l <= 2; ++l)
    EXPECT_DOUBLE_EQ(kCosineLobeOverPi[l], shpack_test::cosine_lobe(l) / std::numbers::pi) << "l=" << l;
  EXPECT_DOUBLE_EQ(kCosineLobeOverPi[0], 1.0);
  EXPECT_DOUBLE_EQ(kCosineLobeOverPi[1], 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(kCosineLobeOverPi[2], 0.25);
}

TEST(Constants, UnityScaleIsLobeOverPiTimesBasisScale) {
  // C_i = (A_l / pi) k_i (docs/conventions.md section 5), each from std::numbers.
  EXPECT_DOUBLE_EQ(kC0, 0.5 * kInvSqrtPi);                                  // k0
  EXPECT_DOUBLE_EQ(kC1, std::numbers::sqrt3 / 3.0 * kInvSqrtPi);            // 2 k1 / 3
  EXPECT_DOUBLE_EQ(kC2, std::sqrt(15.0) / 8.0 * kInvSqrtPi);                // k2 / 4
  EXPECT_DOUBLE_EQ(kC3, std::sqrt(5.0) / 16.0 * kInvSqrtPi);                // k3 / 4
  EXPECT_DOUBLE_EQ(kC4, std::sqrt(15.0) / 16.0 * kInvSqrtPi);               // k4 / 4
  for (int i = 0; i < kShCount; ++i)
    EXPECT_DOUBLE_EQ(kUnityScale[i], kCosineLobeOverPi[kBand[i]] * kBasisScale[i]) << "i=" << i;
  const std::array<double, 9> want = {kC0, kC1, kC1, kC1, kC2, kC2, kC3, kC2, kC4};
  for (int i = 0; i < kShCount; ++i) EXPECT_EQ(kUnityScale[i], want[i]) << "i=" << i;
}

TEST(Constants, UnityScaleMatchesTheNormativeDecimals) {
  EXPECT_DOUBLE_EQ(kC0, 0.282094791773878143);
  EXPECT_DOUBLE_EQ(kC1, 0.325735007935279948);
  EXPECT_DOUBLE_EQ(kC2, 0.273137107648019768);
  EXPECT_DOUBLE_EQ(kC3, 0.0788478913131300015);
  EXPECT_DOUBLE_EQ(kC4, 0.136568553824009884);
}

}  // namespace
