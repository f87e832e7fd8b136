// streaming_test.cpp - the result is bit-identical for any thread count and any way of
// splitting the rows into add_rows calls (fixed tiles reduced in tile order, project.h),
// and the streaming API rejects calls out of sequence.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "shpack/project.h"
#include "support/rgb_image.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

using shpack::Errc;
using shpack::ShL2;

// 61 x 257: odd width (SIMD tail), 257 = 4 tiles of 64 + 1 row; values spanning 1e-3..1e4
// with some negatives, so rounding differences in any reordering would show.
RgbImage random_image(std::uint32_t w, std::uint32_t h, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> log_value(-3.0, 4.0), unit(0.0, 1.0);
  RgbImage img(w, h);
  for (float& v : img.rgb) v = static_cast<float>((unit(rng) < 0.05 ? -1.0 : 1.0) * std::pow(10.0, log_value(rng)));
  return img;
}

shpack::Status stream(const RgbImage& img, const shpack::ProjectOptions& opt,
                      const std::vector<std::uint32_t>& bands, ShL2& out, shpack::ProjectStats* stats) {
  shpack::EquirectProjector p;
  if (shpack::Status st = p.begin(img.width, img.height, opt); !st.ok()) return st;
  std::uint32_t row = 0;
  for (std::size_t k = 0; row < img.height; ++k) {
    const std::uint32_t n = std::min(bands[k % bands.size()], img.height - row);
    const shpack::ImageView band = shpack::make_view(img.rgb.data() + std::size_t{3} * img.width * row, img.width, n, 3);
    if (shpack::Status st = p.add_rows(band, row); !st.ok()) return st;
    row += n;
  }
  return p.finish(out, stats);
}

// The same plus pairs of rows mirrored about the equator (equal solid angles) holding
// opposite huge values: the partial sums reach ~1e20 while the result is O(1e4), a
// cancellation of ~1e16 that Neumaier's sum survives only up to its O(n u^2) sum|t| term -
// so any change in how rows are grouped (tiling that depended on threads or bands) changes
// the last bits, which bit-identity must not allow.
RgbImage cancelling_image(std::uint32_t w, std::uint32_t h, std::uint64_t seed) {
  RgbImage img = random_image(w, h, seed);
  std::mt19937_64 rng(seed + 1);
  std::uniform_real_distribution<double> u(1.0, 2.0);
  for (std::uint32_t j : {3u, 70u, 127u}) {
    for (std::uint32_t i = 0; i < w; ++i)
      for (int c = 0; c < 3; ++c) {
        const float big = static_cast<float>(1e20 * u(rng));
        img.at(i, j, c) = big;
        img.at(i, h - 1 - j, c) = -big;
      }
  }
  return img;
}

TEST(Streaming, ThreadsAndBandsGiveBitIdenticalResults) {
  const RgbImage images[2] = {random_image(61, 257, 0x5eed), cancelling_image(61, 257, 0x5eed)};
  for (int which = 0; which < 2; ++which) {
    const RgbImage& img = images[which];
    for (shpack::SamplingMethod m : {shpack::SamplingMethod::Exact, shpack::SamplingMethod::Center}) {
      shpack::ProjectOptions opt;
      opt.method = m;
      opt.threads = 1;
      ShL2 ref;
      shpack::ProjectStats ref_stats;
      const shpack::Status st = shpack::project_equirect(img.view(), opt, ref, &ref_stats);
      ASSERT_TRUE(st.ok()) << describe(st);
      for (unsigned threads : {1u, 2u, 3u, 0u}) {
        opt.threads = threads;
        const std::string ctx = "image=" + std::to_string(which) + " method=" + std::to_string(int(m)) +
                                " threads=" + std::to_string(threads);
        ShL2 one_shot;
        ASSERT_TRUE(shpack::project_equirect(img.view(), opt, one_shot).ok()) << ctx;
        EXPECT_EQ(ref, one_shot) << ctx;
        for (const std::vector<std::uint32_t>& bands :
             {std::vector<std::uint32_t>{1}, {7}, {64}, {100}, {1, 7, 64, 100}, {257}}) {
          ShL2 streamed;
          shpack::ProjectStats stats;
          const shpack::Status s2 = stream(img, opt, bands, streamed, &stats);
          ASSERT_TRUE(s2.ok()) << describe(s2) << " " << ctx << " first band=" << bands[0];
          EXPECT_EQ(ref, streamed) << ctx << " first band=" << bands[0] << " bands=" << bands.size();
          EXPECT_EQ(ref_stats.negative_texels, stats.negative_texels) << ctx;
          EXPECT_EQ(ref_stats.max_value, stats.max_value) << ctx;
        }
      }
    }
  }
}

