// texel_policy_test.cpp - NaN/Inf and negative texels: explicit policies, counted in
// ProjectStats, first non-finite texel located in row-major order whatever the threads
// and bands.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "shpack/project.h"
#include "support/equirect_oracle.h"
#include "support/rgb_image.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

using shpack::Errc;
using shpack::ShL2;

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

RgbImage positive_image(std::uint32_t w, std::uint32_t h, std::uint64_t seed) {
  return shpack_test::uniform_random_image(w, h, seed, 0.5f, 50.0f);
}

shpack::ProjectOptions options(shpack::NonFinite nf, shpack::Negative neg = shpack::Negative::Keep,
                               unsigned threads = 1) {
  shpack::ProjectOptions o;
  o.nonfinite = nf;
  o.negative = neg;
  o.threads = threads;
  return o;
}

TEST(TexelPolicy, NonFiniteErrorReportsFirstInRowMajorOrder) {
  // (9, 2) comes first in row-major order, (1, 5) in column-major order.
  RgbImage img = positive_image(16, 8, 1);
  img.at(9, 2, 1) = kNaN;
  img.at(1, 5, 0) = kInf;
  img.at(3, 7, 2) = -kInf;
  ShL2 sh;
  shpack::Status st = shpack::project_equirect(img.view(), options(shpack::NonFinite::Error), sh);
  EXPECT_EQ(st.code, Errc::NonFiniteTexel) << describe(st);
  EXPECT_EQ(st.x, 9u);
  EXPECT_EQ(st.y, 2u);
  // Each kind alone is detected too.
  for (float bad : {kNaN, kInf, -kInf}) {
    RgbImage one = positive_image(16, 8, 2);
    one.at(12, 6, 2) = bad;
    st = shpack::project_equirect(one.view(), options(shpack::NonFinite::Error), sh);
    EXPECT_EQ(st.code, Errc::NonFiniteTexel) << "value=" << bad;
    EXPECT_EQ(st.x, 12u) << "value=" << bad;
    EXPECT_EQ(st.y, 6u) << "value=" << bad;
  }
}

TEST(TexelPolicy, NonFiniteFirstLocationIndependentOfThreadsAndBands) {
  // 200 rows = 4 tiles; the first bad texel (50, 70) is in tile 1, a later one in tile 2,
  // and one in tile 3 at a smaller x.
  RgbImage img = positive_image(64, 200, 3);
  img.at(50, 70, 0) = kNaN;
  img.at(3, 150, 1) = kInf;
  img.at(60, 71, 2) = kNaN;
  for (unsigned threads : {1u, 2u, 3u}) {
    ShL2 sh;
    const shpack::Status st = shpack::project_equirect(img.view(), options(shpack::NonFinite::Error,
                                                                           shpack::Negative::Keep, threads), sh);
    EXPECT_EQ(st.code, Errc::NonFiniteTexel) << "threads=" << threads;
    EXPECT_EQ(st.x, 50u) << "threads=" << threads;
    EXPECT_EQ(st.y, 70u) << "threads=" << threads;
    // Streaming in bands of 7: the band holding row 70 fails, with image coordinates.
    shpack::EquirectProjector p;
    ASSERT_TRUE(p.begin(64, 200, options(shpack::NonFinite::Error, shpack::Negative::Keep, threads)).ok());
    shpack::Status band_status;
    std::uint32_t row = 0;
    for (; row < 200; row += 7) {
      const std::uint32_t n = std::min(7u, 200 - row);
      band_status = p.add_rows(shpack::make_view(img.rgb.data() + std::size_t{3} * 64 * row, 64, n, 3), row);
      if (!band_status.ok()) break;
    }
    EXPECT_EQ(band_status.code, Errc::NonFiniteTexel) << "threads=" << threads;
    EXPECT_EQ(band_status.x, 50u) << "threads=" << threads;
    EXPECT_EQ(band_status.y, 70u) << "threads=" << threads;
    EXPECT_EQ(row, 70u) << "the failing band is rows [70, 77)";
  }
}

TEST(TexelPolicy, NonFiniteZeroCountsAndTreatsAsZero) {
  RgbImage img = positive_image(40, 130, 4);
  RgbImage zeroed = img;
  // Four texels, every channel NaN or Inf (the core zeroes non-finite channels).
  const std::pair<std::uint32_t, std::uint32_t> bad[] = {{7, 100}, {39, 3}, {0, 129}, {20, 64}};
  for (auto [x, y] : bad) {
    for (int c = 0; c < 3; ++c) {
      img.at(x, y, c) = (x + c) % 2 == 0 ? kNaN : kInf;
      zeroed.at(x, y, c) = 0.0f;
    }
  }
  for (unsigned threads : {1u, 3u}) {
    ShL2 got, want;
    shpack::ProjectStats stats, zstats;
    const shpack::Status st = shpack::project_equirect(
        img.view(), options(shpack::NonFinite::Zero, shpack::Negative::Keep, threads), got, &stats);
    ASSERT_TRUE(st.ok()) << describe(st);
    ASSERT_TRUE(shpack::project_equirect(zeroed.view(), options(shpack::NonFinite::Error), want, &zstats).ok());
    EXPECT_EQ(want, got) << "threads=" << threads;
    EXPECT_EQ(stats.nonfinite_texels, 4u) << "threads=" << threads;
    EXPECT_EQ(stats.first_nonfinite_x, 39u) << "threads=" << threads;
    EXPECT_EQ(stats.first_nonfinite_y, 3u) << "threads=" << threads;
    EXPECT_EQ(stats.negative_texels, 0u);
    EXPECT_EQ(stats.max_value, zstats.max_value) << "max over finite values only";
  }
}

