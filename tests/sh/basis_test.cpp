// basis_test.cpp - shpack's hard-coded L2 polynomials against the Legendre-recurrence oracle.
//
// Sign convention (pinned here, as google/spherical-harmonics pins its own): Unity's basis
// has NO Condon-Shortley phase, so with Unity's index order the L1 coefficients are
// +k1 (y, z, x): Y_3 is positive at +X, Y_1 at +Y, Y_2 at +Z. google/sh's HardcodedSH
// has -k1 y and -k1 x (with the phase) and would fail BasisSignsHaveNoCondonShortleyPhase.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "shpack/sh_basis.h"
#include "support/gauss_legendre.h"
#include "support/sh_oracle.h"
#include "support/sphere_points.h"
#include "support/test_util.h"
#include "support/unity_shader.h"

namespace shpack_test {
namespace {

using shpack::Dir3;

// Both routes compute each Y_i within a few ulp of its value (|Y| <= 1.1); the oracle's
// atan2/acos add an angle error <= 2 pi u that moves cos(m phi), sin(m phi) by at most
// 4 pi u. So |difference| <= 1.1 * (4 pi + 16) u < 32u; we allow 1e-14 (~90u) to cover
// libm's documented 1-2 ulp per call across the ~10 calls on the oracle's path.
constexpr double kBasisTol = 1e-14;

void expect_basis_matches(const Dir3& d, const char* what) {
  const std::array<double, 9> got = shpack::eval_basis(d.x, d.y, d.z);
  const std::array<double, 9> want = unity_basis_slow(d.x, d.y, d.z);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(want[i], got[i], kBasisTol) << what << " i=" << i << " d=" << d;
}

TEST(Basis, MatchesLegendreRouteAtRandomDirections) {
  std::mt19937_64 rng(0x5eed);
  for (int k = 0; k < 2000; ++k) expect_basis_matches(random_direction(rng), "random");
}

TEST(Basis, MatchesLegendreRouteOnAxesAndFibonacciPoints) {
  for (const Dir3& d : {Dir3{1, 0, 0}, Dir3{-1, 0, 0}, Dir3{0, 1, 0}, Dir3{0, -1, 0}, Dir3{0, 0, 1},
                        Dir3{0, 0, -1}})
    expect_basis_matches(d, "axis");
  for (const Dir3& d : fibonacci_sphere(512)) expect_basis_matches(d, "fibonacci");
}

TEST(Basis, EvalBasisIsScaleTimesPolynomials) {
  std::mt19937_64 rng(0x5eed);
  for (int k = 0; k < 100; ++k) {
    const Dir3 d = random_direction(rng);
    const auto p = shpack::basis_polynomials(d.x, d.y, d.z);
    const auto y = shpack::eval_basis(d.x, d.y, d.z);
    const std::array<double, 9> want_p = {1.0,       d.y,       d.z,
                                          d.x,       d.x * d.y, d.y * d.z,
                                          3.0 * d.z * d.z - 1.0, d.x * d.z, d.x * d.x - d.y * d.y};
    for (int i = 0; i < 9; ++i) {
      EXPECT_EQ(p[i], want_p[i]) << "i=" << i << " d=" << d;
      EXPECT_EQ(y[i], shpack::kBasisScale[i] * p[i]) << "i=" << i << " d=" << d;
    }
  }
}

TEST(Basis, BasisSignsHaveNoCondonShortleyPhase) {
  const double r = std::numbers::sqrt2 / 2;
  struct Case {
    int i;
    Dir3 d;
    double sign;
  };
  for (const Case& c : {Case{1, {0, 1, 0}, 1}, Case{2, {0, 0, 1}, 1}, Case{3, {1, 0, 0}, 1},
                        Case{4, {r, r, 0}, 1}, Case{5, {0, r, r}, 1}, Case{6, {0, 0, 1}, 1},
                        Case{6, {1, 0, 0}, -1}, Case{7, {r, 0, r}, 1}, Case{8, {1, 0, 0}, 1},
                        Case{8, {0, 1, 0}, -1}}) {
    const double got = shpack::eval_basis(c.d.x, c.d.y, c.d.z)[c.i];
    const double oracle = unity_basis_slow(c.d.x, c.d.y, c.d.z)[c.i];
    // Every case has |Y_i| >= k3 = 0.315 (Y6 at +X); the sign is the point.
    EXPECT_GT(c.sign * got, 0.3) << "i=" << c.i << " d=" << c.d;
    EXPECT_GT(c.sign * oracle, 0.3) << "i=" << c.i << " d=" << c.d;
  }
}

TEST(Basis, EvalBasisIsOrthonormal) {
  // Tensor Gauss-Legendre in (theta, phi): Y_a Y_b sin theta has frequency <= 5 in theta
  // and <= 4 in phi; the orders come from the remainder bound (gauss_legendre.h) for a
  // relative error of 1e-16. Products of values <= 1.1 with ~4u error each, weights
  // summing to 4 pi: |Gram - I| <= 4 pi * 1.21 * 8u + 1e-16 < 1e-13.
  const double pi = std::numbers::pi;
  const GaussRule rt = gauss_legendre(gl_order_for(pi, 5.0, 1e-16));
  const GaussRule rp = gauss_legendre(gl_order_for(2 * pi, 4.0, 1e-16));
  double gram[9][9] = {};
  for (std::size_t a = 0; a < rt.nodes.size(); ++a) {
    const double theta = 0.5 * pi * (rt.nodes[a] + 1.0);
    for (std::size_t b = 0; b < rp.nodes.size(); ++b) {
      const double phi = pi * (rp.nodes[b] + 1.0);
      const double w = 0.5 * pi * rt.weights[a] * pi * rp.weights[b] * std::sin(theta);
      const auto y = shpack::eval_basis(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                        std::cos(theta));
      for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) gram[i][j] += w * y[i] * y[j];
    }
  }
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) EXPECT_NEAR(gram[i][j], i == j ? 1.0 : 0.0, 1e-13) << "i=" << i << " j=" << j;
}

TEST(Basis, EvalUnityFormIsTheSumOfCoefficientsTimesPolynomials) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 200; ++k) {
    shpack::ShL2 sh;
    for (auto& ch : sh.c)
      for (double& v : ch) v = u(rng);
    const Dir3 n = random_direction(rng);
    for (int c = 0; c < 3; ++c) {
      // Nine products and eight additions of terms <= 2 * 2: |err| <= 20u * 9 * 4.
      EXPECT_NEAR(reconstruct_unity_form(sh, c, n), shpack::eval_unity_form(sh, c, n.x, n.y, n.z),
                  20 * kU * 36)
          << "c=" << c << " n=" << n;
    }
  }
}

}  // namespace
}  // namespace shpack_test
