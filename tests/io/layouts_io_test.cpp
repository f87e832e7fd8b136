// Reading every layout from files (map_source.h, convert.h): crosses, strips and faces through
// project_cube, the sphere maps through project_sphere_map, the cube frames; and the
// sources: EXR parts and layers (--layer), data windows smaller than the display window,
// chromaticities and --colorspace.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "io_test_files.h"
#include "shpack/cube_layout.h"
#include "shpack/colorspace.h"
#include "shpack/io/convert.h"
#include "shpack/io/map_source.h"
#include "shpack/project_cube.h"
#include "shpack/project_sphere_map.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;
using shpack_io_test::ScratchDir;
using shpack_io_test::write_image;

// Random positive float RGB pixels.
std::vector<float> random_pixels(std::size_t texels, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> value(0.0f, 2.0f);
  std::vector<float> p(3 * texels);
  for (float& v : p) v = value(rng);
  return p;
}

// What the source held and the radiance projected from it. With the default settings the
// finish stage applies intensity 1, no rotation and no window: the projector's radiance up to
// exact operations.
struct Projection {
  SourceInfo info;
  ShL2 radiance;
};

Projection project(const fs::path& path, const ConvertSettings& settings = {}) {
  Projection out;
  Conversion conversion;
  const IoStatus st = convert_file(path, settings, conversion, &out.info);
  EXPECT_TRUE(st.ok()) << st.message;
  out.radiance = conversion.sh.radiance;
  return out;
}

// Both projections read the same float texels with the same arithmetic: equal bit for bit.
void expect_same(const ShL2& a, const ShL2& b, const std::string& what) {
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) EXPECT_EQ(a.c[c][i], b.c[c][i]) << what << " c=" << c << " i=" << i;
}

struct CubeCase {
  Layout layout;
  CubeLayout core;
  std::uint32_t columns, rows;
};
constexpr std::array<CubeCase, 4> kCubeCases = {{{Layout::HorizontalCross, CubeLayout::HorizontalCross, 4, 3},
                                                 {Layout::VerticalCross, CubeLayout::VerticalCross, 3, 4},
                                                 {Layout::HorizontalStrip, CubeLayout::HorizontalStrip, 6, 1},
                                                 {Layout::VerticalStrip, CubeLayout::VerticalStrip, 1, 6}}};

TEST(Layouts, CubeImagesAreDetectedAndProjectedAsTheirFaces) {
  const ScratchDir dir;
  const std::uint32_t n = 8;
  for (const CubeCase& c : kCubeCases) {
    const std::uint32_t w = c.columns * n, h = c.rows * n;
    const std::vector<float> pixels = random_pixels(std::size_t{w} * h, 7 + c.columns);
    const fs::path path = dir / (std::string(layout_name(c.layout)) + ".exr");
    ASSERT_TRUE(write_image(path, static_cast<int>(w), static_cast<int>(h), 3, pixels));
    const Projection p = project(path);  // auto
    EXPECT_EQ(p.info.layout, c.layout) << layout_name(c.layout);
    std::array<ImageView, kCubeFaceCount> faces;
    ASSERT_TRUE(cube_face_views(make_view(pixels.data(), w, h, 3), c.core, faces).ok());
    ShL2 want;
    ASSERT_TRUE(project_cube(faces, {}, want).ok());
    expect_same(p.radiance, want, layout_name(c.layout));
  }
}

TEST(Layouts, SquareImagesNeedTheirLayoutNamed) {
  const ScratchDir dir;
  const std::uint32_t n = 12;
  const std::vector<float> pixels = random_pixels(std::size_t{n} * n, 3);
  ASSERT_TRUE(write_image(dir / "sq.exr", n, n, 3, pixels));
  Conversion p;
  const IoStatus st = convert_file(dir / "sq.exr", {}, p);
  EXPECT_EQ(st.code, IoErrc::UnknownLayout);
  EXPECT_EQ(st.message, (dir / "sq.exr").string() +
                            ": the layout of a 12x12 image is ambiguous: it fits octahedral, angular and mirrorball");
  for (const auto& [layout, map] : {std::pair{Layout::Octahedral, SphereMap::Octahedral},
                                    std::pair{Layout::Angular, SphereMap::Angular},
                                    std::pair{Layout::MirrorBall, SphereMap::MirrorBall}}) {
    ConvertSettings options;
    options.source.layout = layout;
    const Projection got = project(dir / "sq.exr", options);
    EXPECT_EQ(got.info.layout, layout);
    ShL2 want;
    ASSERT_TRUE(project_sphere_map(make_view(pixels.data(), n, n, 3), map, {}, want).ok());
    expect_same(got.radiance, want, layout_name(layout));
  }
}

