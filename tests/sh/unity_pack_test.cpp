// unity_pack_test.cpp - convolution to Unity form, the 27 floats, the seven shader vectors,
// and ShadeSH9 (docs/conventions.md sections 4-7).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "shpack/convolution.h"
#include "shpack/sh_basis.h"
#include "shpack/unity_pack.h"
#include "support/sh_oracle.h"
#include "support/sphere_points.h"
#include "support/test_util.h"
#include "support/unity_shader.h"

namespace shpack_test {
namespace {

using shpack::Dir3;
using shpack::ShL2;
using Float4 = shpack::UnityShaderVectors::Float4;

// sh[c][i] = (-1)^i (10c + i + 1)/8: every slot distinct, all exactly representable in
// float, and sh0 - sh6, 3 sh6 too, so the expected vectors are exact.
ShL2 distinct_unity_form() {
  ShL2 sh;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) sh.c[c][i] = (i % 2 == 0 ? 1.0 : -1.0) * (10.0 * c + i + 1.0) / 8.0;
  return sh;
}

TEST(UnityPack, ShaderVectorsOfKnownCoefficients) {
  // Hand-computed from SHA = (sh3, sh1, sh2, sh0 - sh6), SHB = (sh4, sh5, 3 sh6, sh7),
  // SHC = (sh[0][8], sh[1][8], sh[2][8], 1), with
  //   red   = 0.125 -0.25  0.375 -0.5  0.625 -0.75  0.875 -1.0   1.125
  //   green = 1.375 -1.5   1.625 -1.75 1.875 -2.0   2.125 -2.25  2.375
  //   blue  = 2.625 -2.75  2.875 -3.0  3.125 -3.25  3.375 -3.5   3.625
  const shpack::UnityShaderVectors v = shpack::to_shader_vectors(distinct_unity_form());
  EXPECT_EQ(v.SHAr, (Float4{-0.5f, -0.25f, 0.375f, -0.75f}));
  EXPECT_EQ(v.SHAg, (Float4{-1.75f, -1.5f, 1.625f, -0.75f}));
  EXPECT_EQ(v.SHAb, (Float4{-3.0f, -2.75f, 2.875f, -0.75f}));
  EXPECT_EQ(v.SHBr, (Float4{0.625f, -0.75f, 2.625f, -1.0f}));
  EXPECT_EQ(v.SHBg, (Float4{1.875f, -2.0f, 6.375f, -2.25f}));
  EXPECT_EQ(v.SHBb, (Float4{3.125f, -3.25f, 10.125f, -3.5f}));
  EXPECT_EQ(v.SHC, (Float4{1.125f, 2.375f, 3.625f, 1.0f}));
}

TEST(UnityPack, SphericalHarmonicsL2IsChannelMajorAndRoundedOnce) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  ShL2 sh;
  for (auto& ch : sh.c)
    for (double& x : ch) x = u(rng);
  const shpack::UnitySphericalHarmonicsL2 f = shpack::to_unity_sh(sh);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i)
      EXPECT_EQ(f[c][i], static_cast<float>(sh.c[c][i])) << "c=" << c << " i=" << i;
  // Serialized order sh[0]..sh[26] is 9c + i.
  const float* flat = &f[0][0];
  EXPECT_EQ(flat[9 * 2 + 4], static_cast<float>(sh.c[2][4]));
}

// A packing with the widely copied mistakes (SHB slots of indices 5 and 6 swapped, SHC
// green and blue swapped), to show that the property check below detects it.
shpack::UnityShaderVectors swapped_packing(const ShL2& sh) {
  shpack::UnityShaderVectors v = shpack::to_shader_vectors(sh);
  for (Float4* b : {&v.SHBr, &v.SHBg, &v.SHBb}) std::swap((*b)[1], (*b)[2]);
  std::swap(v.SHC[1], v.SHC[2]);
  return v;
}

