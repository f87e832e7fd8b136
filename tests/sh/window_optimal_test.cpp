// window_optimal_test.cpp - the nearest non-negative L2 irradiance (window.h, Optimal;
// lib/src/sh/nonnegative_fit.h): against an independent interior-point solution of the same
// problem on dense directions, its KKT certificate, the closed form for a directional light,
// never farther than sloan, no change to a channel that does not ring, scale invariance,
// rotation equivariance, termination on adversarial inputs, and the finish stage's radiance.
//
// Notation: one channel in Unity form s, E/pi(n) = sum_i s_i P_i(n); t the input; the RMS
// distance d(s, t) = sqrt(sum_i w_i (s_i - t_i)^2), w_i the mean of P_i^2 over the sphere
// (from the moments <x^2> = 1/3, <x^4> = 1/5, <x^2 y^2> = 1/15: <(3z^2 - 1)^2> = 4/5,
// <(x^2 - y^2)^2> = 4/15, <(xy)^2> = 1/15). sigma = RMS of t = d(t, 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "sh/nonnegative_fit.h"
#include "shpack/convolution.h"
#include "shpack/pipeline.h"
#include "shpack/rotate.h"
#include "shpack/sh_basis.h"
#include "shpack/sh_minimum.h"
#include "shpack/window.h"
#include "support/dense_qp.h"
#include "support/sh_oracle.h"
#include "support/sphere_points.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

using shpack::Dir3;
using shpack::ShL2;
using Channel = std::array<double, 9>;
constexpr double kPi = std::numbers::pi;
constexpr Channel kWeight = {1, 1.0 / 3, 1.0 / 3, 1.0 / 3, 1.0 / 15, 1.0 / 15, 4.0 / 5, 1.0 / 15, 4.0 / 15};

// The basis polynomials written out (docs/conventions.md section 3), not sh_basis.h.
Channel polynomials(const Dir3& n) {
  return {1, n.y, n.z, n.x, n.x * n.y, n.y * n.z, 3 * n.z * n.z - 1, n.x * n.z, n.x * n.x - n.y * n.y};
}

double value(const Channel& s, const Dir3& n) {
  const Channel p = polynomials(n);
  double sum = 0;
  for (int i = 0; i < 9; ++i) sum += s[i] * p[i];
  return sum;
}

double distance(const Channel& a, const Channel& b) {
  double sum = 0;
  for (int i = 0; i < 9; ++i) sum += kWeight[i] * (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum);
}

double rms(const Channel& s) { return distance(s, Channel{}); }

ShL2 single(const Channel& s) {
  ShL2 out;
  out.c[0] = s;
  return out;
}

double minimum(const Channel& s) { return shpack::minimum_on_sphere(single(s), 0).value; }

// Unity form of directional lights of irradiance e[k] from d[k] (radiance E Y_i(d), Y by the
// Legendre route), plus a uniform radiance `ambient`.
Channel lights(const std::vector<Dir3>& d, const std::vector<double>& e, double ambient = 0) {
  ShL2 radiance;
  radiance.c[0][0] = ambient * 2 * std::sqrt(kPi);
  for (std::size_t k = 0; k < d.size(); ++k) {
    const std::array<double, 9> y = unity_basis_slow(d[k].x, d[k].y, d[k].z);
    for (int i = 0; i < 9; ++i) radiance.c[0][i] += e[k] * y[i];
  }
  return shpack::radiance_to_unity_form(radiance).c[0];
}

// A random channel that rings with L00 >= 0: one to three lights spanning three decades on
// a dim ambient, then (for odd `kind`) every coefficient moved by up to 30 % of L00.
Channel random_ringing(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> u(0, 1);
  for (;;) {
    const int count = 1 + static_cast<int>(rng() % 3);
    std::vector<Dir3> d;
    std::vector<double> e;
    for (int k = 0; k < count; ++k) d.push_back(random_direction(rng)), e.push_back(std::pow(10.0, 3 * u(rng)));
    Channel s = lights(d, e, 0.01 * u(rng) * e[0]);
    if (kind % 2 == 1)
      for (int i = 1; i < 9; ++i) s[i] += 0.3 * (2 * u(rng) - 1) * s[0];
    if (minimum(s) < 0 && s[0] >= 0) return s;
  }
}

shpack::NonnegativeFit fit(const Channel& t) { return shpack::nearest_nonnegative(single(t), 0); }

shpack::Window optimal() {
  shpack::Window w;
  EXPECT_TRUE(shpack::parse_window("optimal", w).ok());
  return w;
}

TEST(WindowOptimal, WeightsAreTheMeanSquaresOfTheBasisPolynomials) {
  // rms_weight(i) = (k0 / k_i)^2 from the basis constants; the moments give the same
  // fractions (header). Two roundings in the constants and three operations: 8u.
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(shpack::rms_weight(i), kWeight[i], 8 * kU * kWeight[i]) << "i=" << i;
}

