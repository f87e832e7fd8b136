#include "error_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "sampling.h"

namespace shpack::bake {
namespace {

constexpr int kDirections = 96;
constexpr int kDraws = 128;
constexpr int kQuantileIndex = 121;  // the 122nd smallest of 128 = ceil(0.95 * 128): the 95 % quantile
// t_(0.975, 7) / z_0.975 = 2.364624 / 1.959964 (B = 8 batches, 7 degrees of freedom).
constexpr double kKappa = 2.364624 / 1.959964;
static_assert(kBatches == 8, "kKappa is the t quantile for 8 batches");

struct Tables {
  // E/pi basis at the directions: (A_l / pi) Y_i(n), A_l / pi = 1, 2/3, 1/4 (Ramamoorthi and
  // Hanrahan 2001).
  std::array<std::array<double, kShCount>, kDirections> basis{};
  std::array<std::array<double, kBatches>, kDraws> z{};
};

const Tables& tables() {
  static const Tables t = [] {
    Tables out;
    // A Fibonacci lattice: nearly uniform, so the maximum over it is within a few % of the
    // maximum over the sphere for an L2 function (its largest gap is ~ 0.36 rad).
    constexpr double golden = 2.399963229728653;  // pi (3 - sqrt 5)
    for (int n = 0; n < kDirections; ++n) {
      const double y = 1.0 - (2.0 * n + 1.0) / kDirections, s = std::sqrt(1.0 - y * y);
      const std::array<double, kShCount> b = eval_basis(s * std::cos(golden * n), y, s * std::sin(golden * n));
      for (int i = 0; i < kShCount; ++i) out.basis[n][i] = b[i] * (i == 0 ? 1.0 : i < 4 ? 2.0 / 3.0 : 0.25);
    }
    Rng rng(0xe7707e57u);  // Box-Muller on a fixed stream
    for (auto& draw : out.z)
      for (int b = 0; b < kBatches; b += 2) {
        const double r = std::sqrt(-2.0 * std::log(1.0 - rng.uniform())), phi = 2.0 * std::numbers::pi * rng.uniform();
        draw[b] = r * std::cos(phi);
        draw[b + 1] = r * std::sin(phi);
      }
    return out;
  }();
  return t;
}

}  // namespace

ShL2 batch_mean(const Batches& batches) noexcept {
  // Batches that agree (an effect exact at this probe: nothing hidden, or all) give their
  // value as it is, not a sum of eight copies divided by eight.
  if (std::all_of(batches.begin() + 1, batches.end(), [&](const ShL2& x) { return x == batches[0]; })) return batches[0];
  ShL2 mean;
  for (const ShL2& x : batches)
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) mean.c[c][i] += x.c[c][i];
  for (auto& channel : mean.c)
    for (double& v : channel) v /= kBatches;
  return mean;
}

namespace {

// v[b][n]: component b of the mean's error (module comment) as E/pi of channel c at
// direction n; false when every component is 0 (the batches agree).
using Components = std::array<std::array<double, kDirections>, kBatches>;
bool components(const Batches& batches, const ShL2& mean, int c, Components& v) noexcept {
  const Tables& t = tables();
  const double scale = kKappa / std::sqrt(kBatches * (kBatches - 1.0));
  bool any = false;
  for (int b = 0; b < kBatches; ++b) {
    std::array<double, kShCount> d{};
    for (int i = 0; i < kShCount; ++i) {
      d[i] = scale * (batches[b].c[c][i] - mean.c[c][i]);
      any = any || d[i] != 0;
    }
    for (int n = 0; n < kDirections; ++n) {
      double s = 0;
      for (int i = 0; i < kShCount; ++i) s += d[i] * t.basis[n][i];
      v[b][n] = s;
    }
  }
  return any;
}

}  // namespace

ChannelError estimate_error(const Batches& batches) noexcept {
  const Tables& t = tables();
  const ShL2 mean = batch_mean(batches);
  ChannelError out{};
  for (int c = 0; c < kChannelCount; ++c) {
    Components v;
    if (!components(batches, mean, c, v)) continue;
    std::array<double, kDraws> maxima{};
    for (int k = 0; k < kDraws; ++k) {
      double m = 0;
      for (int n = 0; n < kDirections; ++n) {
        double e = 0;
        for (int b = 0; b < kBatches; ++b) e += t.z[k][b] * v[b][n];
        m = std::max(m, std::fabs(e));
      }
      maxima[k] = m;
    }
    std::nth_element(maxima.begin(), maxima.begin() + kQuantileIndex, maxima.end());
    out[c] = maxima[kQuantileIndex];
  }
  return out;
}

ChannelError pointwise_error(const Batches& batches) noexcept {
  const ShL2 mean = batch_mean(batches);
  ChannelError out{};
  for (int c = 0; c < kChannelCount; ++c) {
    Components v;
    if (!components(batches, mean, c, v)) continue;
    for (int n = 0; n < kDirections; ++n) {
      double var = 0;  // Var e(n) = sum_b v_b(n)^2
      for (int b = 0; b < kBatches; ++b) var += v[b][n] * v[b][n];
      out[c] = std::max(out[c], 1.959964 * std::sqrt(var));
    }
  }
  return out;
}

ChannelError combine_errors(const ChannelError& a, const ChannelError& b) noexcept {
  ChannelError out;
  for (int c = 0; c < kChannelCount; ++c) out[c] = std::hypot(a[c], b[c]);
  return out;
}

double error_pct(const ChannelError& error, const ShL2& total) noexcept {
  double brightest = 0;
  for (int c = 0; c < kChannelCount; ++c) brightest = std::max(brightest, total.c[c][0] * kY0);
  double worst = 0;
  for (int c = 0; c < kChannelCount; ++c) {
    if (error[c] == 0) continue;
    if (!(brightest > 0)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, 100.0 * error[c] / std::max(total.c[c][0] * kY0, 0.01 * brightest));
  }
  return worst;
}

}  // namespace shpack::bake
