// row_kernel_test.cpp - the row kernels' two paths give the same result bit for bit: float
// RGB and RGBA rows of packed texels take the vector kernels (policies applied inside
// them), any other layout the portable loader. The same texels in a padded layout (five
// floats a texel) are the reference: the projection, the counts, the first NaN/Inf texel
// and the largest value must be equal, on maps whose every row holds NaN, Inf, negative,
// negative subnormal and -0 values at columns of every vector lane and of the tails.
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "shpack/project.h"
#include "shpack/project_cube.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

using shpack::Negative;
using shpack::NonFinite;

// A float image with `floats_per_texel` floats a texel (R, G, B, then 1s), rows packed.
struct StridedImage {
  std::uint32_t width = 0, height = 0, floats_per_texel = 0;
  std::vector<float> data;

  shpack::ImageView view() const {
    const std::uint32_t channels = floats_per_texel == 4 ? 4 : 3;
    return {reinterpret_cast<const std::byte*>(data.data()), shpack::PixelType::F32, width, height, channels,
            std::int64_t{4} * floats_per_texel, shpack::kAutoStride};
  }
};

StridedImage strided(const std::vector<float>& rgb, std::uint32_t w, std::uint32_t h, std::uint32_t floats) {
  StridedImage img{w, h, floats, std::vector<float>(std::size_t{floats} * w * h, 1.0f)};
  for (std::size_t t = 0; t < std::size_t{w} * h; ++t)
    for (std::size_t c = 0; c < 3; ++c) img.data[t * floats + c] = rgb[t * 3 + c];
  return img;
}

// Positive values, then in every row six texels given a value from every class the
// policies tell apart, at random columns and channels.
std::vector<float> unclean_rgb(std::uint32_t w, std::uint32_t h, std::uint64_t seed) {
  const float specials[] = {-2.5f, -0.0f, -1e-40f, std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                            -FLT_MAX, 7.0f};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> value(0.0f, 8.0f);
  std::uniform_int_distribution<std::uint32_t> column(0, w - 1), channel(0, 2), kind(0, 7);
  std::vector<float> rgb(std::size_t{3} * w * h);
  for (float& v : rgb) v = value(rng);
  for (std::uint32_t y = 0; y < h; ++y)
    for (int k = 0; k < 6; ++k) rgb[(std::size_t{y} * w + column(rng)) * 3 + channel(rng)] = specials[kind(rng)];
  return rgb;
}

shpack::ProjectOptions policy(NonFinite nonfinite, Negative negative) {
  shpack::ProjectOptions o;
  o.nonfinite = nonfinite;
  o.negative = negative;
  o.threads = 1;
  return o;
}

void expect_same_stats(const shpack::ProjectStats& want, const shpack::ProjectStats& got, const char* what) {
  EXPECT_EQ(want.nonfinite_texels, got.nonfinite_texels) << what;
  EXPECT_EQ(want.negative_texels, got.negative_texels) << what;
  EXPECT_EQ(want.first_nonfinite_x, got.first_nonfinite_x) << what;
  EXPECT_EQ(want.first_nonfinite_y, got.first_nonfinite_y) << what;
  EXPECT_EQ(want.first_nonfinite_face, got.first_nonfinite_face) << what;
  EXPECT_EQ(want.max_value, got.max_value) << what;
}

// 61 columns: 7 groups of 8 and a tail of 5, 15 groups of 4 and a tail of 1.
constexpr std::uint32_t kWidth = 61, kHeight = 70;

TEST(RowKernel, EquirectVectorPathEqualsThePortableLoaderUnderEveryPolicy) {
  const std::vector<float> rgb = unclean_rgb(kWidth, kHeight, 0x5eed);
  const StridedImage reference = strided(rgb, kWidth, kHeight, 5);
  for (Negative negative : {Negative::Keep, Negative::Clamp}) {
    const shpack::ProjectOptions options = policy(NonFinite::Zero, negative);
    shpack::ShL2 want;
    shpack::ProjectStats want_stats;
    ASSERT_TRUE(shpack::project_equirect(reference.view(), options, want, &want_stats).ok());
    ASSERT_GT(want_stats.nonfinite_texels, kHeight / 2) << "NaN/Inf in most rows";
    ASSERT_GT(want_stats.negative_texels, kHeight / 2) << "negatives in most rows";
    for (std::uint32_t floats : {3u, 4u}) {
      shpack::ShL2 got;
      shpack::ProjectStats got_stats;
      ASSERT_TRUE(shpack::project_equirect(strided(rgb, kWidth, kHeight, floats).view(), options, got, &got_stats).ok());
      EXPECT_EQ(want, got) << "floats per texel " << floats << " clamp " << (negative == Negative::Clamp);
      expect_same_stats(want_stats, got_stats, floats == 3 ? "RGB" : "RGBA");
    }
  }
}