TEST(UnityPack, ShaderEvalEqualsCoefficientSumAndCatchesSwappedPacking) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int swapped_caught = 0, checks = 0;
  for (int trial = 0; trial < 20; ++trial) {
    ShL2 sh;
    for (auto& ch : sh.c)
      for (double& x : ch) x = u(rng);
    const shpack::UnityShaderVectors good = shpack::to_shader_vectors(sh);
    const shpack::UnityShaderVectors bad = swapped_packing(sh);
    for (const Dir3& n : fibonacci_sphere(256)) {
      const auto oracle = unity_shade_sh9(good, n);
      const auto wrong = unity_shade_sh9(bad, n);
      for (int c = 0; c < 3; ++c) {
        const double want = reconstruct_unity_form(sh, c, n);
        const double tol = shade_sh9_rounding_bound(sh, c, n);
        // Transcription of the shader (oracle) and shpack's shade_sh9, both on shpack's packing.
        EXPECT_NEAR(want, oracle[c], tol) << "trial=" << trial << " c=" << c << " n=" << n;
        const float got = shpack::shade_sh9(good, c, static_cast<float>(n.x), static_cast<float>(n.y),
                                            static_cast<float>(n.z));
        EXPECT_NEAR(want, got, tol) << "trial=" << trial << " c=" << c << " n=" << n;
        ++checks;
        if (std::fabs(wrong[c] - want) > tol) ++swapped_caught;
      }
    }
  }
  // The swapped packing differs by sh5 (yz - 3zz) + 3 sh6 (zz - yz) [+ blue/green SHC]
  // terms: zero only on measure-zero sets, so it must fail at most of the normals.
  EXPECT_GT(swapped_caught, checks / 2) << "swapped packing caught at " << swapped_caught << " of " << checks;
}

TEST(UnityPack, UniformRadianceGivesAmbientOnly) {
  // L(w) = R: radiance L00 = 2 sqrt(pi) R, others 0. Unity form: sh[c][0] = k0 2 sqrt(pi) R
  // = R (2 roundings in 2 sqrt(pi), 1 in the product: within 3u R), the rest exactly 0,
  // and ShadeSH9 = R everywhere (AddAmbientLight(R)).
  const double r[3] = {0.75, 1.5, 3.25};
  ShL2 radiance;
  for (int c = 0; c < 3; ++c) radiance.c[c][0] = 2.0 * std::sqrt(std::numbers::pi) * r[c];
  const ShL2 unity = shpack::radiance_to_unity_form(radiance);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(unity.c[c][0], r[c], 4 * kU * r[c]) << "c=" << c;
    for (int i = 1; i < 9; ++i) EXPECT_EQ(unity.c[c][i], 0.0) << "c=" << c << " i=" << i;
  }
  const shpack::UnityShaderVectors v = shpack::to_shader_vectors(unity);
  for (const Dir3& n : fibonacci_sphere(256)) {
    const auto s = unity_shade_sh9(v, n);
    for (int c = 0; c < 3; ++c) {
      // Only SHA.w is non-zero: the shader returns float(sh0) exactly (every other term is
      // an exact 0), within one float rounding of R.
      EXPECT_NEAR(r[c], s[c], 0x1p-24 * r[c] + 4 * kU * r[c]) << "c=" << c << " n=" << n;
      EXPECT_EQ(s[c], static_cast<float>(unity.c[c][0])) << "c=" << c << " n=" << n;
    }
  }
}

TEST(Convolution, UnityFormIsLobeOverPiTimesBasisScaleTimesRadiance) {
  // Independently: (A_l / pi) from the general zonal formula, k_i from std::numbers. One
  // product in shpack, three roundings here: within 4 ulp (EXPECT_DOUBLE_EQ).
  const double inv = std::numbers::inv_sqrtpi;
  const double k[9] = {0.5 * inv, 0.5 * std::numbers::sqrt3 * inv, 0.5 * std::numbers::sqrt3 * inv,
                       0.5 * std::numbers::sqrt3 * inv, 0.5 * std::sqrt(15.0) * inv,
                       0.5 * std::sqrt(15.0) * inv, 0.25 * std::sqrt(5.0) * inv,
                       0.5 * std::sqrt(15.0) * inv, 0.25 * std::sqrt(15.0) * inv};
  const int band[9] = {0, 1, 1, 1, 2, 2, 2, 2, 2};
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  ShL2 radiance;
  for (auto& ch : radiance.c)
    for (double& x : ch) x = u(rng);
  const ShL2 unity = shpack::radiance_to_unity_form(radiance);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) {
      const double want = cosine_lobe(band[i]) / std::numbers::pi * k[i] * radiance.c[c][i];
      EXPECT_DOUBLE_EQ(want, unity.c[c][i]) << "c=" << c << " i=" << i;
    }
}