TEST(WindowOptimal, DenseQpOracleSolvesClosedFormCones) {
  // The oracle itself on cones with a closed-form projection: the non-negative orthant
  // (x = max(t, 0)) and one half-space g . x >= 0 (x = t - min(0, g.t) W^-1 g / (g^T W^-1 g)).
  // Its error is within sqrt(gap) in the W-norm, gap (about 2e-10) certified by duality
  // (dense_qp.h).
  const std::vector<double> w = {1, 0.5, 2};
  const std::vector<double> t = {0.5, -0.4, -0.3};
  const std::vector<double> orthant = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const DenseQpResult a = dense_nearest_in_cone(w, t, orthant, {1, 1, 1});
  ASSERT_TRUE(a.converged);
  const double tol = std::sqrt(a.gap);
  EXPECT_NEAR(a.x[0], 0.5, tol);
  EXPECT_NEAR(a.x[1], 0.0, tol / std::sqrt(w[1]));
  EXPECT_NEAR(a.x[2], 0.0, tol / std::sqrt(w[2]));
  const std::vector<double> g = {1, 2, -1};
  const DenseQpResult b = dense_nearest_in_cone(w, t, g, {1, 1, 0});
  ASSERT_TRUE(b.converged);
  const double gt = g[0] * t[0] + g[1] * t[1] + g[2] * t[2];  // -0.005 < 0: the constraint binds
  double gwg = 0;
  for (int i = 0; i < 3; ++i) gwg += g[i] * g[i] / w[i];
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(b.x[i], t[i] - gt / gwg * g[i] / w[i], std::sqrt(b.gap) / std::sqrt(w[i])) << "i=" << i;
}

TEST(WindowOptimal, MatchesADenseInteriorPointSolution) {
  // The same problem on N Fibonacci directions only, solved by the interior-point oracle
  // (dense_qp.h) in the normalised input t/sigma (so its objective starts at 1). Let x_D be
  // its solution (gap g: x_D is within sqrt(g) of the dense optimum x_D*), s ours.
  //  - s is non-negative everywhere, so feasible for the dense problem:
  //    d(s) >= d(x_D*) >= sqrt(d(x_D)^2 - g).
  //  - x_D is >= 0 at the N points but may dip between them to -eta, eta = -(its exact
  //    minimum); x_D + eta (a constant) is feasible for the whole sphere, so the optimum
  //    d* <= d(x_D) + eta, and ours is within its final raise r of d*:
  //    d(s) <= d(x_D) + eta + r.
  //  - Projection onto the dense cone: ||s - x_D*||^2 <= d(s)^2 - d(x_D*)^2, hence
  //    ||s - x_D|| <= sqrt(d(s)^2 - d(x_D)^2 + g) + sqrt(g).
  // The density bounds eta a priori: at the minimiser n* of x_D the tangential gradient
  // vanishes, so within the covering radius rho of n* lies a point p with
  // 0 <= x_D(p) <= x_D(n*) + H rho^2 / 2, H >= |f''| along great circles; for
  // f = c + b.n + n^T A n (sh_minimum.h), f'' = -b.n + 2 v^T A v - 2 n^T A n, so
  // H = |b| + 4 ||A||_F. Fibonacci's covering radius measures 0.76 sqrt(4 pi / N) (2e5 random
  // probes at N = 500 and 3000); rho = sqrt(4 pi / N) is used.
  // Rounding: every distance is a sum of 9 terms of size <= 1 (relative units): 1e-14.
  constexpr int kPoints = 3000;
  const std::vector<Dir3> points = fibonacci_sphere(kPoints);
  std::vector<double> rows;
  for (const Dir3& p : points)
    for (const double v : polynomials(p)) rows.push_back(v);
  const std::vector<double> weights(kWeight.begin(), kWeight.end());
  const double rho = std::sqrt(4 * kPi / kPoints);
  constexpr double kRound = 1e-14;
  std::mt19937_64 rng(0x5eed);
  double worst_gap = 0, worst_eta_ratio = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Channel t = random_ringing(rng, trial);
    const double sigma = rms(t);
    Channel unit;
    for (int i = 0; i < 9; ++i) unit[i] = t[i] / sigma;
    const shpack::NonnegativeFit f = fit(t);
    Channel s;
    for (int i = 0; i < 9; ++i) s[i] = f.unity_form[i] / sigma;
    const double raise = f.raise / sigma;
    const DenseQpResult dense = dense_nearest_in_cone(weights, std::vector<double>(unit.begin(), unit.end()), rows,
                                                      {1, 0, 0, 0, 0, 0, 0, 0, 0});
    ASSERT_TRUE(dense.converged) << "trial " << trial;
    Channel xd;
    std::copy(dense.x.begin(), dense.x.end(), xd.begin());
    const double eta = std::max(0.0, -minimum(xd));
    const double b_norm = std::hypot(xd[3], xd[1], xd[2]);
    const double a_frob = std::sqrt(2 * xd[8] * xd[8] + 9 * xd[6] * xd[6] +
                                    0.5 * (xd[4] * xd[4] + xd[5] * xd[5] + xd[7] * xd[7]));
    const double eta_bound = (b_norm + 4 * a_frob) * rho * rho / 2;
    EXPECT_LE(eta, eta_bound) << "trial " << trial;
    const double ds = distance(s, unit), dd = distance(xd, unit);
    EXPECT_GE(ds, std::sqrt(std::max(0.0, dd * dd - dense.gap)) - kRound) << "trial " << trial;
    EXPECT_LE(ds, dd + eta + raise + kRound) << "trial " << trial;
    EXPECT_LE(distance(s, xd), std::sqrt(std::max(0.0, ds * ds - dd * dd + dense.gap)) + std::sqrt(dense.gap) + kRound)
        << "trial " << trial;
    EXPECT_LT(f.planes, shpack::kMaxFitPlanes) << "trial " << trial << ": converged before the cap";
    worst_gap = std::max(worst_gap, ds - dd);
    worst_eta_ratio = std::max(worst_eta_ratio, eta / eta_bound);
  }
  std::cout << "[ measure  ] optimal vs dense QP (" << kPoints << " points): max d(ours) - d(dense) = " << worst_gap
            << " sigma; dense solution's dip between points up to " << worst_eta_ratio << " of its density bound\n";
}