TEST(RowKernel, ClampedMapEqualsTheMapWithThePoliciesAppliedBeforehand) {
  // Independent of both loaders' policy code: NaN/Inf and negatives set to 0 by hand, then
  // projected as a clean map; -0 stays -0 (it is not below 0).
  std::vector<float> rgb = unclean_rgb(kWidth, kHeight, 7);
  const StridedImage unclean = strided(rgb, kWidth, kHeight, 3);
  for (float& v : rgb)
    if (!std::isfinite(v) || v < 0.0f) v = 0.0f;
  shpack::ShL2 want, got;
  ASSERT_TRUE(shpack::project_equirect(strided(rgb, kWidth, kHeight, 3).view(), policy(NonFinite::Error, Negative::Keep),
                                       want).ok());
  ASSERT_TRUE(shpack::project_equirect(unclean.view(), policy(NonFinite::Zero, Negative::Clamp), got).ok());
  EXPECT_EQ(want, got);
}

TEST(RowKernel, FirstNonFiniteTexelIsTheSameOnBothPaths) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const std::vector<float> rgb = unclean_rgb(kWidth, kHeight, seed);
    shpack::ShL2 sh;
    const shpack::Status want = shpack::project_equirect(strided(rgb, kWidth, kHeight, 5).view(),
                                                         policy(NonFinite::Error, Negative::Keep), sh);
    ASSERT_EQ(want.code, shpack::Errc::NonFiniteTexel) << "seed " << seed;
    for (std::uint32_t floats : {3u, 4u}) {
      const shpack::Status got = shpack::project_equirect(strided(rgb, kWidth, kHeight, floats).view(),
                                                          policy(NonFinite::Error, Negative::Keep), sh);
      EXPECT_EQ(got.code, shpack::Errc::NonFiniteTexel) << "seed " << seed << " floats " << floats;
      EXPECT_EQ(want.x, got.x) << "seed " << seed << " floats " << floats;
      EXPECT_EQ(want.y, got.y) << "seed " << seed << " floats " << floats;
    }
  }
}

TEST(RowKernel, CubeVectorLoaderEqualsThePortableLoaderUnderEveryPolicy) {
  std::array<StridedImage, shpack::kCubeFaceCount> faces[3];
  const std::uint32_t floats_per_layout[3] = {5, 3, 4};
  for (std::uint32_t f = 0; f < shpack::kCubeFaceCount; ++f) {
    const std::vector<float> rgb = unclean_rgb(kWidth, kWidth, 100 + f);
    for (int l = 0; l < 3; ++l) faces[l][f] = strided(rgb, kWidth, kWidth, floats_per_layout[l]);
  }
  for (Negative negative : {Negative::Keep, Negative::Clamp}) {
    shpack::ShL2 sh[3];
    shpack::ProjectStats stats[3];
    for (int l = 0; l < 3; ++l) {
      std::array<shpack::ImageView, shpack::kCubeFaceCount> views;
      for (std::uint32_t f = 0; f < shpack::kCubeFaceCount; ++f) views[f] = faces[l][f].view();
      ASSERT_TRUE(shpack::project_cube(views, policy(NonFinite::Zero, negative), sh[l], &stats[l]).ok());
    }
    for (int l = 1; l < 3; ++l) {
      EXPECT_EQ(sh[0], sh[l]) << "floats per texel " << floats_per_layout[l];
      expect_same_stats(stats[0], stats[l], l == 1 ? "RGB" : "RGBA");
    }
  }
}

}  // namespace
}  // namespace shpack_test