TEST(TexelPolicy, NonFiniteInIgnoredChannelIsNotATexelError) {
  const std::uint32_t w = 12, h = 6;
  std::vector<float> rgba(std::size_t{4} * w * h, 1.0f);
  rgba[4 * 17 + 3] = kNaN;  // alpha of texel 17
  rgba[4 * 40 + 3] = kInf;
  ShL2 sh;
  shpack::ProjectStats stats;
  const shpack::Status st =
      shpack::project_equirect(shpack::make_view(rgba.data(), w, h, 4), options(shpack::NonFinite::Error), sh, &stats);
  EXPECT_TRUE(st.ok()) << describe(st);
  EXPECT_EQ(stats.nonfinite_texels, 0u);
}

TEST(TexelPolicy, NegativeTexelsAreCountedKeptOrClamped) {
  RgbImage img = positive_image(24, 70, 5);
  RgbImage clamped = img;
  // Three texels with negatives (one with two negative channels), -0 is not negative.
  const std::pair<std::uint32_t, std::uint32_t> neg[] = {{3, 0}, {23, 65}, {10, 33}};
  for (auto [x, y] : neg) {
    img.at(x, y, 1) = -2.5f;
    clamped.at(x, y, 1) = 0.0f;
  }
  img.at(10, 33, 2) = -0.125f;
  clamped.at(10, 33, 2) = 0.0f;
  img.at(5, 5, 0) = -0.0f;
  clamped.at(5, 5, 0) = -0.0f;
  for (unsigned threads : {1u, 2u}) {
    ShL2 keep, clamp, want_clamp;
    shpack::ProjectStats ks, cs;
    ASSERT_TRUE(shpack::project_equirect(img.view(), options(shpack::NonFinite::Error, shpack::Negative::Keep, threads),
                                         keep, &ks).ok());
    ASSERT_TRUE(shpack::project_equirect(img.view(),
                                         options(shpack::NonFinite::Error, shpack::Negative::Clamp, threads), clamp, &cs)
                    .ok());
    ASSERT_TRUE(shpack::project_equirect(clamped.view(), options(shpack::NonFinite::Error), want_clamp).ok());
    EXPECT_EQ(ks.negative_texels, 3u) << "threads=" << threads;
    EXPECT_EQ(cs.negative_texels, 3u) << "threads=" << threads;
    EXPECT_EQ(want_clamp, clamp) << "threads=" << threads;
    EXPECT_NE(keep, clamp) << "Keep must keep the negative values";
  }
}

TEST(TexelPolicy, SingleNegativeTexelKeptIsItsSignedIntegral) {
  // Keep: the negative value contributes v * int_t Y_i like any other (1e-12 relative to
  // the coefficient norm, see projection_exactness_test.cpp); Clamp: exactly nothing.
  RgbImage img(16, 8);
  img.set(5, 2, -3.0f, -0.5f, -7.0f);
  ShL2 keep, clamp;
  ASSERT_TRUE(shpack::project_equirect(img.view(), {}, keep).ok());
  ASSERT_TRUE(shpack::project_equirect(img.view(), options(shpack::NonFinite::Error, shpack::Negative::Clamp), clamp).ok());
  const ShL2 want = to_sh(texel_basis_integral(5, 2, 16, 8), {-3.0, -0.5, -7.0});
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) {
      EXPECT_NEAR(want.c[c][i], keep.c[c][i], 1e-12 * channel_norm(want, c)) << "c=" << c << " i=" << i;
      EXPECT_EQ(clamp.c[c][i], 0.0) << "c=" << c << " i=" << i;
    }
}

TEST(TexelPolicy, MaxValueIsTheLargestFiniteChannel) {
  for (std::uint32_t w : {16u, 17u}) {  // vector path and tail
    RgbImage img = positive_image(w, 9, 6);
    img.at(w - 1, 8, 2) = 1234.5f;
    shpack::ProjectStats s;
    ShL2 sh;
    ASSERT_TRUE(shpack::project_equirect(img.view(), {}, sh, &s).ok());
    EXPECT_EQ(s.max_value, 1234.5) << "W=" << w;
    RgbImage negative(w, 3);
    for (float& v : negative.rgb) v = -1.0f;
    ASSERT_TRUE(shpack::project_equirect(negative.view(), {}, sh, &s).ok());
    EXPECT_EQ(s.max_value, 0.0) << "no positive value: 0 (project.h)";
    EXPECT_EQ(s.negative_texels, std::uint64_t{w} * 3);
  }
}

}  // namespace
}  // namespace shpack_test