TEST(WindowOptimal, SatisfiesTheKktConditions) {
  // The certificate of the last QP (nonnegative_fit.h), with s_qp = s - raise e_0:
  //  - multipliers lambda_k >= 0;
  //  - stationarity: w_i (s_qp,i - t_i) = sum_k lambda_k P_i(n_k). The code forms it as
  //    u = u0 + B^T x in (m + 1)-term sums, then scales by a few roundings; this test sums it
  //    again: 4 (m + 8) u (w_i (|s_i| + |t_i|) + sum_k |lambda_k P_i(n_k)|) covers both;
  //  - complementarity: where lambda_k > 0, |E/pi_qp(n_k)| <= kFitTolerance sigma (the
  //    method asks no more of any plane; an active one is solved as an equation by QR, to
  //    rounding times the conditioning of at most 9 columns);
  //  - feasibility: the exact minimum of s is >= 0.
  // Sufficiency, as a number: for any non-negative y, d(y)^2 >= d(s_qp)^2 -
  // 2 sum_k lambda_k E/pi_qp(n_k) - 2 |e . (y - s_qp)| (expand d(y)^2 about s_qp; y >= 0 at
  // every n_k). Coefficient 0 of stationarity reads sum_k lambda_k = s_qp,0 - t_0 <= sigma,
  // so the optimum d* >= sqrt(d(s_qp)^2 - 2 kFitTolerance sigma^2) and ours, d(s) <=
  // d(s_qp) + raise, is within raise + 2 kFitTolerance sigma^2 / d(s_qp) of it.
  std::mt19937_64 rng(0x5eed);
  double worst_certified = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Channel t = random_ringing(rng, trial);
    const shpack::NonnegativeFit f = fit(t);
    const double sigma = rms(t);
    Channel s_qp = f.unity_form;
    s_qp[0] -= f.raise;
    EXPECT_GE(minimum(f.unity_form), 0.0) << "trial " << trial;
    EXPECT_GE(f.raise, 0.0);
    // The loop stops at a deficit <= kFitTolerance sigma; the rounding steps after it add
    // at most 2 x the evaluation error of E/pi, 10u sum |s_i P_i| <= 180u max |s_i|.
    double largest = 0;
    for (const double v : f.unity_form) largest = std::max(largest, std::fabs(v));
    EXPECT_LE(f.raise, shpack::kFitTolerance * sigma + 360 * kU * largest)
        << "trial " << trial << ": stopped within tolerance";
    double complementarity = 0;
    for (int i = 0; i < 9; ++i) {
      double sum = 0, size = kWeight[i] * (std::fabs(f.unity_form[i]) + std::fabs(t[i]));
      for (int k = 0; k < f.planes; ++k) {
        sum += f.multipliers[k] * polynomials(f.directions[k])[i];
        size += std::fabs(f.multipliers[k] * polynomials(f.directions[k])[i]);
      }
      EXPECT_NEAR(kWeight[i] * (s_qp[i] - t[i]), sum, 4 * (f.planes + 8) * kU * size)
          << "trial " << trial << " i=" << i;
    }
    for (int k = 0; k < f.planes; ++k) {
      EXPECT_GE(f.multipliers[k], 0.0) << "trial " << trial << " k=" << k;
      if (f.multipliers[k] == 0) continue;
      const double e = value(s_qp, f.directions[k]);
      EXPECT_LE(std::fabs(e), shpack::kFitTolerance * sigma) << "trial " << trial << " k=" << k;
      complementarity += f.multipliers[k] * e;
    }
    const double dqp = distance(s_qp, t), ds = distance(f.unity_form, t);
    const double lower = std::sqrt(std::max(0.0, dqp * dqp - 2 * std::fabs(complementarity)));
    EXPECT_LE(ds - lower, f.raise + 2 * shpack::kFitTolerance * sigma * sigma / dqp + 1e-14 * sigma)
        << "trial " << trial;
    worst_certified = std::max(worst_certified, (ds - lower) / sigma);
  }
  std::cout << "[ measure  ] optimal: certified distance to the optimum <= " << worst_certified << " sigma\n";
}

