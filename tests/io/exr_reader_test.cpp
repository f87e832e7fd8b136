// lib/io reads OpenEXR with OpenEXR itself (exr_decoder.h); OpenImageIO read it before, and
// the pixels must not have changed. Each test reads a file both ways, read_image_file and
// OpenImageIO's read_image (both decode through OpenEXR, half to float is exact, so the
// tolerance is zero: the floats are compared bit for bit), over the bundled maps and over
// every compression OpenEXR has, scanline and tiled, half, float and uint, with alpha and
// extra channels, multi-part files and a data window inside the display window.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "io_test_files.h"
#include "shpack/io/image_file.h"

namespace {

namespace fs = std::filesystem;
using shpack::io::ImageFile;
using shpack::io::IoStatus;
using shpack_io_test::ScratchDir;

// The display window of subimage `subimage` of `path` as OpenImageIO reads it: channels
// R, G, B (by name, after `prefix`), black outside the data window.
std::vector<float> oiio_rgb(const fs::path& path, int subimage = 0, const std::string& prefix = "") {
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  const OIIO::ImageSpec spec = in->spec(subimage);
  std::vector<float> data(std::size_t(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(in->read_image(subimage, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data())) << in->geterror();
  std::vector<int> index;
  for (const char* c : {"R", "G", "B"}) index.push_back(spec.channelindex(prefix + c));
  EXPECT_TRUE(std::all_of(index.begin(), index.end(), [](int i) { return i >= 0; }));
  std::vector<float> rgb(std::size_t(spec.full_width) * spec.full_height * 3, 0.0f);
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x) {
      const int dx = spec.x + x - spec.full_x, dy = spec.y + y - spec.full_y;
      if (dx < 0 || dy < 0 || dx >= spec.full_width || dy >= spec.full_height) continue;
      for (int k = 0; k < 3; ++k)
        rgb[(std::size_t(dy) * spec.full_width + dx) * 3 + k] =
            data[(std::size_t(y) * spec.width + x) * spec.nchannels + index[k]];
    }
  return rgb;
}

// read_image_file's pixels equal OpenImageIO's, bit for bit.
void expect_same_pixels(const fs::path& path, const std::vector<float>& want, const std::string& layer = "") {
  ImageFile image;
  const IoStatus st = shpack::io::read_image_file(path, layer, image);
  ASSERT_TRUE(st.ok()) << st.message;
  ASSERT_EQ(image.channels, 3u) << path;
  ASSERT_EQ(image.pixels.size(), want.size()) << path;
  EXPECT_EQ(image.format, "openexr");
  for (std::size_t i = 0; i < want.size(); ++i) {
    if (std::memcmp(&image.pixels[i], &want[i], sizeof(float)) != 0) {
      ADD_FAILURE() << path << ": value " << i << " is " << image.pixels[i] << ", OpenImageIO read " << want[i];
      return;
    }
  }
}

// A w x h image of `channels` channels: radiance over five decades, some negative, some zero.
std::vector<float> test_pixels(int w, int h, int channels) {
  std::mt19937_64 rng(0x5eed);
  std::normal_distribution<float> log_radiance(0.0f, 3.0f);
  std::vector<float> pixels(std::size_t(w) * h * channels);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = std::exp(log_radiance(rng)) * (i % 17 == 0 ? -1.0f : 1.0f);
  pixels[1] = 0.0f;
  return pixels;
}

// Writes `pixels` to an EXR through OpenImageIO with `spec`'s layout and `compression`.
void write_exr(const fs::path& path, OIIO::ImageSpec spec, const std::string& compression,
               const std::vector<float>& pixels) {
  spec.attribute("compression", compression);
  const std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close()) << out->geterror();
}

TEST(ExrReader, BundledMapsAreReadAsOpenImageIOReadThem) {
  int maps = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(shpack_io_test::hdri(""))) {
    if (e.path().extension() != ".exr") continue;
    expect_same_pixels(e.path(), oiio_rgb(e.path()));
    ++maps;
  }
  EXPECT_GT(maps, 0);
}

