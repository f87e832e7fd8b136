// values_test.cpp - hard texel values in the core: NaN, +Inf, -Inf, negative and denormal
// texels under every policy (float and half views, scalar and vector row kernels, 1 and 2
// threads), all-black scenes (exact zeros and no NaN from any normalisation: packing,
// sh_minimum, every window including sloan, rotation), and scenes of 1e30, FLT_MAX and 1e-30
// everywhere (no overflow or underflow in accumulation, float outputs in range).
// The same cases through files and the shpack command are in cli_hard_cases_test.cpp.
#include <gtest/gtest.h>

#include <Imath/half.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "hard_cases/checks.h"
#include "hard_cases/hard_case_support.h"
#include "shpack/convolution.h"
#include "shpack/project.h"
#include "shpack/project_cube.h"
#include "shpack/rotate.h"
#include "shpack/sh_minimum.h"
#include "shpack/unity_pack.h"
#include "shpack/window.h"
#include "support/test_util.h"

namespace shpack_hard {
namespace {

using shpack::Errc;
using shpack::NonFinite;
using shpack::Negative;
using shpack_test::describe;

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();
constexpr float kDenormal = 1e-40f;  // binary32 subnormal (FLT_MIN = 1.18e-38)

// A W x H float RGB image of 1.5 with hard values planted; the same image with each
// non-finite channel replaced by 0 (what NonFinite::Zero promises) and each negative one
// by 0 (Negative::Clamp).
struct Planted {
  std::uint32_t w, h;
  std::vector<float> rgb, zeroed, clamped;
  std::uint64_t nonfinite = 0, negative = 0;
  std::uint32_t first_x = 0, first_y = 0;
};

Planted planted(std::uint32_t w, std::uint32_t h) {
  Planted p{w, h, std::vector<float>(std::size_t{3} * w * h, 1.5f), {}, {}};
  auto at = [&](std::uint32_t x, std::uint32_t y, int c) -> float& { return p.rgb[(std::size_t{y} * w + x) * 3 + c]; };
  // In row-major order: NaN (first), +Inf, -Inf; negatives: -2, a negative denormal; a
  // positive denormal and -0 (neither counts).
  at(w - 1, 0, 0) = kNaN;
  at(0, 1, 1) = kInf;
  at(w / 2, h - 1, 2) = -kInf;
  at(1, 0, 2) = -2.0f;
  at(w - 2, 1, 1) = -kDenormal;
  at(w / 2, 1, 0) = kDenormal;
  at(0, h - 1, 0) = -0.0f;
  p.nonfinite = 3;
  p.negative = 2;
  p.first_x = w - 1;
  p.first_y = 0;
  p.zeroed = p.rgb;
  for (float& v : p.zeroed)
    if (!std::isfinite(v)) v = 0.0f;
  p.clamped = p.zeroed;
  for (float& v : p.clamped)
    if (v < 0.0f) v = 0.0f;
  return p;
}

std::vector<std::uint16_t> to_half(const std::vector<float>& v) {
  std::vector<std::uint16_t> out;
  for (float f : v) out.push_back(Imath::half(f).bits());
  return out;
}

shpack::ImageView view_of(const std::vector<float>& rgb, std::uint32_t w, std::uint32_t h) {
  return shpack::make_view(rgb.data(), w, h, 3);
}
shpack::ImageView view_of(const std::vector<std::uint16_t>& rgb, std::uint32_t w, std::uint32_t h) {
  return {reinterpret_cast<const std::byte*>(rgb.data()), shpack::PixelType::F16, w, h, 3};
}

TEST(Values, NonFiniteNegativeAndDenormalTexelsUnderEveryPolicy) {
  // W = 5 runs the scalar loader only; W = 19 the vector kernels on clean rows and the
  // careful loader on the rows that hold the planted values; H = 70 spans two tiles.
  for (auto [w, h] : {std::pair<std::uint32_t, std::uint32_t>{5, 3}, {19, 70}}) {
    const Planted p = planted(w, h);
    for (bool half : {false, true}) {
      // Half: 1e-40 is below the smallest half subnormal (6e-8) and rounds to +-0, so in
      // the half image only one texel is negative.
      const std::vector<std::uint16_t> h_rgb = to_half(p.rgb), h_zeroed = to_half(p.zeroed),
                                       h_clamped = to_half(p.clamped);
      const std::uint64_t negative = half ? 1 : p.negative;
      for (unsigned threads : {1u, 2u}) {
        for (Negative neg : {Negative::Keep, Negative::Clamp}) {
          const std::string what = "W=" + std::to_string(w) + (half ? " half" : " float") +
                                   " threads=" + std::to_string(threads) + (neg == Negative::Clamp ? " clamp" : " keep");
          shpack::ProjectOptions options;
          options.threads = threads;
          options.negative = neg;
          const shpack::ImageView image = half ? view_of(h_rgb, w, h) : view_of(p.rgb, w, h);
          // Error: fails at the first non-finite texel in row-major order.
          options.nonfinite = NonFinite::Error;
          ShL2 sh;
          const shpack::Status st = shpack::project_equirect(image, options, sh);
          EXPECT_EQ(st.code, Errc::NonFiniteTexel) << what;
          EXPECT_EQ(st.x, p.first_x) << what;
          EXPECT_EQ(st.y, p.first_y) << what;
          // Zero: counted, and exactly the projection of the cleaned image.
          options.nonfinite = NonFinite::Zero;
          shpack::ProjectStats stats;
          ASSERT_TRUE(shpack::project_equirect(image, options, sh, &stats).ok()) << what;
          EXPECT_EQ(stats.nonfinite_texels, p.nonfinite) << what;
          EXPECT_EQ(stats.negative_texels, negative) << what << ": counted under Keep and Clamp alike";
          EXPECT_EQ(stats.first_nonfinite_x, p.first_x) << what;
          EXPECT_EQ(stats.first_nonfinite_y, p.first_y) << what;
          EXPECT_EQ(stats.max_value, 1.5) << what;
          shpack::ProjectOptions plain;
          ShL2 want;
          const shpack::ImageView clean = neg == Negative::Clamp ? (half ? view_of(h_clamped, w, h) : view_of(p.clamped, w, h))
                                                                 : (half ? view_of(h_zeroed, w, h) : view_of(p.zeroed, w, h));
          ASSERT_TRUE(shpack::project_equirect(clean, plain, want).ok());
          EXPECT_EQ(sh, want) << what;
          for (const auto& channel : sh.c)
            for (double v : channel) EXPECT_TRUE(std::isfinite(v)) << what;
        }
      }
    }
  }
}

TEST(Values, NonFiniteAndNegativeTexelsInCubeFaces) {
  // The same policies on a 9 x 9 cube with the planted texels on face -Y (face 3).
  const std::uint32_t n = 9;
  const Planted p = planted(n, n);
  std::array<std::vector<float>, 6> faces, cleaned;
  for (int f = 0; f < 6; ++f) faces[f] = cleaned[f] = std::vector<float>(std::size_t{3} * n * n, 0.75f);
  faces[3] = p.rgb;
  cleaned[3] = p.clamped;
  std::array<shpack::ImageView, 6> views, clean_views;
  for (int f = 0; f < 6; ++f) {
    views[f] = view_of(faces[f], n, n);
    clean_views[f] = view_of(cleaned[f], n, n);
  }
  ShL2 sh;
  shpack::Status st = shpack::project_cube(views, {}, sh);
  EXPECT_EQ(st.code, Errc::NonFiniteTexel);
  EXPECT_EQ(st.face, 3u);
  EXPECT_EQ(st.x, p.first_x);
  EXPECT_EQ(st.y, p.first_y);
  shpack::ProjectOptions options;
  options.nonfinite = NonFinite::Zero;
  options.negative = Negative::Clamp;
  shpack::ProjectStats stats;
  ASSERT_TRUE(shpack::project_cube(views, options, sh, &stats).ok());
  EXPECT_EQ(stats.nonfinite_texels, p.nonfinite);
  EXPECT_EQ(stats.negative_texels, p.negative);
  ShL2 want;
  ASSERT_TRUE(shpack::project_cube(clean_views, {}, want).ok());
  EXPECT_EQ(sh, want);
}

TEST(Values, DenormalTexelsAreNotFlushedToZero) {
  // A scene of subnormal radiance (binary32 1e-40 and the smallest, 2^-149; half 2^-24):
  // double has 300 orders of magnitude of room, so L00 = 2 sqrt(pi) v to the same relative
  // bound as any other uniform scene (equirect_sum_tol), in the vector kernel (W = 32), the
  // scalar loader (W = 5) and the half path. A kernel running with flush-to-zero or
  // denormals-are-zero would return exactly 0.
  struct Case {
    const char* name;
    float value;
    bool half;
  };
  for (const Case k : {Case{"1e-40", kDenormal, false}, Case{"2^-149", std::numeric_limits<float>::denorm_min(), false},
                       Case{"half 2^-24", 0x1p-24f, true}}) {
    for (auto [w, h] : {std::pair<std::uint32_t, std::uint32_t>{32, 16}, {5, 3}}) {
      const std::vector<float> rgb(std::size_t{3} * w * h, k.value);
      const std::vector<std::uint16_t> half(rgb.size(), 0x0001);  // half 2^-24
      for (unsigned threads : {1u, 2u}) {
        shpack::ProjectOptions options;
        options.threads = threads;
        ShL2 sh;
        shpack::ProjectStats stats;
        ASSERT_TRUE(shpack::project_equirect(k.half ? view_of(half, w, h) : view_of(rgb, w, h), options, sh, &stats).ok());
        const EquirectOracle oracle(w, h);
        const ShLd want = oracle.project(rgb);
        const Tol tol = equirect_sum_tol(oracle, w, h, rgb, want);
        const double l00 = 2 * std::sqrt(std::numbers::pi) * static_cast<double>(k.value);
        EXPECT_GT(sh.c[0][0], 0.0) << k.name;
        EXPECT_NEAR(sh.c[0][0], l00, tol[0][0] + 4 * kU * l00) << k.name << " W=" << w;
        expect_within(sh, want, tol, std::string(k.name) + " W=" + std::to_string(w));
        EXPECT_EQ(stats.max_value, static_cast<double>(k.value)) << k.name;
        EXPECT_EQ(stats.negative_texels, 0u);
      }
    }
  }
}

// Every output of an all-zero scene: coefficients, packing, minimum, windows, rotation.
void expect_black_everywhere(const ShL2& radiance, const std::string& what) {
  for (const auto& channel : radiance.c)
    for (double v : channel) EXPECT_EQ(v, 0.0) << what;
  const ShL2 unity = shpack::radiance_to_unity_form(radiance);
  for (const auto& channel : shpack::to_unity_sh(unity))
    for (float v : channel) EXPECT_EQ(v, 0.0f) << what;
  const shpack::UnityShaderVectors vectors = shpack::to_shader_vectors(unity);
  for (const auto* v : {&vectors.SHAr, &vectors.SHAg, &vectors.SHAb, &vectors.SHBr, &vectors.SHBg, &vectors.SHBb})
    for (float x : *v) EXPECT_EQ(x, 0.0f) << what;
  EXPECT_EQ(vectors.SHC[3], 1.0f);
  for (int c = 0; c < 3; ++c) {
    const shpack::SphereMinimum m = shpack::minimum_on_sphere(unity, c);
    EXPECT_EQ(m.value, 0.0) << what << " c=" << c;
    const double len = std::hypot(m.direction.x, m.direction.y, m.direction.z);
    EXPECT_NEAR(len, 1.0, 4 * kU) << what << " the direction is a unit vector, not NaN";
  }
  for (const char* name : {"none", "hanning:0.5", "hanning:1", "hanning:3", "lanczos:2", "lanczos:1e6", "unity", "sloan"}) {
    shpack::Window window;
    ASSERT_TRUE(shpack::parse_window(name, window).ok()) << name;
    ShL2 out;
    shpack::WindowResult result;
    ASSERT_TRUE(shpack::apply_window(unity, window, out, &result).ok()) << name;
    for (int c = 0; c < 3; ++c) {
      for (double v : out.c[c]) EXPECT_EQ(v, 0.0) << what << " window " << name;
      for (double f : result.factors[c]) EXPECT_TRUE(std::isfinite(f)) << what << " window " << name;
      EXPECT_FALSE(result.impossible[c]) << what << " window " << name;
      EXPECT_EQ(shpack::minimum_on_sphere(out, c).value, 0.0) << what << " window " << name;
    }
  }
  const ShL2 turned = shpack::rotate_about_y(radiance, 37.0);
  for (const auto& channel : turned.c)
    for (double v : channel) EXPECT_EQ(v, 0.0) << what << " rotated";
}

TEST(Values, AllBlackScenesAreExactZerosWithoutNaN) {
  for (float zero : {0.0f, -0.0f}) {
    for (auto [w, h] : {std::pair<std::uint32_t, std::uint32_t>{1, 1}, {16, 8}, {17, 9}, {3, 130}}) {
      const std::vector<float> rgb(std::size_t{3} * w * h, zero);
      for (shpack::SamplingMethod method : {shpack::SamplingMethod::Exact, shpack::SamplingMethod::Center}) {
        shpack::ProjectOptions options;
        options.method = method;
        options.negative = Negative::Clamp;
        ShL2 sh;
        shpack::ProjectStats stats;
        ASSERT_TRUE(shpack::project_equirect(view_of(rgb, w, h), options, sh, &stats).ok());
        EXPECT_EQ(stats.negative_texels, 0u) << "-0 is not negative";
        EXPECT_EQ(stats.max_value, 0.0);
        expect_black_everywhere(sh, "equirect " + std::to_string(w) + "x" + std::to_string(h));
      }
    }
    for (std::uint32_t n : {1u, 4u}) {
      const std::vector<float> face(std::size_t{3} * n * n, zero);
      std::array<shpack::ImageView, 6> views;
      views.fill(view_of(face, n, n));
      ShL2 sh;
      ASSERT_TRUE(shpack::project_cube(views, {}, sh).ok());
      expect_black_everywhere(sh, "cube " + std::to_string(n));
    }
  }
  // sh_minimum and the windows on the all-zero coefficients directly.
  expect_black_everywhere(ShL2{}, "ShL2{}");
}

TEST(Values, HugeAndTinyUniformScenes) {
  // All texels 1e30, FLT_MAX and 1e-30: L00 = 2 sqrt(pi) v and the rest 0, to
  // equirect_sum_tol (relative, so the same at every scale: nothing overflows or underflows
  // in double, whose range is 1e+-308). The Unity-form L00 is v itself, which fits in float
  // even at FLT_MAX (the double is within 1e-14 of it, far inside half a float ulp, so it
  // rounds to FLT_MAX, not to Inf); the minimum of E/pi is v; no window changes a uniform
  // scene beyond its (zero) higher bands.
  for (float v : {1e30f, FLT_MAX, 1e-30f}) {
    for (auto [w, h] : {std::pair<std::uint32_t, std::uint32_t>{64, 32}, {5, 3}}) {
      const std::vector<float> rgb(std::size_t{3} * w * h, v);
      ShL2 sh;
      ASSERT_TRUE(shpack::project_equirect(view_of(rgb, w, h), {}, sh).ok());
      const EquirectOracle oracle(w, h);
      const ShLd want = oracle.project(rgb);
      const Tol tol = equirect_sum_tol(oracle, w, h, rgb, want);
      const std::string what = "v=" + std::to_string(v) + " W=" + std::to_string(w);
      const double worst = expect_within(sh, want, tol, what);
      const double packed = expect_packed(sh, want, tol, what);
      const ShL2 unity = shpack::radiance_to_unity_form(sh);
      const shpack::UnitySphericalHarmonicsL2 floats = shpack::to_unity_sh(unity);
      EXPECT_EQ(floats[0][0], v) << what;
      const shpack::UnityShaderVectors vectors = shpack::to_shader_vectors(unity);
      EXPECT_EQ(vectors.SHAr[3], v) << what;
      for (int c = 0; c < 3; ++c) {
        const shpack::SphereMinimum m = shpack::minimum_on_sphere(unity, c);
        EXPECT_NEAR(m.value, v, 1e-12 * v) << what;
        shpack::Window sloan;
        ASSERT_TRUE(shpack::parse_window("sloan", sloan).ok());
        ShL2 out;
        shpack::WindowResult result;
        ASSERT_TRUE(shpack::apply_window(unity, sloan, out, &result).ok());
        EXPECT_FALSE(result.impossible[c]);
        EXPECT_EQ(out.c[c][0], unity.c[c][0]) << what;
      }
      std::cout << "[ measure  ] uniform " << v << " " << w << "x" << h << ": max err/tol = " << worst
                << ", packed floats: max error/tol = " << packed << "\n";
    }
  }
}

}  // namespace
}  // namespace shpack_hard
