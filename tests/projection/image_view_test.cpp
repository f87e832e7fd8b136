// image_view_test.cpp - ImageView: defaults and validation in resolve_view, and that every
// legal layout of the same texel values projects to the bit-identical result: negative
// strides (bottom-up, mirrored), padded pixels and rows, RGBA with the alpha ignored,
// half floats, grey. Reads stay inside the view (guard pages).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "shpack/image_view.h"
#include "shpack/project.h"
#include "support/guarded_buffer.h"
#include "support/half_oracle.h"
#include "support/rgb_image.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

using shpack::Errc;
using shpack::ImageView;
using shpack::PixelType;
using shpack::ShL2;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

RgbImage random_image(std::uint32_t w, std::uint32_t h, std::uint64_t seed) {
  return shpack_test::uniform_random_image(w, h, seed, 0.0f, 100.0f);
}

ShL2 project_ok(const ImageView& v, const std::string& what) {
  ShL2 sh;
  const shpack::Status st = shpack::project_equirect(v, {}, sh);
  EXPECT_TRUE(st.ok()) << what << ": " << describe(st);
  return sh;
}

const std::byte* bytes(const float* p) { return reinterpret_cast<const std::byte*>(p); }

TEST(ImageView, ResolveFillsDefaultStrides) {
  float px[12] = {};
  ImageView v = shpack::make_view(px, 2, 2, 3);
  ASSERT_TRUE(shpack::resolve_view(v).ok());
  EXPECT_EQ(v.pixel_stride, 12);
  EXPECT_EQ(v.row_stride, 24);
  ImageView h{bytes(px), PixelType::F16, 3, 2, 4};
  ASSERT_TRUE(shpack::resolve_view(h).ok());
  EXPECT_EQ(h.pixel_stride, 8);
  EXPECT_EQ(h.row_stride, 24);
  EXPECT_EQ(shpack::pixel_type_size(PixelType::F32), 4);
  EXPECT_EQ(shpack::pixel_type_size(PixelType::F16), 2);
}

TEST(ImageView, ResolveRejectsMalformedViews) {
  float px[64] = {};
  struct Case {
    const char* what;
    ImageView view;
  };
  const Case cases[] = {
      {"null data", {nullptr, PixelType::F32, 2, 2, 3}},
      {"zero width", {bytes(px), PixelType::F32, 0, 2, 3}},
      {"zero height", {bytes(px), PixelType::F32, 2, 0, 3}},
      {"zero channels", {bytes(px), PixelType::F32, 2, 2, 0}},
      {"pixel stride below the pixel size", {bytes(px), PixelType::F32, 4, 2, 3, 8}},
      {"zero pixel stride", {bytes(px), PixelType::F32, 4, 2, 3, 0}},
      {"rows overlap", {bytes(px), PixelType::F32, 4, 2, 3, 12, 44}},
      {"zero row stride", {bytes(px), PixelType::F32, 4, 2, 3, 12, 0}},
      {"negative rows overlap", {bytes(px + 48), PixelType::F32, 4, 2, 3, 12, -40}},
      {"negative pixels overlap", {bytes(px + 9), PixelType::F32, 4, 2, 3, -8}},
  };
  for (const Case& c : cases) {
    ImageView v = c.view;
    EXPECT_EQ(shpack::resolve_view(v).code, Errc::BadView) << c.what;
    ShL2 sh;
    EXPECT_EQ(shpack::project_equirect(c.view, {}, sh).code, Errc::BadView) << c.what;
  }
}

TEST(ImageView, BottomUpImageEqualsFlippedCopy) {
  const RgbImage img = random_image(37, 19, 1);
  RgbImage flipped(37, 19);  // rows stored bottom-up
  for (std::uint32_t j = 0; j < 19; ++j)
    for (std::uint32_t i = 0; i < 37; ++i)
      for (int c = 0; c < 3; ++c) flipped.at(i, 18 - j, c) = img.at(i, j, c);
  ImageView v = shpack::make_view(flipped.rgb.data() + 3 * 37 * 18, 37, 19, 3);
  v.row_stride = -3 * 4 * 37;
  EXPECT_EQ(project_ok(img.view(), "top-down"), project_ok(v, "bottom-up view"));
}