TEST(WindowOptimal, DirectionalLightMatchesTheZonalClosedForm) {
  // A light from d with E / (4 pi) = 1: t = (a0, b0, c0) = (1, 2, 5/8) in the zonal terms
  // f = a + b t + c (3t^2 - 1), t = n.d (s0 = E/4pi, s along d = E/2pi, s6 = 5E/32pi).
  // Rotations about d leave the input and the non-negative cone alone and the objective is
  // strictly convex, so the unique optimum is zonal; in the d frame its objective is
  // (a - a0)^2 + (b - b0)^2 / 3 + (4/5)(c - c0)^2 and its constraint g(t) = 3c t^2 + b t +
  // (a - c) >= 0 on [-1, 1]. The light rings on a circle inside (-1, 1) (t = -8/15); suppose
  // the optimum touches 0 on a circle t = tau: g = 3c (t - tau)^2, c > 0, i.e.
  //   b = -6 c tau,   a - c = 3 c tau^2.
  // Stationarity with a uniform multiplier of mass mu on that circle (its mean of P is the
  // zonal (1, tau, 3 tau^2 - 1)): a - a0 = mu, (b - b0)/3 = mu tau, (4/5)(c - c0) =
  // mu (3 tau^2 - 1). Eliminating a, b, c:
  //   mu = -(b0 + 6 c0 tau) / (4.5 tau (5 tau^2 - 1)),
  //   5 b0 tau^4 + (10 a0 - 4 c0) tau^3 - (2 a0 + 4 c0) tau - b0 = 0,
  // here 20 tau^4 + 15 tau^3 - 9 tau - 4 = 0: 10 at -1, -0.52 at -1/sqrt(5), decreasing
  // between (derivative 80 tau^3 + 45 tau^2 - 9 < 0 there), so one root, tau = -0.51587
  // (121.06 degrees from the light). If then mu > 0 and c > 0 the point is feasible and
  // stationary with a non-negative multiplier supported where g = 0: sufficient for a convex
  // problem, so it is the optimum. The Unity form of a + b (n.d) + c (3 (n.d)^2 - 1):
  //   s0 = a, (s3, s1, s2) = b d, s4 = 6c dx dy, s5 = 6c dy dz, s6 = c (3 dz^2 - 1)/2,
  //   s7 = 6c dx dz, s8 = (3/2) c (dx^2 - dy^2).
  // Tolerances: ours is within its raise r of d* in RMS distance, and by projection
  // ||s - s*||^2 <= d(s)^2 - d*^2 (the distances carry 1e-14 of rounding each, so their
  // squares' difference is known to 4 d* 1e-14). A plane with lambda > 0 has E/pi_qp = 0
  // there (to kFitTolerance sigma, above); E/pi_qp is within eps = 3 ||s_qp - s*|| of f*
  // everywhere (Cauchy-Schwarz with sum_i P_i^2 / w_i = 4 pi sum_i Y_i^2 = 9), and
  // f* = 3c (t - tau)^2, so that plane's t is within sqrt(eps / 3c) of tau.
  long double lo = -1, hi = -1 / std::sqrt(5.0L);
  auto quartic = [](long double x) { return ((20 * x + 15) * x * x - 9) * x - 4; };
  for (int it = 0; it < 200; ++it) ((quartic((lo + hi) / 2) > 0) ? lo : hi) = (lo + hi) / 2;
  const double tau = static_cast<double>((lo + hi) / 2);
  const double a0 = 1, b0 = 2, c0 = 5.0 / 8;
  const double mu = -(b0 + 6 * c0 * tau) / (4.5 * tau * (5 * tau * tau - 1));
  const double a = a0 + mu, b = b0 + 3 * mu * tau, c = c0 + 1.25 * mu * (3 * tau * tau - 1);
  ASSERT_GT(mu, 0.0);
  ASSERT_GT(c, 0.0);
  EXPECT_NEAR(b, -6 * c * tau, 1e-14) << "the double root of the derivation";
  EXPECT_NEAR(a - c, 3 * c * tau * tau, 1e-14);
  const double d_star = std::sqrt(mu * mu + (b - b0) * (b - b0) / 3 + 0.8 * (c - c0) * (c - c0));
  std::mt19937_64 rng(0x5eed);
  std::vector<Dir3> dirs = {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}};
  for (int k = 0; k < 8; ++k) dirs.push_back(random_direction(rng));
  for (const Dir3& d : dirs) {
    const Channel t = lights({d}, {4 * kPi});
    const Channel want = {a, b * d.y, b * d.z, b * d.x, 6 * c * d.x * d.y, 6 * c * d.y * d.z,
                          c * (3 * d.z * d.z - 1) / 2, 6 * c * d.x * d.z, 1.5 * c * (d.x * d.x - d.y * d.y)};
    EXPECT_NEAR(distance(want, t), d_star, 1e-14) << "d=" << d;
    const shpack::NonnegativeFit f = fit(t);
    const double ds = distance(f.unity_form, t);
    EXPECT_NEAR(ds, d_star, f.raise + 1e-14) << "d=" << d;
    const double slack = std::sqrt(4 * d_star * 1e-14);
    EXPECT_LE(distance(f.unity_form, want), std::sqrt(std::max(0.0, ds * ds - d_star * d_star)) + slack) << "d=" << d;
    Channel s_qp = f.unity_form;
    s_qp[0] -= f.raise;
    const double dqp = distance(s_qp, t);
    const double eps = 3 * (std::sqrt(std::max(0.0, dqp * dqp - d_star * d_star)) + slack) +
                       shpack::kFitTolerance * rms(t);
    for (int k = 0; k < f.planes; ++k) {  // the active planes lie on the ring
      if (f.multipliers[k] == 0) continue;
      const Dir3& n = f.directions[k];
      EXPECT_NEAR(n.x * d.x + n.y * d.y + n.z * d.z, tau, std::sqrt(eps / (3 * c))) << "d=" << d << " k=" << k;
    }
  }
  // Through the public window: the same, and its RMS change in units of the input's RMS.
  ShL2 in, out;
  in.c = {lights({{0, 1, 0}}, {4 * kPi}), lights({{0, 1, 0}}, {4 * kPi}), lights({{0, 1, 0}}, {4 * kPi})};
  shpack::WindowResult result;
  ASSERT_TRUE(shpack::apply_window(in, optimal(), out, &result).ok());
  for (int c2 = 0; c2 < 3; ++c2) {
    EXPECT_NEAR(result.rms_change[c2], d_star / rms(in.c[c2]), 1e-9) << "c=" << c2;
    EXPECT_GT(result.planes[c2], 0);
    EXPECT_FALSE(result.impossible[c2]);
    for (const double factor : result.factors[c2]) EXPECT_TRUE(std::isnan(factor)) << "no per-band factor";
  }
  std::cout << "[ measure  ] directional light: optimal RMS change " << 100 * d_star / rms(in.c[0])
            << " % of the RMS of E/pi, touching 0 on the circle at " << std::acos(tau) * 180 / kPi << " deg\n";
}

