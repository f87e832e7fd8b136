// Reading environment maps (the map source, stage 1 of the pipeline, through convert_file):
// formats, pixel types, channels, colour encoding, layouts, NaN/Inf policy, errors, and that
// bands of scanlines give the one-shot projection exactly.
#include "shpack/io/map_source.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "io_test_files.h"
#include "shpack/convolution.h"
#include "shpack/io/convert.h"
#include "shpack/srgb.h"

namespace shpack::io {
namespace {

using shpack_io_test::hdri;
using shpack_io_test::ScratchDir;
using shpack_io_test::write_constant_image;
using shpack_io_test::write_image;

// L00 of a uniform environment of radiance v: v * k0 * 4 pi = v * 2 sqrt(pi).
constexpr double kUniformL00 = 2.0 / std::numbers::inv_sqrtpi;
// The exact projection of a uniform map sums per-texel integrals in double: a few ulps of
// the largest coefficient, with room for 32 texels of rounding.
constexpr double kUniformTol = 1e-13;
// An sRGB integer texel arrives as the float nearest k/max (relative error 2^-24), the
// EOTF's 2.4 power multiplies that by up to 2.4, and the linear value is rounded to float
// once more: 3.4 * 2^-24, rounded up to 4 * 2^-24.
constexpr double kDecodedTol = 4.0 * 0x1p-24;

// What the source held and the radiance projected from it. With the default settings the
// finish stage applies intensity 1, no rotation and no window: the projector's radiance up to
// exact operations.
struct Projection {
  SourceInfo info;
  ShL2 radiance;
  ProjectStats stats;
};

Projection project(const std::filesystem::path& path, const ConvertSettings& settings = {}) {
  Projection out;
  Conversion conversion;
  const IoStatus st = convert_file(path, settings, conversion, &out.info);
  EXPECT_TRUE(st.ok()) << st.message;
  out.radiance = conversion.sh.radiance;
  out.stats = conversion.stats;
  return out;
}

// The per-channel mean radiance of a projection: the Unity-form constant term, which
// for a uniform environment is the radiance itself (Unity's AddAmbientLight).
std::array<double, 3> mean_radiance(const Projection& p) {
  const ShL2 unity = radiance_to_unity_form(p.radiance);
  return {unity.c[0][0], unity.c[1][0], unity.c[2][0]};
}

void expect_uniform(const Projection& p, const std::array<double, 3>& value, double rel_tol) {
  for (int c = 0; c < kChannelCount; ++c) {
    EXPECT_NEAR(p.radiance.c[c][0], value[c] * kUniformL00, rel_tol * value[c] * kUniformL00)
        << "channel " << c;
    for (int i = 1; i < kShCount; ++i)
      EXPECT_NEAR(p.radiance.c[c][i], 0.0, kUniformTol * kUniformL00) << "channel " << c << " i=" << i;
  }
}

TEST(MapSource, FloatExrIsReadAsIs) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "sky.exr", 8, 4, {0.5f, 0.25f, 2.0f}));
  const Projection p = project(dir / "sky.exr");
  expect_uniform(p, {0.5, 0.25, 2.0}, kUniformTol);
  EXPECT_EQ(p.info.width, 8u);
  EXPECT_EQ(p.info.height, 4u);
  EXPECT_EQ(p.info.channels, 3u);
  EXPECT_EQ(p.info.ignored_channels, 0u);
  EXPECT_EQ(p.info.layout, Layout::Equirect);
  EXPECT_EQ(p.info.format, "openexr");
  EXPECT_FALSE(p.info.srgb_decoded);
}