TEST(ImageView, MirroredImageWithNegativePixelStrideEqualsOriginal) {
  const RgbImage img = random_image(36, 10, 2);
  RgbImage mirrored(36, 10);
  for (std::uint32_t j = 0; j < 10; ++j)
    for (std::uint32_t i = 0; i < 36; ++i)
      for (int c = 0; c < 3; ++c) mirrored.at(35 - i, j, c) = img.at(i, j, c);
  ImageView v = shpack::make_view(mirrored.rgb.data() + 3 * 35, 36, 10, 3);
  v.pixel_stride = -12;
  v.row_stride = 3 * 4 * 36;
  EXPECT_EQ(project_ok(img.view(), "original"), project_ok(v, "mirrored view"));
}

TEST(ImageView, RgbaAndPaddedLayoutsIgnoreExtraBytes) {
  for (std::uint32_t w : {36u, 37u}) {  // a multiple of 4 and not (vector loops and tails)
    const RgbImage img = random_image(w, 11, 3);
    const ShL2 want = project_ok(img.view(), "rgb");
    // RGBA with NaN alpha: as 4 channels, and as 3 channels with a 16-byte pixel stride.
    std::vector<float> rgba(std::size_t{4} * w * 11);
    for (std::size_t k = 0; k < std::size_t{w} * 11; ++k) {
      for (int c = 0; c < 3; ++c) rgba[4 * k + c] = img.rgb[3 * k + c];
      rgba[4 * k + 3] = kNaN;
    }
    EXPECT_EQ(want, project_ok(shpack::make_view(rgba.data(), w, 11, 4), "rgba")) << "W=" << w;
    ImageView strided = shpack::make_view(rgba.data(), w, 11, 3);
    strided.pixel_stride = 16;
    EXPECT_EQ(want, project_ok(strided, "rgb stride 16")) << "W=" << w;
    // Five channels (RGB + two ignored), and rows padded by 5 floats of NaN.
    std::vector<float> five(std::size_t{5} * w * 11, kNaN);
    for (std::size_t k = 0; k < std::size_t{w} * 11; ++k)
      for (int c = 0; c < 3; ++c) five[5 * k + c] = img.rgb[3 * k + c];
    EXPECT_EQ(want, project_ok(shpack::make_view(five.data(), w, 11, 5), "5 channels")) << "W=" << w;
    const std::size_t row_floats = 3 * w + 5;
    std::vector<float> padded(row_floats * 11, kNaN);
    for (std::uint32_t j = 0; j < 11; ++j)
      std::memcpy(&padded[row_floats * j], &img.rgb[std::size_t{3} * w * j], sizeof(float) * 3 * w);
    ImageView pv = shpack::make_view(padded.data(), w, 11, 3);
    pv.row_stride = static_cast<std::int64_t>(row_floats * 4);
    EXPECT_EQ(want, project_ok(pv, "padded rows")) << "W=" << w;
  }
}

TEST(ImageView, GreyEqualsRgbWithEqualChannels) {
  const std::uint32_t w = 29, h = 13;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<float> u(0.0f, 10.0f);
  std::vector<float> grey(std::size_t{w} * h), grey_alpha(std::size_t{2} * w * h);
  RgbImage rgb(w, h);
  for (std::size_t k = 0; k < grey.size(); ++k) {
    grey[k] = u(rng);
    grey_alpha[2 * k] = grey[k];
    grey_alpha[2 * k + 1] = kNaN;  // alpha is never read
    for (int c = 0; c < 3; ++c) rgb.rgb[3 * k + c] = grey[k];
  }
  const ShL2 want = project_ok(rgb.view(), "rgb");
  EXPECT_EQ(want, project_ok(shpack::make_view(grey.data(), w, h, 1), "grey"));
  EXPECT_EQ(want, project_ok(shpack::make_view(grey_alpha.data(), w, h, 2), "grey + alpha"));
}

TEST(ImageView, HalfToFloatMatchesOracleForAllValues) {
  for (std::uint32_t bits = 0; bits <= 0xffff; ++bits) {
    const auto h = static_cast<std::uint16_t>(bits);
    const float want = half_bits_to_float(h), got = shpack::half_to_float(h);
    if (std::isnan(want)) {
      EXPECT_TRUE(std::isnan(got)) << "bits=0x" << std::hex << bits;
    } else {
      EXPECT_EQ(want, got) << "bits=0x" << std::hex << bits;
      EXPECT_EQ(std::signbit(want), std::signbit(got)) << "bits=0x" << std::hex << bits;
    }
  }
}