TEST(WindowOptimal, IsNeverFartherThanSloan) {
  // Sloan's result is non-negative (when possible), so a candidate: d(optimal) <=
  // d(sloan) + raise, raise <= kFitTolerance sigma + 360u max |s_i| (above), and
  // |s_i| <= RMS(s) / sqrt(w_i) <= 2 sqrt(15) sigma (RMS(s) <= sigma + d(s, t) <= 2 sigma).
  std::mt19937_64 rng(0x5eed);
  shpack::Window sloan;
  ASSERT_TRUE(shpack::parse_window("sloan", sloan).ok());
  double mean_ratio = 0;
  constexpr int kTrials = 30;
  for (int trial = 0; trial < kTrials; ++trial) {
    ShL2 in;
    for (auto& ch : in.c) ch = random_ringing(rng, trial);
    ShL2 by_sloan, by_optimal;
    shpack::WindowResult rs, ro;
    ASSERT_TRUE(shpack::apply_window(in, sloan, by_sloan, &rs).ok());
    ASSERT_TRUE(shpack::apply_window(in, optimal(), by_optimal, &ro).ok());
    for (int c = 0; c < 3; ++c) {
      const double sigma = rms(in.c[c]);
      EXPECT_GE(minimum(by_optimal.c[c]), 0.0);
      const double raise = shpack::kFitTolerance * sigma + 720 * kU * std::sqrt(15.0) * sigma;
      EXPECT_LE(distance(by_optimal.c[c], in.c[c]), distance(by_sloan.c[c], in.c[c]) + raise)
          << "trial " << trial << " c=" << c;
      EXPECT_NEAR(ro.rms_change[c] * sigma, distance(by_optimal.c[c], in.c[c]), 1e-14 * sigma);
      EXPECT_NEAR(rs.rms_change[c] * sigma, distance(by_sloan.c[c], in.c[c]), 1e-14 * sigma);
      mean_ratio += ro.rms_change[c] / rs.rms_change[c] / (3 * kTrials);
    }
  }
  std::cout << "[ measure  ] RMS change of optimal / sloan, mean over random ringing channels: " << mean_ratio << "\n";
}

