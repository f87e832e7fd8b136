// oracle_self_test.cpp - the oracle in tests/support is checked against closed forms before
// any test trusts it: quadrature rules, Legendre functions, orthonormality, the cosine-lobe
// factors, brute-force irradiance, the half conversion, the shader transcription.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <unistd.h>

#include "support/equirect_oracle.h"
#include "support/exr_file.h"
#include "support/gauss_legendre.h"
#include "support/guarded_buffer.h"
#include "support/half_oracle.h"
#include "support/irradiance_oracle.h"
#include "support/sh_oracle.h"
#include "support/sphere_points.h"
#include "support/test_util.h"
#include "support/unity_shader.h"

namespace shpack_test {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(OracleGaussLegendre, IntegratesMonomialsUpToDegree2qMinus1) {
  for (int q = 1; q <= 24; ++q) {
    const GaussRule r = gauss_legendre(q);
    for (int k = 0; k <= 2 * q - 1; ++k) {
      double sum = 0.0, abs_sum = 0.0;
      for (int a = 0; a < q; ++a) {
        sum += r.weights[a] * std::pow(r.nodes[a], k);
        abs_sum += r.weights[a] * std::fabs(std::pow(r.nodes[a], k));
      }
      const double want = k % 2 == 1 ? 0.0 : 2.0 / (k + 1);
      // The three-term recurrence to P_q and P_q' carries <= 3q roundings, so weights are
      // within 3q u (relative) and nodes within 3q u (absolute, |P_q'| >= 1 at the roots);
      // x^k multiplies a node's error by k and adds k roundings: per term <= (3q + k(3q + 1)) u
      // relative to w |x|^k, doubled for the summation of <= 24 terms.
      const double tol = 2.0 * (3.0 * q + k * (3.0 * q + 1.0)) * kU * std::max(abs_sum, 1.0);
      EXPECT_NEAR(want, sum, tol) << "q=" << q << " k=" << k;
    }
  }
}

TEST(OracleGaussLegendre, RemainderBoundIsMonotoneAndPicksAnOrder) {
  // Halving the interval cuts the bound by 2^(2q).
  EXPECT_NEAR(gl_relative_bound(0.1, 3.0, 4) / gl_relative_bound(0.05, 3.0, 4), 256.0, 1e-9);
  const int q = gl_order_for(kPi, 3.0, 1e-16);
  EXPECT_LE(gl_relative_bound(kPi, 3.0, q), 1e-16) << "q=" << q;
  EXPECT_GT(gl_relative_bound(kPi, 3.0, q - 1), 1e-16) << "q=" << q;
}

TEST(OracleLegendre, MatchesClosedFormsWithoutCondonShortleyPhase) {
  for (double x : {-1.0, -0.7, -0.2, 0.0, 0.3, 0.9, 1.0}) {
    const double s = std::sqrt(1.0 - x * x);
    // Closed forms (no (-1)^m): every value is a polynomial in x and s evaluated with a few
    // roundings, so 16u times the largest term bounds the difference.
    EXPECT_NEAR(assoc_legendre(2, 0, x), 0.5 * (3 * x * x - 1), 16 * kU * 3) << "x=" << x;
    EXPECT_NEAR(assoc_legendre(2, 1, x), 3 * x * s, 16 * kU * 3) << "x=" << x;
    EXPECT_NEAR(assoc_legendre(2, 2, x), 3 * (1 - x * x), 16 * kU * 3) << "x=" << x;
    EXPECT_NEAR(assoc_legendre(1, 1, x), s, 16 * kU) << "x=" << x;
    EXPECT_NEAR(assoc_legendre(3, 1, x), 1.5 * (5 * x * x - 1) * s, 16 * kU * 8) << "x=" << x;
    EXPECT_NEAR(assoc_legendre(4, 0, x), (35 * std::pow(x, 4) - 30 * x * x + 3) / 8, 16 * kU * 9)
        << "x=" << x;
  }
}

TEST(OracleLegendre, BasisIsOrthonormalUpToL4) {
  // Tensor Gauss-Legendre on the sphere: Y_a Y_b sin(theta) is a trig polynomial of
  // frequency <= 9 in theta and <= 8 in phi; the orders come from the remainder bound
  // (gauss_legendre.h) for 1e-16 relative. Each Y is within ~8u of its value and
  // |Y| <= 1.5, weights sum to 4 pi: |Gram - I| <= 4 pi * 2.25 * 16u < 1e-13.
  const int lmax = 4, n = (lmax + 1) * (lmax + 1);
  const GaussRule rt = gauss_legendre(gl_order_for(kPi, 9.0, 1e-16));
  const GaussRule rp = gauss_legendre(gl_order_for(2 * kPi, 8.0, 1e-16));
  std::vector<double> gram(n * n, 0.0);
  for (std::size_t a = 0; a < rt.nodes.size(); ++a) {
    const double theta = 0.5 * kPi * (rt.nodes[a] + 1.0);
    for (std::size_t b = 0; b < rp.nodes.size(); ++b) {
      const double phi = kPi * (rp.nodes[b] + 1.0);
      const double w = 0.5 * kPi * rt.weights[a] * kPi * rp.weights[b] * std::sin(theta);
      const std::vector<double> y = sh_slow_all(lmax, std::sin(theta) * std::cos(phi),
                                                std::sin(theta) * std::sin(phi), std::cos(theta));
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) gram[i * n + j] += w * y[i] * y[j];
    }
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      EXPECT_NEAR(gram[i * n + j], i == j ? 1.0 : 0.0, 1e-13) << "i=" << i << " j=" << j;
}

TEST(OracleCosineLobe, ClosedFormMatchesDirectIntegral) {
  // A_l = 2 pi int_0^1 P_l(t) t dt; the integrand is a polynomial of degree l + 1, which a
  // (l/2 + 2)-point rule integrates exactly: only rounding (~(l + 8) u |terms|) remains.
  // The sum of |P_l(t) t| over [0, 1] is at most 1, so 64u * 2 pi bounds the difference.
  for (int l = 0; l <= 16; ++l) {
    const GaussRule r = gauss_legendre(l / 2 + 2);
    double sum = 0.0;
    for (std::size_t a = 0; a < r.nodes.size(); ++a) {
      const double t = 0.5 * (r.nodes[a] + 1.0);
      sum += 0.5 * r.weights[a] * assoc_legendre(l, 0, t) * t;
    }
    EXPECT_NEAR(cosine_lobe(l), 2.0 * kPi * sum, 64 * kU * 2.0 * kPi) << "l=" << l;
  }
  EXPECT_DOUBLE_EQ(cosine_lobe(4), -kPi / 24) << "Ramamoorthi-Hanrahan A4";
}

TEST(OracleCosineLobe, TruncationKernelNormTailIsBounded) {
  // S^2 sums terms that decay like l^-4; the tail bound used for l > 20000 must dominate
  // the actual terms from any cut-off: check it against the exact sum over [200, 20000).
  double explicit_tail = 0.0;
  for (int l = 20000 - 1; l >= 200; --l) {
    const double a = cosine_lobe(l) / kPi;
    explicit_tail += a * a * (2.0 * l + 1.0) / (4.0 * kPi);
  }
  EXPECT_LE(explicit_tail, 0.43 / (6.0 * std::pow(200.0 - 3.0, 3)));
  // The leading term is (A4/pi)^2 9/(4 pi) = 9/(576 * 4 pi); S is larger than its root.
  const double s = truncation_kernel_norm();
  EXPECT_GT(s, std::sqrt(9.0 / (576.0 * 4.0 * kPi)));
  EXPECT_LT(s, 2.0 * std::sqrt(9.0 / (576.0 * 4.0 * kPi)));
}

TEST(OracleProjection, UniformImageIsTheWhiteFurnace) {
  // L(w) = v: L00 = 2 sqrt(pi) v, all others 0. The oracle's rules are accurate to 1e-16
  // relative; rounding over W*H*q^2 nodes in double per texel and long double overall
  // stays below 64u * (4 pi max|Y| v).
  for (auto [w, h] : {std::pair{1u, 1u}, {2u, 1u}, {7u, 3u}, {32u, 16u}}) {
    RgbImage img(w, h);
    for (std::uint32_t j = 0; j < h; ++j)
      for (std::uint32_t i = 0; i < w; ++i) img.set(i, j, 1.0f, 2.0f, 0.5f);
    const shpack::ShL2 sh = project_oracle(img);
    const double v[3] = {1.0, 2.0, 0.5};
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 9; ++i) {
        const double want = i == 0 ? 2.0 * std::sqrt(kPi) * v[c] : 0.0;
        EXPECT_NEAR(want, sh.c[c][i], 64 * kU * 4 * kPi * 0.64 * v[c])
            << "W=" << w << " H=" << h << " c=" << c << " i=" << i;
      }
  }
}