TEST(Layouts, AWrongShapeSaysWhatWouldFit) {
  const ScratchDir dir;
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "wide.exr", 16, 8, {1, 1, 1}));
  ConvertSettings cross;
  cross.source.layout = Layout::HorizontalCross;
  Conversion p;
  const IoStatus st = convert_file(dir / "wide.exr", cross, p);
  EXPECT_EQ(st.code, IoErrc::UnknownLayout);
  EXPECT_EQ(st.message, (dir / "wide.exr").string() + ": a 16x8 image is not a hcross (4N x 3N); its shape fits equirect");
  EXPECT_EQ(st.message.find('\n'), std::string::npos);
  cross.source.layout = Layout::Angular;
  EXPECT_EQ(convert_file(dir / "wide.exr", cross, p).message,
            (dir / "wide.exr").string() + ": a 16x8 image is not an angular (N x N); its shape fits equirect");
}

TEST(Layouts, TheCubeFrameTurnsTheFaces) {
  // A bright texel at the centre of the +Z face of a horizontal cross: in Unity's frame it
  // lights +Z; faces made in a GL world light -Z (z mirrored); three.js faces too (a turn
  // about +Y). One at the centre of +X: +X (unity, gl), -X (three.js).
  const ScratchDir dir;
  const std::uint32_t n = 4;
  struct Marker {
    std::uint32_t cell_x, cell_y;
    CubeFrame frame;
    std::array<double, 3> lands;  // the unit axis the L1 part points to
  };
  const std::vector<Marker> markers = {{1, 1, CubeFrame::Unity, {0, 0, 1}},  {1, 1, CubeFrame::Gl, {0, 0, -1}},
                                       {1, 1, CubeFrame::ThreeJs, {0, 0, -1}}, {2, 1, CubeFrame::Unity, {1, 0, 0}},
                                       {2, 1, CubeFrame::Gl, {1, 0, 0}},      {2, 1, CubeFrame::ThreeJs, {-1, 0, 0}}};
  for (const Marker& m : markers) {
    std::vector<float> pixels(std::size_t{3} * 4 * n * 3 * n, 0.0f);
    for (std::uint32_t y = n / 2 - 1; y <= n / 2; ++y)
      for (std::uint32_t x = n / 2 - 1; x <= n / 2; ++x)
        pixels[3 * ((m.cell_y * n + y) * 4 * n + m.cell_x * n + x)] = 100.0f;  // red: the face's 4 centre texels
    ASSERT_TRUE(write_image(dir / "cross.exr", 4 * n, 3 * n, 3, pixels));
    ConvertSettings options;
    options.source.cube_frame = m.frame;
    const Projection p = project(dir / "cross.exr", options);
    const std::array<double, 3> l1 = {p.radiance.c[0][3], p.radiance.c[0][1], p.radiance.c[0][2]};
    const double norm = std::hypot(l1[0], l1[1], l1[2]);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(l1[k] / norm, m.lands[k], 1e-12) << "cell (" << m.cell_x << ", " << m.cell_y << ") frame "
                                                   << static_cast<int>(m.frame) << " axis " << k;
  }
  // The frame means nothing to an equirect map: refused rather than ignored.
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "sky.exr", 8, 4, {1, 1, 1}));
  ConvertSettings gl;
  gl.source.cube_frame = CubeFrame::Gl;
  Conversion p;
  EXPECT_EQ(convert_file(dir / "sky.exr", gl, p).code, IoErrc::InvalidArgument);
}