TEST(MapSource, HalfExrAndRadianceHdrAreLinear) {
  // Powers of two are exact in half and in RGBE, so the values must come back exactly.
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "half.exr", 8, 4, {0.5f, 0.25f, 4.0f}, OIIO::TypeDesc::HALF));
  ASSERT_TRUE(write_constant_image(dir / "sky.hdr", 8, 4, {0.5f, 0.25f, 4.0f}));
  for (const char* name : {"half.exr", "sky.hdr"}) {
    SCOPED_TRACE(name);
    const Projection p = project(dir / name);
    expect_uniform(p, {0.5, 0.25, 4.0}, kUniformTol);
    EXPECT_FALSE(p.info.srgb_decoded);
  }
}

TEST(MapSource, PfmIsReadTopRowFirst) {
  // PFM stores rows bottom to top (and OpenImageIO cannot write it): write one by hand
  // whose last file row, the image's top row (+Y in Unity's frame), is the bright one.
  const ScratchDir dir;
  const int width = 4, height = 2;
  std::string bytes = "PF\n4 2\n-1.0\n";  // negative scale: little-endian floats
  for (int file_row = 0; file_row < height; ++file_row) {
    for (int x = 0; x < width * 3; ++x) {
      const float v = file_row == height - 1 ? 3.0f : 1.0f;
      char raw[4];
      std::memcpy(raw, &v, 4);
      bytes.append(raw, 4);
    }
  }
  shpack_io_test::write_bytes(dir / "sky.pfm", {bytes.begin(), bytes.end()});
  const Projection p = project(dir / "sky.pfm");
  EXPECT_EQ(p.info.format, "pnm");
  EXPECT_FALSE(p.info.srgb_decoded);  // OpenImageIO calls PFM "Rec709": float is never decoded
  // Upper hemisphere 3, lower 1: L00 = 2 * 2 sqrt(pi), and L1 along +Y = (3 - 1) k1 pi > 0.
  for (int c = 0; c < kChannelCount; ++c) {
    EXPECT_NEAR(p.radiance.c[c][0], 2.0 * kUniformL00, kUniformTol * 2.0 * kUniformL00);
    EXPECT_NEAR(p.radiance.c[c][1], 2.0 * kY1 * std::numbers::pi, kUniformTol * 2.0 * kUniformL00);
  }
}

TEST(MapSource, EightBitPngIsDecodedFromSrgb) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "sky.png", 8, 4, {128 / 255.0f, 64 / 255.0f, 10 / 255.0f},
                                   OIIO::TypeDesc::UINT8));
  const Projection p = project(dir / "sky.png");
  EXPECT_TRUE(p.info.srgb_decoded);
  expect_uniform(p, {srgb_to_linear(128 / 255.0), srgb_to_linear(64 / 255.0), srgb_to_linear(10 / 255.0)},
                 kDecodedTol);
}

TEST(MapSource, SixteenBitPngIsDecodedFromSrgb) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "sky.png", 8, 4, {32768 / 65535.0f, 0.0f, 1.0f},
                                   OIIO::TypeDesc::UINT16));
  const Projection p = project(dir / "sky.png");
  EXPECT_TRUE(p.info.srgb_decoded);
  const std::array<double, 3> mean = mean_radiance(p);
  EXPECT_NEAR(mean[0], srgb_to_linear(32768 / 65535.0), kDecodedTol * mean[0]);
  EXPECT_EQ(mean[1], 0.0);
  EXPECT_NEAR(mean[2], 1.0, kDecodedTol);
}

TEST(MapSource, UntaggedEightBitTiffIsLinear) {
  // Only PNG and JPEG are sRGB when they say nothing; a TIFF without a colour space is not.
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "sky.tif", 8, 4, {128 / 255.0f, 128 / 255.0f, 128 / 255.0f},
                                   OIIO::TypeDesc::UINT8));
  const Projection p = project(dir / "sky.tif");
  EXPECT_FALSE(p.info.srgb_decoded);
  EXPECT_NEAR(mean_radiance(p)[0], 128 / 255.0, 0x1p-24);  // the float nearest 128/255
}