TEST(WindowOptimal, LeavesWhatNeedsNoFitAlone) {
  // A channel that does not ring: bit for bit. L00 < 0 and ringing: unchanged, impossible.
  // Non-finite: unchanged (the float32 check of the finish stage refuses it). All zero: 0.
  ShL2 in;
  in.c[0] = {1.0, 0.1, -0.05, 0.2, 0.01, 0, 0.02, 0, -0.01};
  in.c[1] = {-0.5, 0.3, 0, 0, 0, 0, 0, 0, 0};
  in.c[2] = {1.0, std::numeric_limits<double>::infinity(), 0, 0, 0, 0, 0, 0, 0};
  ASSERT_GE(minimum(in.c[0]), 0.0);
  ShL2 out;
  shpack::WindowResult result;
  ASSERT_TRUE(shpack::apply_window(in, optimal(), out, &result).ok());
  EXPECT_EQ(out.c[0], in.c[0]);
  EXPECT_EQ(result.rms_change[0], 0.0);
  EXPECT_EQ(result.planes[0], 0);
  EXPECT_FALSE(result.impossible[0]);
  EXPECT_EQ(out.c[1], in.c[1]);
  EXPECT_TRUE(result.impossible[1]);
  EXPECT_EQ(out.c[2], in.c[2]);
  EXPECT_FALSE(result.impossible[2]);
  ShL2 zero, zero_out;
  ASSERT_TRUE(shpack::apply_window(zero, optimal(), zero_out, &result).ok());
  EXPECT_EQ(zero_out, zero);
  // The window is named and parsed like the others, and has no per-band factors.
  EXPECT_STREQ(shpack::window_name(optimal()).text, "optimal");
  shpack::Window w;
  EXPECT_EQ(shpack::parse_window("optimal:2", w).code, shpack::Errc::InvalidArgument);
  std::array<double, 3> f{};
  EXPECT_EQ(shpack::window_factors(optimal(), f).code, shpack::Errc::InvalidArgument);
  EXPECT_FALSE(shpack::scales_bands(shpack::WindowKind::Optimal));
  EXPECT_TRUE(shpack::scales_bands(shpack::WindowKind::Sloan));
}

TEST(WindowOptimal, IsScaleInvariant) {
  // Homogeneous problem, solved after an exact scaling by a power of 2 (nonnegative_fit.h):
  // another power of 2 changes no rounding, so the result scales bit for bit, out to 2^-1000
  // and 2^900, where sh_minimum.h could not be trusted on the unscaled numbers (their
  // squares under- or overflow) - but for coefficient 0's last correction, each at most
  // 128 + 2 + 4 + ... + 256 < 640 eps max |s_i| (nonnegative_fit.cpp), so 1280 for two. For 1e-6 and 1e6 the
  // scaled inputs differ by rounding (1u per coefficient) and each result is within its raise
  // r of the optimum a s*: the distances agree to the raises, and the coefficients to
  // sqrt((d + r)^2 - d^2) each (projection).
  std::mt19937_64 rng(0x5eed);
  for (int trial = 0; trial < 10; ++trial) {
    const Channel t = random_ringing(rng, trial);
    const shpack::NonnegativeFit base = fit(t);
    for (const double a : {0x1p-40, 0x1p+40, 0x1p-1000, 0x1p+900}) {
      Channel ta;
      for (int i = 0; i < 9; ++i) ta[i] = a * t[i];
      const shpack::NonnegativeFit scaled = fit(ta);
      double largest = 0;
      for (const double v : base.unity_form) largest = std::max(largest, std::fabs(v));
      EXPECT_NEAR(scaled.unity_form[0], a * base.unity_form[0], 1280 * kEps * a * largest) << "a=" << a;
      for (int i = 1; i < 9; ++i) EXPECT_EQ(scaled.unity_form[i], a * base.unity_form[i]) << "a=" << a << " i=" << i;
      EXPECT_EQ(scaled.planes, base.planes);
    }
    const double d = distance(base.unity_form, t);
    for (const double a : {1e-6, 1e6}) {
      Channel ta, back;
      for (int i = 0; i < 9; ++i) ta[i] = a * t[i];
      const shpack::NonnegativeFit scaled = fit(ta);
      for (int i = 0; i < 9; ++i) back[i] = scaled.unity_form[i] / a;
      const double r = base.raise + scaled.raise / a + 1e-15 * rms(t);
      EXPECT_NEAR(distance(back, t), d, r) << "a=" << a;
      EXPECT_LE(distance(back, base.unity_form), 2 * std::sqrt((d + r) * (d + r) - d * d)) << "a=" << a;
      EXPECT_GE(minimum(scaled.unity_form), 0.0);
    }
  }
}

// The Unity form of the environment turned by r (rotate.h), turned as radiance: the Unity
// form's band-2 scale differs between indices (k2/4, k3/4, k4/4), so a rotation of band 2
// does not commute with it.
Channel rotated(const Channel& s, const shpack::Matrix3& r) {
  ShL2 radiance, turned;
  for (int i = 0; i < 9; ++i) radiance.c[0][i] = s[i] / shpack::kUnityScale[i];
  EXPECT_TRUE(shpack::rotate(radiance, r, turned).ok());
  return shpack::radiance_to_unity_form(turned).c[0];
}