TEST(OracleProjection, TexelSolidAnglesSumTo4Pi) {
  for (auto [w, h] : {std::pair{1u, 1u}, {3u, 5u}, {64u, 32u}}) {
    double sum = 0.0;
    for (std::uint32_t j = 0; j < h; ++j)
      for (std::uint32_t i = 0; i < w; ++i) sum += patch_solid_angle(texel_patch(i, j, w, h));
    // Each patch within 1e-16 (rule) + ~8u (rounding) relative; the plain sum of W H
    // positive terms adds <= (W H - 1) u of the total.
    EXPECT_NEAR(sum, 4 * kPi, (w * h + 16.0) * kU * 4 * kPi) << "W=" << w << " H=" << h;
  }
}

TEST(OracleIrradiance, UniformRadianceGivesItsValueEverywhere) {
  // E(n) = v int max(0, n.w) dw = pi v for every n, whatever the image size.
  for (auto [w, h, depth] : {std::tuple{1u, 1u, 7}, {2u, 1u, 7}, {16u, 8u, 4}, {64u, 32u, 2}}) {
    RgbImage img(w, h);
    for (std::uint32_t j = 0; j < h; ++j)
      for (std::uint32_t i = 0; i < w; ++i) img.set(i, j, 1.0f, 3.0f, 0.25f);
    const IrradianceOracle oracle(img, depth);
    for (const shpack::Dir3& n : fibonacci_sphere(32)) {
      const IrradianceEstimate e = oracle.eval(n);
      const double v[3] = {1.0, 3.0, 0.25};
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(v[c], e.e_over_pi[c], e.bound[c]) << "W=" << w << " H=" << h << " n=" << n;
        // The bound must also be useful: below 5% of the value at these depths.
        EXPECT_LT(e.bound[c], 0.05 * v[c]) << "W=" << w << " H=" << h << " n=" << n;
      }
    }
  }
}