TEST(MapSource, GreyIsReplicatedToRgb) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "grey.exr", 8, 4, {0.75f}));
  const Projection p = project(dir / "grey.exr");
  expect_uniform(p, {0.75, 0.75, 0.75}, kUniformTol);
  EXPECT_EQ(p.info.ignored_channels, 0u);
}

TEST(MapSource, GreyAlphaIgnoresAlpha) {
  const ScratchDir dir;
  ASSERT_TRUE(shpack_io_test::write_named_constant_image(dir / "grey_alpha.exr", 8, 4, {"Y", "A"}, {0.75f, 0.25f}));
  const Projection p = project(dir / "grey_alpha.exr");
  expect_uniform(p, {0.75, 0.75, 0.75}, kUniformTol);
  EXPECT_EQ(p.info.ignored_channels, 1u);
}

TEST(MapSource, ChannelsAfterRgbAreIgnoredAndCounted) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "five.exr", 8, 4, {1.0f, 2.0f, 3.0f, 4.0f, 5.0f}));
  const Projection p = project(dir / "five.exr");
  expect_uniform(p, {1.0, 2.0, 3.0}, kUniformTol);
  EXPECT_EQ(p.info.ignored_channels, 2u);
}

TEST(MapSource, PngAlphaIsNotMultipliedIntoColour) {
  // The file stores unassociated colour (255, 128, 51) with alpha 128. A reader that
  // premultiplies would halve the colour; the environment's colour is what is stored.
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "rgba.png", 8, 4, {1.0f, 128 / 255.0f, 51 / 255.0f, 128 / 255.0f},
                                   OIIO::TypeDesc::UINT8, {OIIO::ParamValue("oiio:UnassociatedAlpha", 1)}));
  const Projection p = project(dir / "rgba.png");
  EXPECT_EQ(p.info.ignored_channels, 1u);
  expect_uniform(p, {1.0, srgb_to_linear(128 / 255.0), srgb_to_linear(51 / 255.0)}, kDecodedTol);
}

TEST(MapSource, OneTexelIsAUniformEnvironment) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "one.exr", 1, 1, {2.0f, 3.0f, 4.0f}));
  const Projection p = project(dir / "one.exr");
  EXPECT_EQ(p.info.layout, Layout::Equirect);
  expect_uniform(p, {2.0, 3.0, 4.0}, kUniformTol);
}

TEST(MapSource, OtherShapesNeedAnExplicitLayout) {
  const ScratchDir dir;
  ASSERT_TRUE(write_constant_image(dir / "odd.exr", 6, 4, {1.0f, 1.0f, 1.0f}));
  Conversion p;
  const IoStatus st = convert_file(dir / "odd.exr", {}, p);
  EXPECT_EQ(st.code, IoErrc::UnknownLayout);
  EXPECT_EQ(st.message, (dir / "odd.exr").string() +
                            ": the layout of a 6x4 image cannot be detected: it fits no layout (2:1 equirect, 4:3 hcross, "
                            "3:4 vcross, 6:1 hstrip, 1:6 vstrip, square octahedral, angular or mirrorball)");
  ConvertSettings equirect;
  equirect.source.layout = Layout::Equirect;
  expect_uniform(project(dir / "odd.exr", equirect), {1.0, 1.0, 1.0}, kUniformTol);
}

std::vector<float> image_with_nonfinite_texels() {
  std::vector<float> pixels(8 * 4 * 3, 1.0f);
  auto texel = [&](int x, int y) { return pixels.begin() + (y * 8 + x) * 3; };
  texel(3, 1)[0] = std::numeric_limits<float>::quiet_NaN();
  texel(5, 2)[1] = std::numeric_limits<float>::infinity();
  texel(6, 2)[2] = -std::numeric_limits<float>::infinity();
  return pixels;
}