TEST(WindowOptimal, IsRotationEquivariant) {
  // The non-negative cone and the RMS are rotation invariant, so the exact answer commutes
  // with rotations: fit(R t) = R fit(t). Ours differ from the exact ones by their raises r
  // (in distance) and by sqrt((d + r)^2 - d^2) each in coefficients (projection), plus the
  // rounding of turning t (a few u per coefficient: 1e-14 sigma).
  std::mt19937_64 rng(0x5eed);
  const shpack::Matrix3 cycle = {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}};  // x -> y -> z -> x
  for (int trial = 0; trial < 10; ++trial) {
    const Channel t = random_ringing(rng, trial);
    const shpack::Matrix3 yaw = shpack::rotation_about_y(17.0 + 29.0 * trial);
    shpack::Matrix3 r{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) r[i][j] += cycle[i][k] * yaw[k][j];
    const Channel rt = rotated(t, r);
    const shpack::NonnegativeFit f = fit(t), g = fit(rt);
    const Channel rf = rotated(f.unity_form, r);
    const double d = distance(f.unity_form, t), sigma = rms(t);
    const double raises = f.raise + g.raise + 1e-14 * sigma;
    EXPECT_NEAR(distance(g.unity_form, rt), d, raises) << "trial " << trial;
    EXPECT_LE(distance(g.unity_form, rf), 2 * std::sqrt((d + raises) * (d + raises) - d * d) + 1e-14 * sigma)
        << "trial " << trial;
  }
}

TEST(WindowOptimal, TerminatesOnAdversarialInputs) {
  // Each ends non-negative (exact minimum), finite, within the plane cap, and no farther
  // from t than E/pi = 0 (a candidate) plus the raise.
  const Channel delta = lights({{0, 0, 1}}, {4 * kPi});
  const Channel opposite = lights({{0, 0, 1}, {0, 0, -1}}, {1.0, 1e-12});
  struct Case {
    const char* name;
    Channel t;
  };
  std::vector<Case> cases = {
      {"pure band 2, zonal", {0, 0, 0, 0, 0, 0, 1, 0, 0}},
      {"pure band 2, xy", {0, 0, 0, 0, 1, 0, 0, 0, 0}},
      {"pure band 1, s0 = 0", {0, 1, 0, 0, 0, 0, 0, 0, 0}},
      {"s0 = 0, bands 1 and 2", {0, 0.3, 0.1, 0, 0, 0.05, 0, 0, 0}},
      {"delta light", delta},
      {"two opposite deltas, 1 and 1e-12", opposite},
      {"huge dynamic range", {1e-20, 1e10, 0, 0, 0, 0, 0, 0, 1e-30}},
      {"delta at 1e-300", {}},
      {"delta at 1e30", {}},
      {"two lights 1e12 apart", lights({{0, 1, 0}, {1, 0, 0}}, {1.0, 1e12})},
      // Found by fuzz_sh_minimum: a flat zero set where sh_minimum.h finds a point 1 ulp of
      // s0 lower on the unscaled result than on the scaled one.
      {"xz lobe on 1e-19", {9.9999988079071048e-20, 9.9999988079071048e-20, 9.9999988079071048e-20,
                            9.9999988079071048e-20, 9.9999988079071048e-20, 9.9999988079071048e-20,
                            9.9999988079071048e-20, 9.999694824218751e+18, 0}},
  };
  for (int i = 0; i < 9; ++i) cases[7].t[i] = 1e-300 * delta[i], cases[8].t[i] = 1e30 * delta[i];
  for (const Case& k : cases) {
    ASSERT_LT(minimum(k.t), 0.0) << k.name << " must ring";
    const shpack::NonnegativeFit f = fit(k.t);
    for (const double s : f.unity_form) EXPECT_TRUE(std::isfinite(s)) << k.name;
    EXPECT_LE(f.planes, shpack::kMaxFitPlanes) << k.name;
    // Checked on everything divided by 2^e ~ max |t_i| (exact), so that no square in the
    // distances or in sh_minimum.h under- or overflows (1e-300, 1e30 squared is fine).
    double largest = 0;
    for (const double v : k.t) largest = std::max(largest, std::fabs(v));
    int e = 0;
    std::frexp(largest, &e);
    Channel t, s;
    for (int i = 0; i < 9; ++i) t[i] = std::ldexp(k.t[i], -e), s[i] = std::ldexp(f.unity_form[i], -e);
    EXPECT_GE(minimum(s), 0.0) << k.name;
    if (e > -400 && e < 400) {  // where sh_minimum.h's squares stay in range (1e+-120)
      EXPECT_GE(minimum(f.unity_form), 0.0) << k.name << ": as the finish stage sees it";
    }
    EXPECT_LE(distance(s, t), rms(t) * (1 + 1e-14) + std::ldexp(f.raise, -e)) << k.name;
    std::cout << "[ measure  ] " << k.name << ": " << f.planes << " planes, raise " << std::ldexp(f.raise, -e) / rms(t)
              << " sigma\n";
  }
  // Two equal opposite deltas cancel band 1 and do not ring: unchanged.
  const Channel both = lights({{0, 0, 1}, {0, 0, -1}}, {1.0, 1.0});
  EXPECT_GE(minimum(both), 0.0);
}

