// The error estimate of the bake's Monte Carlo effects (lib/bake/src/error_estimate.h) on
// batches whose spread is known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "error_estimate.h"

namespace shpack::bake {
namespace {

// Batches that differ only in L_0 of channel 0, by x_b: the mean's error is then the same in
// every direction, e = (sum_b z_b c_b) Y_0 (A_0 / pi = 1), with c_b = kappa (x_b - mean) /
// sqrt(B (B - 1)): a Gaussian of standard deviation kappa s Y_0 / sqrt(B), s the batches'
// sample standard deviation, kappa = t(0.975, 7) / z(0.975). Its 95 % two-sided quantile is
// 1.96 kappa s Y_0 / sqrt(B): pointwise_error exactly; estimate_error up to the bootstrap's
// 128 fixed draws, whose 95 % quantile of |N(0, 1)| has a standard error of
// sqrt(0.05 0.95 / 128) / (2 phi(1.96)) = 0.165, 8.4 % of 1.96: within 25 % (3 sigma).
TEST(ErrorEstimate, AnL0SpreadGivesTheGaussianQuantile) {
  Batches batches{};
  const double x[kBatches] = {1.0, 1.2, 0.9, 1.1, 0.95, 1.05, 0.8, 1.3};
  double mean = 0;
  for (int b = 0; b < kBatches; ++b) {
    batches[b].c[0][0] = x[b];
    mean += x[b] / kBatches;
  }
  double ss = 0;
  for (const double v : x) ss += (v - mean) * (v - mean);
  const double s = std::sqrt(ss / (kBatches - 1));
  const double kappa = 2.364624 / 1.959964;
  const double want = 1.959964 * kappa * s * kY0 / std::sqrt(kBatches);
  const ChannelError pointwise = pointwise_error(batches), estimate = estimate_error(batches);
  EXPECT_NEAR(pointwise[0], want, 1e-12 * want);
  EXPECT_NEAR(estimate[0], want, 0.25 * want);
  EXPECT_EQ(estimate[1], 0.0) << "the other channels have no spread";
  EXPECT_NEAR(batch_mean(batches).c[0][0], mean, 1e-15);
}

// A spread in a band-1 coefficient is largest at the poles of its axis and 0 on its equator:
// the maximum over directions is what is estimated, never a mean over them.
TEST(ErrorEstimate, TheMaximumOverDirectionsIsEstimatedNotTheMean) {
  Batches batches{};
  for (int b = 0; b < kBatches; ++b) batches[b].c[1][2] = b % 2 ? 0.1 : -0.1;  // z coefficient
  // s = 0.1 sqrt(8 / 7); E/pi error at +z: (2/3) Y_1 e_z, largest over directions.
  const double s = 0.1 * std::sqrt(8.0 / 7.0), kappa = 2.364624 / 1.959964;
  const double want = 1.959964 * kappa * s * (2.0 / 3.0) * kY1 / std::sqrt(kBatches);
  // The 96 directions' nearest to +z is within 0.15 rad of it: cos(0.15) = 0.989.
  EXPECT_NEAR(pointwise_error(batches)[1], want, 0.012 * want);
  EXPECT_NEAR(estimate_error(batches)[1], want, 0.25 * want);
}

TEST(ErrorEstimate, BatchesThatAgreeHaveNoErrorAndTheirValueAsItIs) {
  Batches batches{};
  for (ShL2& b : batches) b.c[2][4] = 0.1;  // 8 * 0.1 / 8 is not 0.1 in double
  EXPECT_EQ(estimate_error(batches), (ChannelError{0, 0, 0}));
  EXPECT_EQ(batch_mean(batches).c[2][4], 0.1);
}

TEST(ErrorEstimate, PercentOfTheMeanUsesTheWorstChannelAndFloorsDimOnes) {
  ShL2 total;
  total.c[0][0] = 1.0 / kY0;  // mean E/pi 1
  total.c[1][0] = 0.5 / kY0;  // 0.5
  total.c[2][0] = 0;          // black: measured against 1 % of the brightest
  EXPECT_DOUBLE_EQ(error_pct({0.01, 0.01, 0}, total), 2.0);
  EXPECT_DOUBLE_EQ(error_pct({0, 0, 0.001}, total), 10.0);
  EXPECT_EQ(error_pct({0, 0, 0}, ShL2{}), 0.0);
  EXPECT_TRUE(std::isinf(error_pct({0.1, 0, 0}, ShL2{})));
  EXPECT_DOUBLE_EQ(combine_errors({3, 0, 1}, {4, 0, 0})[0], 5.0);
}

}  // namespace
}  // namespace shpack::bake