TEST(MapSource, NonFiniteTexelsAreCountedAndLocated) {
  const ScratchDir dir;
  ASSERT_TRUE(write_image(dir / "nan.exr", 8, 4, 3, image_with_nonfinite_texels()));
  Conversion p;
  const IoStatus st = convert_file(dir / "nan.exr", {}, p);
  EXPECT_EQ(st.code, IoErrc::NonFiniteTexel);
  EXPECT_EQ(st.message, (dir / "nan.exr").string() + ": 3 NaN/Inf texels (first at x=3, y=1)");
}

TEST(MapSource, NonFiniteTexelsCountAsZeroWhenAsked) {
  const ScratchDir dir;
  std::vector<float> pixels = image_with_nonfinite_texels();
  ASSERT_TRUE(write_image(dir / "nan.exr", 8, 4, 3, pixels));
  for (float& v : pixels)
    if (!std::isfinite(v)) v = 0.0f;
  ASSERT_TRUE(write_image(dir / "zero.exr", 8, 4, 3, pixels));

  ConvertSettings zero;
  zero.convert.nonfinite = NonFinite::Zero;
  const Projection with_nan = project(dir / "nan.exr", zero);
  EXPECT_EQ(with_nan.stats.nonfinite_texels, 3u);
  EXPECT_EQ(with_nan.radiance, project(dir / "zero.exr").radiance);
}

// Errors: each is one line that starts with the file's name.
void expect_error(const std::filesystem::path& path, IoErrc code, const std::string& problem) {
  Conversion p;
  const IoStatus st = convert_file(path, {}, p);
  EXPECT_EQ(st.code, code) << st.message;
  EXPECT_EQ(st.message.rfind(path.string() + ": " + problem, 0), 0u) << st.message;
  EXPECT_EQ(st.message.find('\n'), std::string::npos) << st.message;
}

TEST(MapSource, ErrorsNameTheFileAndTheProblem) {
  const ScratchDir dir;
  expect_error(dir / "missing.exr", IoErrc::NotFound, "no such file");
  expect_error(dir.path(), IoErrc::NotAFile, "is a directory");
  shpack_io_test::write_bytes(dir / "notes.txt", {'h', 'i', '\n'});
  expect_error(dir / "notes.txt", IoErrc::Unreadable, "not an image that can be read");
  shpack_io_test::write_bytes(dir / "notes.exr", {'h', 'i', '\n'});
  expect_error(dir / "notes.exr", IoErrc::Unreadable, "not an image that can be read");
  shpack_io_test::write_bytes(dir / "empty.exr", {});
  expect_error(dir / "empty.exr", IoErrc::Unreadable, "not an image that can be read");
}

TEST(MapSource, TruncatedFileIsAReadError) {
  const ScratchDir dir;
  std::vector<char> bytes = shpack_io_test::read_bytes(hdri("courtyard.exr"));
  ASSERT_GT(bytes.size(), 100000u);
  bytes.resize(bytes.size() / 2);  // the header survives, half of the pixel blocks do not
  shpack_io_test::write_bytes(dir / "half.exr", bytes);
  expect_error(dir / "half.exr", IoErrc::Unreadable, "cannot read rows");
}

TEST(MapSource, BandsGiveTheOneShotProjectionExactly) {
  // courtyard.exr read in bands of 64, 128 and 192 rows (1, 2, 3 threads) and in one piece
  // must project to the same bits: the core's tiles do not depend on how rows arrive.
  const std::filesystem::path path = hdri("courtyard.exr");
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec spec = in->spec();
  std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, pixels.data())) << in->geterror();
  ShL2 one_shot;
  ASSERT_TRUE(project_equirect(make_view(pixels.data(), static_cast<std::uint32_t>(spec.width),
                                         static_cast<std::uint32_t>(spec.height), 3),
                               {}, one_shot)
                  .ok());
  for (unsigned threads : {1u, 2u, 3u}) {
    ConvertSettings options;
    options.convert.threads = threads;
    EXPECT_EQ(project(path, options).radiance, one_shot) << "threads=" << threads;
  }
}

}  // namespace
}  // namespace shpack::io