TEST(WindowOptimal, FinishStageKeepsTheRadianceConsistent) {
  // finish_projection with optimal: radiance = unity form / kUnityScale (convolution.h) for a
  // fitted channel (one division: 1u, and radiance_to_unity_form's one product back: 2u of
  // each coefficient), bit for bit the unwindowed radiance for a channel left alone. For the
  // per-band windows the radiance is still the input's times the factors, bit for bit.
  ShL2 radiance;
  const std::array<double, 9> y = unity_basis_slow(0.6, 0.0, 0.8);
  for (int i = 0; i < 9; ++i) radiance.c[0][i] = 3.0 * y[i], radiance.c[1][i] = 5.0 * y[i];
  radiance.c[2][0] = 1.0;  // uniform: does not ring
  shpack::FinishOptions options;
  options.window = optimal();
  shpack::FinishedSh fitted, plain;
  ASSERT_TRUE(shpack::finish_projection(radiance, options, fitted).ok());
  ASSERT_TRUE(shpack::finish_projection(radiance, shpack::FinishOptions{}, plain).ok());
  const ShL2 back = shpack::radiance_to_unity_form(fitted.radiance);
  for (int c = 0; c < 2; ++c) {
    EXPECT_GE(fitted.min_e_over_pi[c].value, 0.0) << "c=" << c;
    for (int i = 0; i < 9; ++i)
      EXPECT_NEAR(back.c[c][i], fitted.unity_form.c[c][i], 2 * kU * std::fabs(fitted.unity_form.c[c][i])) << "c=" << c;
  }
  EXPECT_EQ(fitted.radiance.c[2], plain.radiance.c[2]);
  EXPECT_EQ(fitted.unity_form.c[2], plain.unity_form.c[2]);
  for (const char* name : {"sloan", "hanning:2.5", "unity"}) {
    shpack::FinishOptions banded;
    ASSERT_TRUE(shpack::parse_window(name, banded.window).ok());
    shpack::FinishedSh out;
    ASSERT_TRUE(shpack::finish_projection(radiance, banded, out).ok());
    EXPECT_EQ(out.radiance, shpack::apply_band_factors(radiance, out.window.factors)) << name;
  }
}

TEST(WindowOptimal, InL1ItIsTheClosedFormConeProjection) {
  // An L1 channel (band 2 zero) that rings: its fit stays L1, has minimum s0 - |s| >= 0 (0
  // up to the ulps it is raised by), and satisfies the KKT conditions of minimise
  // (s0 - t0)^2 + |s - t|^2 / 3 s.t. s0 - |s| >= 0 (nonnegative_fit.h): with multiplier
  // lambda = 2 (s0 - t0) >= 0, the stationarity of band 1 reads s - t = -3 (s0 - t0) s/|s|.
  std::mt19937_64 rng(11);
  for (int k = 0; k < 200; ++k) {
    Channel t = random_ringing(rng, k);
    for (int i = 4; i < 9; ++i) t[i] = 0;
    if (!(t[0] - std::hypot(t[1], t[2], t[3]) < 0) || t[0] < 0) continue;
    ShL2 out;
    ASSERT_TRUE(shpack::apply_window(single(t), optimal(), out, nullptr, /*l1=*/true).ok());
    const Channel& s = out.c[0];
    for (int i = 4; i < 9; ++i) EXPECT_EQ(s[i], 0.0) << k;
    const double length = std::hypot(s[1], s[2], s[3]), scale = std::fabs(t[0]) + std::hypot(t[1], t[2], t[3]);
    EXPECT_GE(minimum(s), 0.0) << k;
    EXPECT_LE(std::fabs(s[0] - length), 8 * kU * scale) << k;  // on the cone's boundary: active constraint
    EXPECT_GE(s[0] - t[0], 0.0) << k;
    for (int i = 1; i <= 3; ++i)
      EXPECT_NEAR(s[i] - t[i], -3 * (s[0] - t[0]) * s[i] / length, 16 * kU * scale) << k << " i=" << i;
  }
}

TEST(WindowOptimal, WithL1TheFinishedEOverPiIsNonNegative) {
  // A directional light's L1 part, (1 + 2 n.d) / (4 pi) per unit irradiance, rings; with
  // --window optimal --l1 (and sloan --l1) what Unity shows must not be negative anywhere.
  // (The L1 part of the non-negative L2 fit need not be non-negative: the window must act on
  // the L1 function.)
  ShL2 radiance;
  const std::array<double, 9> y = unity_basis_slow(0.48, 0.6, 0.64);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) radiance.c[c][i] = (1.0 + c) * y[i];
  for (const char* name : {"optimal", "sloan"}) {
    shpack::FinishOptions options;
    ASSERT_TRUE(shpack::parse_window(name, options.window).ok());
    options.l1 = true;
    shpack::FinishedSh out;
    ASSERT_TRUE(shpack::finish_projection(radiance, options, out).ok()) << name;
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(out.min_e_over_pi[c].value, 0.0) << name << " c=" << c;
      for (int i = 4; i < 9; ++i) EXPECT_EQ(out.unity_form.c[c][i], 0.0) << name;
      for (int i = 4; i < 9; ++i) EXPECT_EQ(out.radiance.c[c][i], 0.0) << name;
    }
  }
}

}  // namespace
}  // namespace shpack_test