TEST(Convolution, UnityFormEvaluatesToIrradianceOverPi) {
  // sum_i sh_i P_i(n) = sum_l (A_l/pi) sum_m L_lm Y_lm(n): shpack's constants and
  // polynomials against the oracle's zonal factors and Legendre-route basis. Both sides
  // sum 9 terms each within ~8u: |diff| <= 32u sum_i |C_i L_i P_i(n)| <= 32u * 9 * 1.5.
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    ShL2 radiance;
    for (auto& ch : radiance.c)
      for (double& x : ch) x = u(rng);
    const ShL2 unity = shpack::radiance_to_unity_form(radiance);
    const Dir3 n = random_direction(rng);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(reconstruct_irradiance_over_pi(radiance, c, n),
                  shpack::eval_unity_form(unity, c, n.x, n.y, n.z), 32 * kU * 9 * 1.5)
          << "trial=" << trial << " c=" << c << " n=" << n;
  }
}

TEST(UnityPack, FitsFloat32ChecksTheShaderVectorsToo) {
  // FLT_MAX = 3.4028e38. s0 = 3e38 and s6 = -1e38 fit as floats, but SHA.w = s0 - s6 = 4e38
  // does not; s6 = 2e38 fits but SHB.z = 3 s6 = 6e38 does not. (Regression: convert and bake
  // checked only the 27 floats and wrote null into "shader".)
  ShL2 sh;
  sh.c[1][0] = 3e38;
  EXPECT_TRUE(shpack::fits_unity_float32(sh));
  sh.c[1][6] = -1e38;
  EXPECT_FALSE(shpack::fits_unity_float32(sh));
  sh = {};
  sh.c[2][6] = 2e38;
  EXPECT_FALSE(shpack::fits_unity_float32(sh));
  sh = {};
  sh.c[0][8] = 4e38;  // one of the 27, and SHC.x
  EXPECT_FALSE(shpack::fits_unity_float32(sh));
}

TEST(Convolution, ScaledMultipliesEveryCoefficient) {
  const ShL2 sh = distinct_unity_form();
  const ShL2 s = shpack::scaled(sh, 2.5);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) EXPECT_EQ(s.c[c][i], 2.5 * sh.c[c][i]) << "c=" << c << " i=" << i;
}

TEST(Convolution, DirectionalLightLobePeaksAtTheLight) {
  // A delta light of irradiance E from d: L_i = E Y_i(d) (docs section 5). Its L2 E/pi at
  // n = d is E sum_l (A_l/pi)(2l+1)/(4pi) = E (1 + 3(2/3) + 5/4)/(4 pi) = E (17/4)/(4 pi),
  // by the addition theorem, whatever d: pins the 1/pi and A_l (a missing 1/pi is pi times
  // too bright, a missing A_l 1/(1 + 3 + 5) * 17/4 off).
  std::mt19937_64 rng(0x5eed);
  const double e = 3.0;
  for (int trial = 0; trial < 20; ++trial) {
    const Dir3 d = random_direction(rng);
    const auto y = shpack::eval_basis(d.x, d.y, d.z);
    ShL2 radiance;
    for (int i = 0; i < 9; ++i) radiance.c[0][i] = e * y[i];
    const ShL2 unity = shpack::radiance_to_unity_form(radiance);
    const double want = e * (17.0 / 4.0) / (4.0 * std::numbers::pi);
    EXPECT_NEAR(want, shpack::eval_unity_form(unity, 0, d.x, d.y, d.z), 64 * kU * want) << "d=" << d;
  }
}

}  // namespace
}  // namespace shpack_test