TEST(Layouts, NaNInACrossIsLocatedInTheImage) {
  const ScratchDir dir;
  const std::uint32_t n = 4;
  std::vector<float> pixels(std::size_t{3} * 3 * n * 4 * n, 1.0f);
  pixels[3 * ((3 * n + 1) * 3 * n + n + 2) + 1] = std::numeric_limits<float>::quiet_NaN();  // -Z cell, upside down
  pixels[3 * (0 * 3 * n + 0)] = std::numeric_limits<float>::quiet_NaN();  // an unused cell: never read
  ASSERT_TRUE(write_image(dir / "v.exr", 3 * n, 4 * n, 3, pixels));
  Conversion p;
  const IoStatus st = convert_file(dir / "v.exr", {}, p);
  EXPECT_EQ(st.code, IoErrc::NonFiniteTexel);
  EXPECT_EQ(st.message, (dir / "v.exr").string() + ": 1 NaN/Inf texels (first at x=6, y=13)");
}

// Six face files; face f holds the f-th cell of a horizontal strip.
std::array<fs::path, 6> write_faces(const ScratchDir& dir, std::uint32_t n, const std::vector<float>& strip) {
  std::array<fs::path, 6> paths;
  const char* names[6] = {"px", "nx", "py", "ny", "pz", "nz"};
  for (int f = 0; f < 6; ++f) {
    std::vector<float> face(std::size_t{3} * n * n);
    for (std::uint32_t y = 0; y < n; ++y)
      for (std::uint32_t x = 0; x < n; ++x)
        for (int c = 0; c < 3; ++c) face[3 * (y * n + x) + c] = strip[3 * (y * 6 * n + f * n + x) + c];
    paths[f] = dir / (std::string(names[f]) + ".exr");
    EXPECT_TRUE(write_image(paths[f], n, n, 3, face));
  }
  return paths;
}

TEST(Layouts, SixFacesGiveTheStripsProjection) {
  const ScratchDir dir;
  const std::uint32_t n = 8;
  const std::vector<float> strip = random_pixels(std::size_t{6} * n * n, 11);
  ASSERT_TRUE(write_image(dir / "strip.exr", 6 * n, n, 3, strip));
  const std::array<fs::path, 6> paths = write_faces(dir, n, strip);
  ConvertSettings settings;
  ShDocument faces, one;
  ASSERT_TRUE(convert_cube_faces(paths, settings, faces).ok());
  ASSERT_TRUE(convert_env_map(dir / "strip.exr", settings, one).ok());
  expect_same(faces.sh.radiance, one.sh.radiance, "faces vs strip");
  EXPECT_EQ(faces.source.layout, Layout::Faces);
  EXPECT_EQ(faces.source.files, (std::vector<std::string>{"px.exr", "nx.exr", "py.exr", "ny.exr", "pz.exr", "nz.exr"}));
  EXPECT_EQ(faces.source.sha256.size(), 6u);
  EXPECT_EQ(faces.source.width, n);
}

TEST(Layouts, BadFacesAreNamed) {
  const ScratchDir dir;
  const std::uint32_t n = 4;
  std::array<fs::path, 6> paths = write_faces(dir, n, random_pixels(std::size_t{6} * n * n, 5));
  ConvertSettings settings;
  ShDocument doc;
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "big.exr", 8, 8, {1, 1, 1}));
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "flat.exr", 4, 2, {1, 1, 1}));
  std::array<fs::path, 6> bad = paths;
  bad[3] = dir / "big.exr";
  IoStatus st = convert_cube_faces(bad, settings, doc);
  EXPECT_EQ(st.code, IoErrc::Unsupported);
  EXPECT_EQ(st.message, (dir / "big.exr").string() + ": the face is 8x8 but px.exr is 4x4");
  bad[3] = dir / "flat.exr";
  EXPECT_EQ(convert_cube_faces(bad, settings, doc).message, (dir / "flat.exr").string() + ": the face is 4x2, not square");
  bad[3] = dir / "missing.exr";
  st = convert_cube_faces(bad, settings, doc);
  EXPECT_EQ(st.code, IoErrc::NotFound);
  EXPECT_EQ(st.message, (dir / "missing.exr").string() + ": no such file");
}

// ---------------------------------------------------------------------------------------
// Sources

// Writes subimages (EXR parts) each with its own spec and float pixels.
void write_parts(const fs::path& path, const std::vector<OIIO::ImageSpec>& specs,
                 const std::vector<std::vector<float>>& pixels) {
  const std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), static_cast<int>(specs.size()), specs.data())) << out->geterror();
  for (std::size_t k = 0; k < specs.size(); ++k) {
    if (k > 0) {
      ASSERT_TRUE(out->open(path.string(), specs[k], OIIO::ImageOutput::AppendSubimage)) << out->geterror();
    }
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels[k].data())) << out->geterror();
  }
  ASSERT_TRUE(out->close());
}