TEST(Streaming, CallsOutOfSequenceAreRejected) {
  const RgbImage img = random_image(8, 10, 1);
  auto rows = [&](std::uint32_t first, std::uint32_t n) {
    return shpack::make_view(img.rgb.data() + std::size_t{3} * 8 * first, 8, n, 3);
  };
  ShL2 out;
  {
    shpack::EquirectProjector p;
    EXPECT_EQ(p.add_rows(rows(0, 2), 0).code, Errc::BadSequence) << "add_rows before begin";
    EXPECT_EQ(p.finish(out).code, Errc::BadSequence) << "finish before begin";
  }
  {
    shpack::EquirectProjector p;
    ASSERT_TRUE(p.begin(8, 10, {}).ok());
    EXPECT_EQ(p.add_rows(rows(2, 2), 2).code, Errc::BadSequence) << "skipping rows 0-1";
  }
  {
    shpack::EquirectProjector p;
    ASSERT_TRUE(p.begin(8, 10, {}).ok());
    ASSERT_TRUE(p.add_rows(rows(0, 4), 0).ok());
    EXPECT_EQ(p.add_rows(rows(0, 4), 0).code, Errc::BadSequence) << "repeating rows";
  }
  {
    shpack::EquirectProjector p;
    ASSERT_TRUE(p.begin(8, 9, {}).ok());
    EXPECT_EQ(p.add_rows(rows(0, 10), 0).code, Errc::BadSequence) << "more rows than the image";
  }
  {
    shpack::EquirectProjector p;
    ASSERT_TRUE(p.begin(8, 10, {}).ok());
    ASSERT_TRUE(p.add_rows(rows(0, 9), 0).ok());
    EXPECT_EQ(p.finish(out).code, Errc::BadSequence) << "finish with a row missing";
  }
  {
    shpack::EquirectProjector p;
    ASSERT_TRUE(p.begin(8, 10, {}).ok());
    ASSERT_TRUE(p.add_rows(rows(0, 10), 0).ok());
    ASSERT_TRUE(p.finish(out).ok());
    EXPECT_EQ(p.finish(out).code, Errc::BadSequence) << "finish twice";
    EXPECT_EQ(p.add_rows(rows(0, 1), 0).code, Errc::BadSequence) << "add_rows after finish";
  }
  {
    shpack::EquirectProjector p;
    ASSERT_TRUE(p.begin(9, 10, {}).ok());
    EXPECT_FALSE(p.add_rows(rows(0, 2), 0).ok()) << "band width 8 for an image of width 9";
  }
  {
    shpack::EquirectProjector p;
    EXPECT_FALSE(p.begin(0, 10, {}).ok()) << "zero width";
    EXPECT_FALSE(p.begin(8, 0, {}).ok()) << "zero height";
  }
}

TEST(Streaming, RestartAfterBeginStartsOver) {
  // begin() again discards what was added: the second projection equals a fresh one.
  const RgbImage a = random_image(16, 9, 2), b = random_image(16, 9, 3);
  ShL2 want, got;
  ASSERT_TRUE(shpack::project_equirect(b.view(), {}, want).ok());
  shpack::EquirectProjector p;
  ASSERT_TRUE(p.begin(16, 9, {}).ok());
  ASSERT_TRUE(p.add_rows(shpack::make_view(a.rgb.data(), 16, 4, 3), 0).ok());
  ASSERT_TRUE(p.begin(16, 9, {}).ok());
  ASSERT_TRUE(p.add_rows(b.view(), 0).ok());
  ASSERT_TRUE(p.finish(got).ok());
  EXPECT_EQ(want, got);
}

}  // namespace
}  // namespace shpack_test