TEST(ExrReader, EveryCompressionScanlineAndTiledHalfAndFloat) {
  const ScratchDir dir;
  // Odd sizes, so that the last chunk and the last tiles are partial.
  const int w = 45, h = 37;
  const std::vector<float> pixels = test_pixels(w, h, 5);
  for (const char* compression : {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"}) {
    for (const OIIO::TypeDesc type : {OIIO::TypeDesc::HALF, OIIO::TypeDesc::FLOAT}) {
      for (const bool tiled : {false, true}) {
        OIIO::ImageSpec spec(w, h, 5, type);
        spec.channelnames = {"R", "G", "B", "A", "Z"};
        if (tiled) spec.tile_width = spec.tile_height = 16;
        const fs::path path = dir / (std::string(compression) + (type == OIIO::TypeDesc::HALF ? "_half" : "_float") +
                                     (tiled ? "_tiled" : "") + ".exr");
        write_exr(path, spec, compression, pixels);
        expect_same_pixels(path, oiio_rgb(path));
      }
    }
  }
}

TEST(ExrReader, UintChannelsAreScaledAsOpenImageIOScaledThem) {
  const ScratchDir dir;
  const int w = 9, h = 5;
  std::vector<float> pixels(std::size_t(w) * h * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<float>(i) / static_cast<float>(pixels.size());
  pixels[0] = 1.0f;  // 2^32 - 1
  write_exr(dir / "uint.exr", OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT), "zip", pixels);
  expect_same_pixels(dir / "uint.exr", oiio_rgb(dir / "uint.exr"));
}

TEST(ExrReader, ADataWindowInsideTheDisplayWindowIsBlackOutside) {
  const ScratchDir dir;
  for (const bool tiled : {false, true}) {
    OIIO::ImageSpec spec(13, 6, 3, OIIO::TypeDesc::HALF);
    spec.x = 5;
    spec.y = 3;
    spec.full_x = spec.full_y = 0;
    spec.full_width = 24;
    spec.full_height = 12;
    if (tiled) spec.tile_width = spec.tile_height = 8;
    const fs::path path = dir / (tiled ? "window_tiled.exr" : "window.exr");
    write_exr(path, spec, "piz", test_pixels(13, 6, 3));
    expect_same_pixels(path, oiio_rgb(path));
  }
}

TEST(ExrReader, PartsAndLayersOfAMultiPartFile) {
  const ScratchDir dir;
  const int w = 20, h = 10;
  OIIO::ImageSpec beauty(w, h, 3, OIIO::TypeDesc::HALF), sky(w, h, 6, OIIO::TypeDesc::FLOAT);
  beauty.attribute("oiio:subimagename", "beauty");
  beauty.attribute("compression", "dwab");
  sky.attribute("oiio:subimagename", "sky");
  sky.channelnames = {"diffuse.B", "diffuse.G", "diffuse.R", "specular.B", "specular.G", "specular.R"};
  sky.attribute("compression", "zip");
  const std::vector<float> a = test_pixels(w, h, 3), b = test_pixels(w, h, 6);
  const fs::path path = dir / "parts.exr";
  {
    const OIIO::ImageSpec specs[] = {beauty, sky};
    const std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path.string(), 2, specs)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, a.data())) << out->geterror();
    ASSERT_TRUE(out->open(path.string(), sky, OIIO::ImageOutput::AppendSubimage)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, b.data())) << out->geterror();
    ASSERT_TRUE(out->close());
  }
  expect_same_pixels(path, oiio_rgb(path, 0));
  expect_same_pixels(path, oiio_rgb(path, 0), "beauty");
  expect_same_pixels(path, oiio_rgb(path, 1, "specular."), "specular");
  expect_same_pixels(path, oiio_rgb(path, 1, "diffuse."), "diffuse");
}

TEST(ExrReader, ChromaticitiesAreTheFiles) {
  const ScratchDir dir;
  OIIO::ImageSpec spec(4, 2, 3, OIIO::TypeDesc::HALF);
  const float p3[8] = {0.68f, 0.32f, 0.265f, 0.69f, 0.15f, 0.06f, 0.3127f, 0.329f};
  spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), p3);
  write_exr(dir / "p3.exr", spec, "zip", test_pixels(4, 2, 3));
  ImageFile image;
  ASSERT_TRUE(shpack::io::read_image_file(dir / "p3.exr", image).ok());
  ASSERT_TRUE(image.chromaticities.has_value());
  for (int k = 0; k < 8; ++k) EXPECT_EQ((*image.chromaticities)[k], static_cast<double>(p3[k])) << k;  // float to double is exact
}

}  // namespace