TEST(Sources, APartIsChosenByName) {
  const ScratchDir dir;
  const int w = 8, h = 4;
  OIIO::ImageSpec a(w, h, 3, OIIO::TypeDesc::FLOAT), b(w, h, 3, OIIO::TypeDesc::FLOAT);
  a.attribute("oiio:subimagename", "beauty");
  b.attribute("oiio:subimagename", "sky");
  const std::vector<float> pa(3 * w * h, 1.0f), pb(3 * w * h, 5.0f);
  write_parts(dir / "parts.exr", {a, b}, {pa, pb});
  ConvertSettings options;
  EXPECT_NEAR(project(dir / "parts.exr", options).radiance.c[0][0], 2.0 * std::sqrt(std::numbers::pi), 1e-13);
  options.source.layer = "sky";
  EXPECT_NEAR(project(dir / "parts.exr", options).radiance.c[0][0], 10.0 * std::sqrt(std::numbers::pi), 1e-12);
  options.source.layer = "fog";
  Conversion p;
  const IoStatus st = convert_file(dir / "parts.exr", options, p);
  EXPECT_EQ(st.code, IoErrc::Unsupported);
  EXPECT_EQ(st.message, (dir / "parts.exr").string() + ": no layer 'fog' (its layers are beauty, sky)");
}

TEST(Sources, AChannelLayerIsChosenByName) {
  // One part with the channels of two layers, in EXR's alphabetical order; the layers' R, G
  // and B are found by name, not position.
  const ScratchDir dir;
  const int w = 8, h = 4;
  OIIO::ImageSpec spec(w, h, 6, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"diffuse.B", "diffuse.G", "diffuse.R", "specular.B", "specular.G", "specular.R"};
  std::vector<float> pixels;
  for (int t = 0; t < w * h; ++t) pixels.insert(pixels.end(), {3, 2, 1, 30, 20, 10});
  write_parts(dir / "layers.exr", {spec}, {pixels});
  ConvertSettings options;
  options.source.layer = "specular";
  const Projection p = project(dir / "layers.exr", options);
  const double l00 = 2.0 * std::sqrt(std::numbers::pi);
  EXPECT_NEAR(p.radiance.c[0][0], 10 * l00, 1e-12);
  EXPECT_NEAR(p.radiance.c[1][0], 20 * l00, 1e-12);
  EXPECT_NEAR(p.radiance.c[2][0], 30 * l00, 1e-12);
  EXPECT_EQ(p.info.ignored_channels, 3u);
  // Without --layer, a file of layers only is refused, naming them.
  Conversion q;
  const IoStatus st = convert_file(dir / "layers.exr", {}, q);
  EXPECT_EQ(st.code, IoErrc::Unsupported);
  EXPECT_EQ(st.message, (dir / "layers.exr").string() +
                            ": the image has no R, G, B or Y channels; its layers are diffuse, specular "
                            "(--layer chooses one)");
}

TEST(Sources, OutsideTheDataWindowIsBlack) {
  // A 16 x 8 display window with data only in x 4..11, y 2..5 (tiled, to take OpenImageIO's
  // tiled path too): the same as the full image with zeros around the data.
  const ScratchDir dir;
  const int w = 16, h = 8;
  OIIO::ImageSpec spec(8, 4, 3, OIIO::TypeDesc::FLOAT);
  spec.x = 4;
  spec.y = 2;
  spec.full_x = 0;
  spec.full_y = 0;
  spec.full_width = w;
  spec.full_height = h;
  spec.tile_width = spec.tile_height = 16;
  const std::vector<float> data = random_pixels(8 * 4, 21);
  write_parts(dir / "window.exr", {spec}, {data});
  std::vector<float> full(3 * w * h, 0.0f);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x)
      for (int c = 0; c < 3; ++c) full[3 * ((y + 2) * w + x + 4) + c] = data[3 * (y * 8 + x) + c];
  ASSERT_TRUE(write_image(dir / "full.exr", w, h, 3, full));
  const Projection a = project(dir / "window.exr"), b = project(dir / "full.exr");
  EXPECT_EQ(a.info.width, static_cast<std::uint32_t>(w));
  EXPECT_EQ(a.info.height, static_cast<std::uint32_t>(h));
  expect_same(a.radiance, b.radiance, "data window");
  // Data reaching outside the display window is cut off at it.
  spec.x = -4;
  spec.y = -2;
  write_parts(dir / "overhang.exr", {spec}, {data});
  std::vector<float> cut(3 * w * h, 0.0f);
  for (int y = 2; y < 4; ++y)
    for (int x = 4; x < 8; ++x)
      for (int c = 0; c < 3; ++c) cut[3 * ((y - 2) * w + x - 4) + c] = data[3 * (y * 8 + x) + c];
  ASSERT_TRUE(write_image(dir / "cut.exr", w, h, 3, cut));
  expect_same(project(dir / "overhang.exr").radiance, project(dir / "cut.exr").radiance, "overhang");
}

