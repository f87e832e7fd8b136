// convert_pixels (convert_pixels.h): pixels in memory give the document their file gives,
// through the same stages; errors name the pixels as a file's name the file.
#include "shpack/io/convert_pixels.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "io_test_files.h"
#include "shpack/io/error_remedy.h"
#include "shpack/io/json_writer.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;
using shpack_io_test::ScratchDir;

// Varied texels in [-0.125, 2), a few negative, so every coefficient and policy counts.
std::vector<float> texels(int w, int h, int channels, unsigned seed = 0x5eed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> value(-0.125f, 2.0f);
  std::vector<float> pixels(static_cast<std::size_t>(w) * h * channels);
  for (float& v : pixels) v = value(rng);
  return pixels;
}

// The JSON of a document whose source names no file, as convert_pixels' does.
std::string json_without_files(ShDocument doc) {
  doc.source.files.clear();
  doc.source.sha256.clear();
  return to_json(doc);
}

std::string file_json(const fs::path& path, const ConvertSettings& settings) {
  ShDocument doc;
  const IoStatus st = convert_env_map(path, settings, doc);
  EXPECT_TRUE(st.ok()) << st.message;
  return json_without_files(doc);
}

std::string pixels_json(const ImageView& view, const ConvertSettings& settings) {
  ShDocument doc;
  const IoStatus st = convert_pixels(view, "pixels", settings, doc);
  EXPECT_TRUE(st.ok()) << st.message;
  EXPECT_TRUE(doc.source.files.empty());
  EXPECT_TRUE(doc.source.sha256.empty());
  return to_json(doc);
}

TEST(ConvertPixels, TheDocumentOfTheFileOfTheSameTexels) {
  const ScratchDir dir;
  const int w = 32, h = 16;
  const std::vector<float> pixels = texels(w, h, 3);
  ASSERT_TRUE(shpack_io_test::write_image(dir / "map.exr", w, h, 3, pixels));
  const ImageView view = make_view(pixels.data(), w, h, 3);
  std::vector<ConvertSettings> cases(6);
  cases[1].convert.finish.intensity = 2.5;
  cases[1].convert.finish.rotate_deg = 30;
  ASSERT_TRUE(parse_window("sloan", cases[2].convert.finish.window).ok());
  ASSERT_TRUE(parse_method("mc:256", cases[3].convert.method).ok());  // read whole, not streamed
  cases[4].convert.negative = Negative::Clamp;
  cases[4].source.colorspace = ColorSpace::AcesCg;
  cases[5].convert.finish.l1 = true;
  for (std::size_t k = 0; k < cases.size(); ++k)
    EXPECT_EQ(pixels_json(view, cases[k]), file_json(dir / "map.exr", cases[k])) << "case " << k;
}

TEST(ConvertPixels, ExtractionWorksOnACopy) {
  const ScratchDir dir;
  const int w = 64, h = 32;
  std::vector<float> pixels(static_cast<std::size_t>(w) * h * 3, 0.25f);
  for (int c = 0; c < 3; ++c) pixels[(5 * w + 20) * 3 + c] = 4000.0f;  // a one-texel sun
  ASSERT_TRUE(shpack_io_test::write_image(dir / "sun.exr", w, h, 3, pixels));
  const std::vector<float> before = pixels;
  for (const bool sun : {true, false}) {
    ConvertSettings settings;
    settings.convert.extract_sun = sun;
    settings.convert.extract_lights = sun ? 0 : 2;
    EXPECT_EQ(pixels_json(make_view(pixels.data(), w, h, 3), settings), file_json(dir / "sun.exr", settings));
    EXPECT_EQ(pixels, before) << "the caller's pixels were written";
  }
  ConvertSettings settings;
  settings.convert.extract_sun = true;
  ShDocument doc;
  ASSERT_TRUE(convert_pixels(make_view(pixels.data(), w, h, 3), "pixels", settings, doc).ok());
  EXPECT_TRUE(doc.sun.has_value()) << "no sun was taken out: the copy was not needed";
}

