// sizes_test.cpp - tiny and odd image sizes: 1x1, 2x1, 1x2, 3x1, odd sizes, sizes that are
// not multiples of the 64-row tile or the 8-lane row kernel, 1x1 cube faces and odd cube
// sizes. Each is the exact projection of its piecewise-constant image (long-double oracle,
// derived rounding bound of checks.h), bit-identical for any thread count and any split
// into streamed bands (project.h). The 16384 x 8192 map is large_streaming_test.cpp.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "hard_cases/checks.h"
#include "hard_cases/hard_case_support.h"
#include "shpack/project.h"
#include "shpack/project_cube.h"
#include "support/test_util.h"

namespace shpack_hard {
namespace {

using shpack_test::describe;

struct Size {
  std::uint32_t w, h;
};

// Log-uniform values in [0.01, 100] per texel and channel.
std::vector<float> random_image(std::uint32_t w, std::uint32_t h, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> e(-2.0, 2.0);
  std::vector<float> rgb(std::size_t{3} * w * h);
  for (float& v : rgb) v = static_cast<float>(std::pow(10.0, e(rng)));
  return rgb;
}

ShL2 project(const std::vector<float>& rgb, Size s, unsigned threads) {
  shpack::ProjectOptions options;
  options.threads = threads;
  ShL2 sh;
  const shpack::Status st = shpack::project_equirect(shpack::make_view(rgb.data(), s.w, s.h, 3), options, sh);
  EXPECT_TRUE(st.ok()) << describe(st) << " W=" << s.w << " H=" << s.h;
  return sh;
}

// Streamed in bands of `band` rows (the last one shorter).
ShL2 project_in_bands(const std::vector<float>& rgb, Size s, std::uint32_t band) {
  shpack::EquirectProjector projector;
  ShL2 sh;
  EXPECT_TRUE(projector.begin(s.w, s.h, {}).ok());
  for (std::uint32_t y = 0; y < s.h; y += band) {
    const std::uint32_t n = std::min(band, s.h - y);
    const shpack::Status st = projector.add_rows(shpack::make_view(rgb.data() + std::size_t{3} * s.w * y, s.w, n, 3), y);
    EXPECT_TRUE(st.ok()) << describe(st);
  }
  EXPECT_TRUE(projector.finish(sh).ok());
  return sh;
}

TEST(Sizes, TinyAndOddEquirectImagesAreExact) {
  // Every size: W and H below, at and above the kernel's 8 lanes and the 64-row tile, odd
  // and prime, degenerate (one row, one column).
  const Size sizes[] = {{1, 1},  {2, 1},   {1, 2},   {3, 1},   {1, 3},    {3, 2},    {2, 3},    {5, 3},
                        {7, 5},  {9, 9},   {15, 7},  {17, 9},  {31, 16},  {33, 17},  {127, 63}, {129, 65},
                        {1, 1000}, {1001, 1}, {3, 131}, {131, 67}, {8, 64},  {9, 65}};
  double worst = 0;
  for (const Size s : sizes) {
    const std::vector<float> rgb = random_image(s.w, s.h, 0x5eed + s.w * 1000 + s.h);
    const EquirectOracle oracle(s.w, s.h);
    const ShLd want = oracle.project(rgb);
    const Tol tol = equirect_sum_tol(oracle, s.w, s.h, rgb, want);
    const std::string what = "W=" + std::to_string(s.w) + " H=" + std::to_string(s.h);
    const ShL2 one = project(rgb, s, 1);
    worst = std::max(worst, expect_within(one, want, tol, what));
    expect_packed(one, want, tol, what);
    EXPECT_EQ(one, project(rgb, s, 2)) << what << " threads 1 vs 2";
    EXPECT_EQ(one, project(rgb, s, 3)) << what << " threads 1 vs 3";
    EXPECT_EQ(one, project_in_bands(rgb, s, 1)) << what << " bands of 1 row";
    EXPECT_EQ(one, project_in_bands(rgb, s, 7)) << what << " bands of 7 rows";
  }
  std::cout << "[ measure  ] tiny and odd equirect sizes: max err/tol = " << worst << "\n";
}

TEST(Sizes, OneTexelIsAUniformEnvironment) {
  // Closed form, no oracle: L00 = int v Y0 = 4 pi k0 v = 2 sqrt(pi) v, and every other
  // coefficient integrates to 0 over the sphere. Bound: equirect_sum_tol with W = 1,
  // S = 4 pi v: (1 + 26) * 4 + 1 = 109 u * k_i * 4 pi v, plus 2u |L00|.
  for (float v : {1.0f, 0.1f, 3e38f, 1e-30f}) {
    const std::vector<float> rgb = {v, v / 2, v / 4};
    const ShL2 sh = project(rgb, {1, 1}, 1);
    for (int c = 0; c < 3; ++c) {
      const double value = rgb[c];
      const double l00 = 2 * std::sqrt(std::numbers::pi) * value;
      EXPECT_NEAR(sh.c[c][0], l00, (109 * shpack::kY0 * 4 * std::numbers::pi + 2) * kU * l00) << "v=" << v;
      for (int i = 1; i < 9; ++i)
        EXPECT_LE(std::fabs(sh.c[c][i]), 109 * kU * shpack::kBasisScale[i] * 4 * std::numbers::pi * value)
            << "v=" << v << " c=" << c << " i=" << i;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Cubes

struct Faces {
  std::uint32_t n;
  std::array<std::vector<float>, 6> rgb;
  std::array<shpack::ImageView, 6> views() const {
    std::array<shpack::ImageView, 6> v;
    for (int f = 0; f < 6; ++f) v[f] = shpack::make_view(rgb[f].data(), n, n, 3);
    return v;
  }
};

Faces random_cube(std::uint32_t n, std::uint64_t seed) {
  Faces faces{n, {}};
  for (int f = 0; f < 6; ++f) faces.rgb[f] = random_image(n, n, seed + f);
  return faces;
}

// Sum of texel values times oracle integrals, long double; and sum |v| Omega per channel.
ShLd cube_oracle_projection(const Faces& cube, std::array<long double, 3>& abs_integral) {
  ShLd want{};
  abs_integral = {};
  for (int f = 0; f < 6; ++f)
    for (std::uint32_t y = 0; y < cube.n; ++y)
      for (std::uint32_t x = 0; x < cube.n; ++x) {
        const std::array<long double, 10> t = cube_texel_oracle(cube.n, f, x, y);
        for (int c = 0; c < 3; ++c) {
          const float v = cube.rgb[f][(std::size_t{y} * cube.n + x) * 3 + c];
          for (int i = 0; i < 9; ++i) want[c][i] += v * t[i];
          abs_integral[c] += std::fabs(v) * t[9];
        }
      }
  return want;
}

TEST(Sizes, OneByOneAndOddCubeFaces) {
  // 1x1 faces: each texel is a whole face (the six sum to the sphere). Bound: per texel
  // weight within ~10 u / h of k_i Omega (project_cube.h, h = 2/N), 4-lane row sums
  // (N/4 + 2 levels), Neumaier over rows and faces, |P_i| <= 2:
  //   |err| <= (10 N/2 + N/4 + 8) u * 2 k_i * sum |v| Omega + 2u |L|.
  double worst = 0;
  for (std::uint32_t n : {1u, 2u, 3u, 5u, 7u, 9u, 65u}) {
    const Faces cube = random_cube(n, 0xc0be + n);
    std::array<long double, 3> abs_integral{};
    const ShLd want = cube_oracle_projection(cube, abs_integral);
    Tol tol{};
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 9; ++i)
        tol[c][i] = (10.0 * n / 2 + n / 4.0 + 8) * kU * 2 * shpack::kBasisScale[i] * static_cast<double>(abs_integral[c]) +
                    2 * kU * static_cast<double>(std::fabs(want[c][i]));
    ShL2 one, two;
    shpack::ProjectOptions options;
    ASSERT_TRUE(shpack::project_cube(cube.views(), options, one).ok());
    options.threads = 2;
    ASSERT_TRUE(shpack::project_cube(cube.views(), options, two).ok());
    const std::string what = "cube N=" + std::to_string(n);
    worst = std::max(worst, expect_within(one, want, tol, what));
    expect_packed(one, want, tol, what);
    EXPECT_EQ(one, two) << what << " threads 1 vs 2";
  }
  std::cout << "[ measure  ] 1x1 and odd cube faces: max err/tol = " << worst << "\n";

  // A uniform 1x1 cube is the white furnace: L00 = 2 sqrt(pi) v, others 0; as six 1x1
  // faces cut from one 6x1 strip, float and half. Bound as above with N = 1:
  // (10/2 + 1/4 + 8) = 13.25 u * 2 k_i * sum |v| Omega.
  const float strip[18] = {2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2};
  const std::uint16_t half_strip[18] = {0x4000, 0x4000, 0x4000, 0x4000, 0x4000, 0x4000, 0x4000, 0x4000, 0x4000,
                                        0x4000, 0x4000, 0x4000, 0x4000, 0x4000, 0x4000, 0x4000, 0x4000, 0x4000};
  for (shpack::PixelType type : {shpack::PixelType::F32, shpack::PixelType::F16}) {
    std::array<shpack::ImageView, 6> faces;
    for (int f = 0; f < 6; ++f) {
      const std::byte* base = type == shpack::PixelType::F32 ? reinterpret_cast<const std::byte*>(strip + 3 * f)
                                                            : reinterpret_cast<const std::byte*>(half_strip + 3 * f);
      faces[f] = {base, type, 1, 1, 3};
    }
    ShL2 sh;
    ASSERT_TRUE(shpack::project_cube(faces, {}, sh).ok());
    for (int c = 0; c < 3; ++c) {
      const double l00 = 2 * std::sqrt(std::numbers::pi) * 2.0;
      const double s = 2.0 * 4 * std::numbers::pi;  // sum |v| Omega
      EXPECT_NEAR(sh.c[c][0], l00, 13.25 * kU * 2 * shpack::kY0 * s + 2 * kU * l00);
      for (int i = 1; i < 9; ++i) EXPECT_LE(std::fabs(sh.c[c][i]), 13.25 * kU * 2 * shpack::kBasisScale[i] * s) << "i=" << i;
    }
  }
}

// ---------------------------------------------------------------------------------------
// Views

TEST(Views, HugeButRepresentableStridesAreChecked) {
  // resolve_view only validates: nothing is read, so any data pointer will do. Strides and
  // sizes at the edge of int64 that do not overflow are accepted or rejected by the rules of
  // image_view.h (pixels and rows must not overlap).
  const float texel[3] = {1, 1, 1};
  shpack::ImageView v = shpack::make_view(texel, 1u << 31, 2, 3);
  v.pixel_stride = std::int64_t{1} << 31;  // 2^31 * 2^31 = 2^62 fits
  EXPECT_TRUE(shpack::resolve_view(v).ok());
  EXPECT_EQ(v.row_stride, std::int64_t{1} << 62);
  v = shpack::make_view(texel, 0xffffffffu, 0xffffffffu, 3);
  v.row_stride = 12;  // rows overlap
  EXPECT_EQ(shpack::resolve_view(v).code, shpack::Errc::BadView);
}

// Regression for a bug fuzz_project found: resolve_view formed
// llabs(pixel_stride) * width in int64 unchecked, so a pixel stride of 2^62 and a width of 4
// was signed overflow (UBSan abort) in the function whose job is to reject bad views, and
// llabs(INT64_MIN) is itself undefined. Every byte offset ImageView::pixel() can form,
// |row_stride| (height - 1) + |pixel_stride| (width - 1), must fit in int64.
TEST(Views, AbsurdStridesAreBadViewsNotOverflow) {
  const float texel[3] = {1, 1, 1};
  for (std::int64_t stride : {std::int64_t{1} << 62, -(std::int64_t{1} << 62), INT64_MAX, INT64_MIN + 1}) {  // INT64_MIN is kAutoStride
    shpack::ImageView v = shpack::make_view(texel, 4, 1, 3);
    v.pixel_stride = stride;
    EXPECT_EQ(shpack::resolve_view(v).code, shpack::Errc::BadView) << stride;
  }
  // Rows that fit one by one but whose stack does not: 2^61 (3 rows - 1) = 2^62 is fine,
  // 2^62 (3 - 1) = 2^63 is one past INT64_MAX.
  shpack::ImageView v = shpack::make_view(texel, 1, 3, 3);
  v.row_stride = std::int64_t{1} << 61;
  EXPECT_TRUE(shpack::resolve_view(v).ok());
  v.row_stride = -(std::int64_t{1} << 62);
  EXPECT_EQ(shpack::resolve_view(v).code, shpack::Errc::BadView);
}

}  // namespace
}  // namespace shpack_hard
