// error_estimate.h (private) - how wrong a probe's Monte Carlo part may be, from its batches.
//
// Every random effect estimates each probe's SH as the mean of kBatches independent,
// unbiased replicates (independent scrambles of the same point set, sobol.h). Their spread
// measures the error of the mean (batch means): with deviations d_b = X_b - mean, the mean's
// error is close to a Gaussian vector e = sum_b z_b c_b, z_b ~ N(0, 1) independent,
// c_b = kappa d_b / sqrt(B (B - 1)); kappa = t_(0.975, B-1) / z_0.975 widens the Gaussian
// quantile for the variance being estimated from B replicates.
//
// The quantity a user reads is the largest error of E/pi over directions, so the estimate is
// the 95 % quantile of max_n |e_c(n)| (E/pi of channel c at direction n), found by drawing e
// (a multiplier bootstrap: Chernozhukov, Chetverikov, Kato, Ann. Statist. 41(6), 2013) over a
// fixed set of directions. Everything here is deterministic: the draws are a fixed table.
#pragma once

#include <array>

#include "shpack/sh_basis.h"

namespace shpack::bake {

inline constexpr int kBatches = 8;
using Batches = std::array<ShL2, kBatches>;

// Per channel: the 95 % quantile of the largest |error of E/pi| over the sphere.
using ChannelError = std::array<double, kChannelCount>;

ShL2 batch_mean(const Batches& batches) noexcept;

// The error of batch_mean(batches), in E/pi units per channel.
ChannelError estimate_error(const Batches& batches) noexcept;

// 1.96 times the largest standard error of E/pi at one direction: the two-sided 95 % bound at
// that direction, so at most the quantile of the maximum (up to its bootstrap noise), and 30
// times cheaper. batch_sampling.h uses it to skip estimate_error while the target is far.
ChannelError pointwise_error(const Batches& batches) noexcept;

// Independent parts (effects, lights) add in quadrature: the sum of independent Gaussian
// errors has the root sum of their variances, and so, nearly, the quantile of its maximum.
ChannelError combine_errors(const ChannelError& a, const ChannelError& b) noexcept;

// The error in % of the probe's mean E/pi (of `total`), the worst channel. The mean E/pi of
// channel c is L_c,0 Y_0 (A_0 = pi); a channel dimmer than 1 % of the brightest is measured
// against 1 % of the brightest, so a colour channel near zero cannot ask for endless samples.
// 0 when the error is 0; infinite when there is an error and no light.
double error_pct(const ChannelError& error, const ShL2& total) noexcept;

}  // namespace shpack::bake