TEST(Sources, ChromaticitiesAreConvertedToRec709) {
  // An EXR tagged with ACEScg (AP1) primaries: the coefficients are the file's, mixed by the
  // AP1 -> Rec. 709 matrix (Bradford); --colorspace overrides the tag.
  const ScratchDir dir;
  const int w = 8, h = 4;
  const std::vector<float> pixels = random_pixels(w * h, 33);
  const Chromaticities ap1 = colorspace_chromaticities(ColorSpace::AcesCg);
  const float tag[8] = {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
  ASSERT_TRUE(write_image(dir / "ap1.exr", w, h, 3, pixels, OIIO::TypeDesc::FLOAT,
                          {OIIO::ParamValue("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), 1, tag)}));
  ASSERT_TRUE(write_image(dir / "plain.exr", w, h, 3, pixels));
  ConvertSettings settings;
  ShDocument tagged, plain, forced, ignored;
  ASSERT_TRUE(convert_env_map(dir / "ap1.exr", settings, tagged).ok());
  ASSERT_TRUE(convert_env_map(dir / "plain.exr", settings, plain).ok());
  EXPECT_EQ(tagged.reading.colorspace, "acescg");
  EXPECT_EQ(plain.reading.colorspace, "linear-rec709");
  EXPECT_FALSE(plain.colour_matrix.has_value());
  ASSERT_TRUE(tagged.colour_matrix.has_value());
  // The matrix from the file's float chromaticities and the one from the exact AP1 values
  // agree to the floats' rounding (2^-24 relative, times the matrix's condition ~ 3).
  Matrix3 want;
  std::string problem;
  ASSERT_TRUE(rgb_to_rec709_matrix(ap1, want, problem));
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR((*tagged.colour_matrix)[r][c], want[r][c], 1e-6) << r << "," << c;
  const ShL2 mixed = mix_channels(plain.sh.radiance, *tagged.colour_matrix);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < kShCount; ++i)
      EXPECT_NEAR(tagged.sh.radiance.c[c][i], mixed.c[c][i], 1e-14 * 8) << "c=" << c << " i=" << i;
  // --colorspace names the primaries whatever the file says.
  settings.source.colorspace = ColorSpace::LinearRec709;
  ASSERT_TRUE(convert_env_map(dir / "ap1.exr", settings, ignored).ok());
  expect_same(ignored.sh.radiance, plain.sh.radiance, "--colorspace linear-rec709");
  settings.source.colorspace = ColorSpace::AcesCg;
  ASSERT_TRUE(convert_env_map(dir / "plain.exr", settings, forced).ok());
  EXPECT_EQ(forced.reading.colorspace, "acescg");
}

TEST(Sources, DegenerateChromaticitiesAreRefused) {
  const ScratchDir dir;
  const float collinear[8] = {0.2f, 0.2f, 0.3f, 0.3f, 0.4f, 0.4f, 0.3127f, 0.3290f};
  ASSERT_TRUE(shpack_io_test::write_constant_image(
      dir / "bad.exr", 8, 4, {1, 1, 1}, OIIO::TypeDesc::FLOAT,
      {OIIO::ParamValue("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), 1, collinear)}));
  ShDocument doc;
  const IoStatus st = convert_env_map(dir / "bad.exr", {}, doc);
  EXPECT_EQ(st.code, IoErrc::Unsupported);
  EXPECT_EQ(st.message, (dir / "bad.exr").string() +
                            ": its chromaticities do not define three independent primaries and a white; "
                            "--colorspace can name the primaries");
}

}  // namespace
}  // namespace shpack::io