TEST(OracleIrradiance, TwoHemispheresMatchClosedForm) {
  // 2x1 image: left texel is the hemisphere z >= 0 (value a), right z <= 0 (value b).
  // E(+z)/pi = a, E(-z)/pi = b, E(n)/pi = (a + b)/2 for n in the plane z = 0, and in
  // general (a + b)/2 + (a - b) n_z / 2 (the cosine-weighted area of each hemisphere).
  RgbImage img(2, 1);
  img.set(0, 0, 2.0f, 1.0f, 0.0f);
  img.set(1, 0, 0.5f, 1.0f, 4.0f);
  const double a[3] = {2.0, 1.0, 0.0}, b[3] = {0.5, 1.0, 4.0};
  const IrradianceOracle oracle(img, 8);
  for (const shpack::Dir3& n : fibonacci_sphere(64)) {
    const IrradianceEstimate e = oracle.eval(n);
    for (int c = 0; c < 3; ++c) {
      const double want = 0.5 * (a[c] + b[c]) + 0.5 * (a[c] - b[c]) * n.z;
      EXPECT_NEAR(want, e.e_over_pi[c], e.bound[c]) << "c=" << c << " n=" << n;
    }
  }
}

TEST(OracleHalf, KnownValues) {
  EXPECT_EQ(half_bits_to_float(0x3c00), 1.0f);
  EXPECT_EQ(half_bits_to_float(0xc000), -2.0f);
  EXPECT_EQ(half_bits_to_float(0x7bff), 65504.0f);
  EXPECT_EQ(half_bits_to_float(0x0001), std::ldexp(1.0f, -24));
  EXPECT_EQ(half_bits_to_float(0x0400), std::ldexp(1.0f, -14));
  EXPECT_EQ(half_bits_to_float(0x3555), 0x1.554p-2f);
  EXPECT_TRUE(std::signbit(half_bits_to_float(0x8000)));
  EXPECT_EQ(half_bits_to_float(0x7c00), INFINITY);
  EXPECT_EQ(half_bits_to_float(0xfc00), -INFINITY);
  EXPECT_TRUE(std::isnan(half_bits_to_float(0x7e00)));
}