TEST(ImageView, HalfInputEqualsFloatInputOfTheSameValues) {
  // Random finite halves (all exponents incl. subnormals and both signs), and the floats of
  // the same values: every half is exactly a float, so the projections are bit-identical.
  for (std::uint32_t channels : {3u, 4u}) {
    const std::uint32_t w = 33, h = 70;  // two tiles, odd width
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int> bits(0, 0xffff);
    std::vector<std::uint16_t> half(std::size_t{channels} * w * h);
    RgbImage f(w, h);
    for (std::size_t k = 0; k < std::size_t{w} * h; ++k)
      for (std::uint32_t c = 0; c < channels; ++c) {
        std::uint16_t b;
        do b = static_cast<std::uint16_t>(bits(rng));
        while (((b >> 10) & 0x1f) == 0x1f);  // finite only
        half[channels * k + c] = b;
        if (c < 3) f.rgb[3 * k + c] = half_bits_to_float(b);
      }
    const ImageView hv{reinterpret_cast<const std::byte*>(half.data()), PixelType::F16, w, h, channels};
    shpack::ProjectStats hs, fs;
    ShL2 from_half, from_float;
    ASSERT_TRUE(shpack::project_equirect(hv, {}, from_half, &hs).ok());
    ASSERT_TRUE(shpack::project_equirect(f.view(), {}, from_float, &fs).ok());
    EXPECT_EQ(from_float, from_half) << "channels=" << channels;
    EXPECT_EQ(fs.negative_texels, hs.negative_texels) << "channels=" << channels;
    EXPECT_EQ(fs.max_value, hs.max_value) << "channels=" << channels;
  }
}

// A view whose last byte is the last byte before an inaccessible page (or whose first byte
// follows one): any read outside the described pixels crashes this test.
TEST(ImageView, ReadsStayInsideTheView) {
  const std::uint32_t w = 16, h = 5;  // width a multiple of 4: vector loops reach the last pixel
  const RgbImage img = random_image(w, h, 6);
  const ShL2 want = project_ok(img.view(), "reference");
  struct Layout {
    const char* what;
    std::int64_t pixel_stride;  // bytes
    std::uint32_t channels;
  };
  for (const Layout& l : {Layout{"rgb packed", 12, 3}, Layout{"rgb in 16-byte pixels", 16, 3},
                          Layout{"rgba", 16, 4}, Layout{"rgb in 20-byte pixels", 20, 3}}) {
    // Exactly (w*h - 1) strides plus the last pixel's own channels.
    const std::size_t size = static_cast<std::size_t>(l.pixel_stride) * (w * h - 1) + 4 * l.channels;
    for (auto guard : {GuardedBuffer::Guard::After, GuardedBuffer::Guard::Before}) {
      GuardedBuffer buf(size, guard);
      ASSERT_TRUE(buf.ok());
      std::memset(buf.data(), 0xff, size);  // NaN in every padding byte
      for (std::size_t k = 0; k < std::size_t{w} * h; ++k)
        std::memcpy(buf.data() + k * l.pixel_stride, &img.rgb[3 * k], 12);
      const ImageView v{buf.data(), PixelType::F32, w, h, l.channels, l.pixel_stride,
                        l.pixel_stride * w};
      ShL2 got;
      const shpack::Status st = shpack::project_equirect(v, {}, got);
      ASSERT_TRUE(st.ok()) << l.what << ": " << describe(st);
      EXPECT_EQ(want, got) << l.what;
    }
  }
  // Bottom-up: the view starts at the last row of the buffer and walks back to its start,
  // which follows a guard page.
  GuardedBuffer buf(img.rgb.size() * 4, GuardedBuffer::Guard::Before);
  ASSERT_TRUE(buf.ok());
  for (std::uint32_t j = 0; j < h; ++j)
    std::memcpy(buf.data() + std::size_t{12} * w * (h - 1 - j), &img.rgb[std::size_t{3} * w * j], 12 * w);
  const ImageView v{buf.data() + std::size_t{12} * w * (h - 1), PixelType::F32, w, h, 3, 12,
                    -static_cast<std::int64_t>(12 * w)};
  EXPECT_EQ(want, project_ok(v, "bottom-up guarded"));
}

}  // namespace
}  // namespace shpack_test