TEST(ConvertPixels, GreyHalfCrossAndSixFaces) {
  const ScratchDir dir;
  const ConvertSettings settings;
  // Grey: one channel, R = G = B.
  const std::vector<float> grey = texels(32, 16, 1);
  ASSERT_TRUE(shpack_io_test::write_image(dir / "grey.exr", 32, 16, 1, grey));
  EXPECT_EQ(pixels_json(make_view(grey.data(), 32, 16, 1), settings), file_json(dir / "grey.exr", settings));
  // F16 views are their float values.
  std::vector<std::uint16_t> halves(grey.size(), 0x3c00);  // 1.0
  halves[7] = 0x4200;                                        // 3.0
  std::vector<float> widened(grey.size(), 1.0f);
  widened[7] = 3.0f;
  const ImageView half_view{reinterpret_cast<const std::byte*>(halves.data()), PixelType::F16, 32, 16, 1,
                            kAutoStride, kAutoStride};
  EXPECT_EQ(pixels_json(half_view, settings), pixels_json(make_view(widened.data(), 32, 16, 1), settings));
  // A horizontal cross (4:3), detected, and in the GL frame.
  const std::vector<float> cross = texels(16, 12, 3);
  ASSERT_TRUE(shpack_io_test::write_image(dir / "cross.exr", 16, 12, 3, cross));
  ConvertSettings gl;
  gl.source.cube_frame = CubeFrame::Gl;
  for (const ConvertSettings& s : {settings, gl})
    EXPECT_EQ(pixels_json(make_view(cross.data(), 16, 12, 3), s), file_json(dir / "cross.exr", s));
  // Six faces, as six files.
  std::array<std::vector<float>, kCubeFaceCount> faces;
  std::array<ImageView, kCubeFaceCount> views;
  std::array<fs::path, kCubeFaceCount> files;
  for (std::uint32_t f = 0; f < kCubeFaceCount; ++f) {
    faces[f] = texels(4, 4, 3, f);
    views[f] = make_view(faces[f].data(), 4, 4, 3);
    files[f] = dir / ("face" + std::to_string(f) + ".exr");
    ASSERT_TRUE(shpack_io_test::write_image(files[f], 4, 4, 3, faces[f]));
  }
  ShDocument from_pixels, from_files;
  ASSERT_TRUE(convert_pixel_faces(views, "pixels", settings, from_pixels).ok());
  ASSERT_TRUE(convert_cube_faces(files, settings, from_files).ok());
  EXPECT_EQ(to_json(from_pixels), json_without_files(from_files));
}

TEST(ConvertPixels, ErrorsNameThePixelsAsAFilesNameTheFile) {
  const ScratchDir dir;
  std::vector<float> pixels = texels(32, 16, 3);
  pixels[(6 * 32 + 11) * 3 + 2] = std::numeric_limits<float>::quiet_NaN();
  ASSERT_TRUE(shpack_io_test::write_image(dir / "nan.exr", 32, 16, 3, pixels));
  ShDocument doc;
  const IoStatus from_file = convert_env_map(dir / "nan.exr", {}, doc);
  const IoStatus from_pixels = convert_pixels(make_view(pixels.data(), 32, 16, 3), "pixels", {}, doc);
  EXPECT_EQ(from_pixels.code, IoErrc::NonFiniteTexel);
  EXPECT_EQ(from_pixels.message, "pixels: 1 NaN/Inf texels (first at x=11, y=6)");
  EXPECT_EQ("pixels" + from_file.message.substr((dir / "nan.exr").string().size()), from_pixels.message);
  EXPECT_EQ(with_remedy(from_pixels, Layout::Auto), from_pixels.message + "; use --nonfinite=zero to replace them");

  const std::vector<float> odd = texels(7, 5, 3);
  const IoStatus shape = convert_pixels(make_view(odd.data(), 7, 5, 3), "pixels", {}, doc);
  EXPECT_EQ(shape.code, IoErrc::UnknownLayout);
  EXPECT_EQ(shape.message.rfind("pixels: the layout of a 7x5 image cannot be detected", 0), 0u) << shape.message;

  ConvertSettings layered;
  layered.source.layer = "diffuse";
  EXPECT_EQ(convert_pixels(make_view(odd.data(), 7, 5, 3), "pixels", layered, doc).code, IoErrc::InvalidArgument);
  ConvertSettings faces_layout;
  faces_layout.source.layout = Layout::Faces;
  EXPECT_EQ(convert_pixels(make_view(odd.data(), 7, 5, 3), "pixels", faces_layout, doc).code,
            IoErrc::InvalidArgument);
  EXPECT_EQ(convert_pixels(ImageView{}, "pixels", {}, doc).message, "pixels: image data is null");

  std::array<std::vector<float>, kCubeFaceCount> faces;
  std::array<ImageView, kCubeFaceCount> views;
  for (std::uint32_t f = 0; f < kCubeFaceCount; ++f) {
    faces[f].assign(4 * 4 * 3, 1.0f);
    views[f] = make_view(faces[f].data(), 4, 4, 3);
  }
  faces[4][(1 * 4 + 2) * 3] = std::numeric_limits<float>::infinity();
  EXPECT_EQ(convert_pixel_faces(views, "pixels", {}, doc).message, "pixels[4]: 1 NaN/Inf texels (first at x=2, y=1)");
  const std::vector<float> small(3 * 3 * 3, 1.0f);
  views[3] = make_view(small.data(), 3, 3, 3);
  EXPECT_EQ(convert_pixel_faces(views, "pixels", {}, doc).message, "pixels[3]: the face is 3x3 but pixels[0] is 4x4");
}

}  // namespace
}  // namespace shpack::io