TEST(OracleShader, TranscriptionOnAxisNormals) {
  shpack::UnityShaderVectors v{};
  v.SHAr = {1.0f, 2.0f, 3.0f, 4.0f};
  v.SHBr = {5.0f, 6.0f, 7.0f, 8.0f};
  v.SHC = {9.0f, 10.0f, 11.0f, 1.0f};
  // n = +X: dot(SHA, (1,0,0,1)) + dot(SHB, (0,0,0,0)) + SHC.r (1 - 0) = 1 + 4 + 9.
  EXPECT_EQ(unity_shade_sh9(v, {1, 0, 0})[0], 14.0f);
  // n = +Y: 2 + 4 + 0 - 9 = -3.  n = +Z: 3 + 4 + 7 (zz) = 14.
  EXPECT_EQ(unity_shade_sh9(v, {0, 1, 0})[0], -3.0f);
  EXPECT_EQ(unity_shade_sh9(v, {0, 0, 1})[0], 14.0f);
  // Green uses SHAg/SHBg (zero here) and SHC.g: +X gives 10.
  EXPECT_EQ(unity_shade_sh9(v, {1, 0, 0})[1], 10.0f);
}

TEST(OracleGuardedBuffer, WholeBufferIsUsable) {
  for (auto g : {GuardedBuffer::Guard::After, GuardedBuffer::Guard::Before}) {
    GuardedBuffer buf(4099, g);
    ASSERT_TRUE(buf.ok());
    for (std::size_t k = 0; k < buf.size(); ++k) buf.data()[k] = std::byte{0x5a};
    EXPECT_EQ(buf.data()[buf.size() - 1], std::byte{0x5a});
  }
}

TEST(OracleExr, WriteThenReadIsLossless) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<float> u(-10.0f, 1e4f);
  RgbImage img(13, 7);
  for (float& v : img.rgb) v = u(rng);
  const auto path = std::filesystem::path(::testing::TempDir()) / ("shpack_oracle_exr_" + std::to_string(::getpid()) + ".exr");
  std::string error;
  ASSERT_TRUE(write_exr_rgb(path, img, error)) << error;
  RgbImage back;
  ASSERT_TRUE(read_exr_rgb(path, back, error)) << error;
  std::filesystem::remove(path);
  ASSERT_EQ(back.width, img.width);
  ASSERT_EQ(back.height, img.height);
  for (std::size_t k = 0; k < img.rgb.size(); ++k) ASSERT_EQ(img.rgb[k], back.rgb[k]) << "k=" << k;
}

}  // namespace
}  // namespace shpack_test
