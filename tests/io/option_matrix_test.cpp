// The option matrix of the conversion pipeline (shpack/pipeline.h): every option against
// every method and every layout, through files as `shpack convert` reads them.
//
// Each input is a small EXR whose light is in a channel layer "diffuse" (diffuse.R/G/B),
// tagged with ACEScg chromaticities, beside plain R, G, B channels holding a decoy: a path
// that ignored --layer would project the decoy, one that ignored the chromaticities would skip
// the colour matrix. For every (layout, method, option) the document must hold what the
// test composes by hand from the core's own projector of that layout and method (proven
// against oracles in the core's tests) and the stated finish formulas (pipeline.h):
//   radiance = rotate_about_y(k M L_proj, rotate), windowed, band 2 zeroed under --l1.
// Both sides do the same double operations in the same order, so they agree to rounding; the
// tolerance allows 1e-13 of the coefficient norm (a few ulp, for any reordering of sums).
//
// A second input, uniform (1, 2, 3) in the layer, has a known answer for every method:
// L00 = 2 sqrt(pi) k (M v)_c. The methods integrate a constant exactly up to rounding, except
// riemann:N, whose weights sum to 4 pi (1 + pi^2 / (24 N^2)) (the midpoint rule on
// int_0^pi sin t dt with N cells gives (pi/N) / sin(pi/(2N)) = 2 (1 + pi^2/(24 N^2) + ...)).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io_test_files.h"
#include "shpack/colorspace.h"
#include "shpack/convolution.h"
#include "shpack/cube_layout.h"
#include "shpack/io/convert.h"
#include "shpack/io/json_writer.h"
#include "shpack/project_cube.h"
#include "shpack/project_sphere_map.h"
#include "shpack/rotate.h"
#include "shpack/sampling_methods.h"
#include "shpack/window.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;
using shpack_io_test::ScratchDir;

constexpr float kAp1Tag[8] = {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
constexpr std::array<float, 3> kDecoy = {7, 7, 7};

// Writes `layer` (RGB per texel) as diffuse.R/G/B beside R, G, B = kDecoy, ACEScg-tagged.
void write_layered(const fs::path& path, int w, int h, const std::vector<float>& layer) {
  OIIO::ImageSpec spec(w, h, 6, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"B", "G", "R", "diffuse.B", "diffuse.G", "diffuse.R"};
  spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), kAp1Tag);
  std::vector<float> pixels;
  for (std::size_t t = 0; t < layer.size() / 3; ++t)
    pixels.insert(pixels.end(), {kDecoy[2], kDecoy[1], kDecoy[0], layer[3 * t + 2], layer[3 * t + 1], layer[3 * t]});
  const std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

struct LayoutCase {
  Layout layout;
  int w, h;  // of the image (of one face for Faces)
};
constexpr std::array<LayoutCase, 9> kLayouts = {{{Layout::Equirect, 16, 8},
                                                 {Layout::HorizontalCross, 16, 12},
                                                 {Layout::VerticalCross, 12, 16},
                                                 {Layout::HorizontalStrip, 24, 4},
                                                 {Layout::VerticalStrip, 4, 24},
                                                 {Layout::Faces, 4, 4},
                                                 {Layout::Octahedral, 8, 8},
                                                 {Layout::Angular, 8, 8},
                                                 {Layout::MirrorBall, 8, 8}}};

const std::vector<std::string>& method_specs() {
  static const std::vector<std::string> specs = {"exact", "center", "mip:1",  "mc:256",       "qmc:256", "fib:256",
                                                 "is:256", "riemann:64", "cube:8", "cube-exact:8", "lsq:64"};
  return specs;
}

bool method_fits(Layout layout, const MethodSpec& m) {
  if (layout == Layout::Equirect) return true;
  if (layout == Layout::Octahedral || layout == Layout::Angular || layout == Layout::MirrorBall)
    return m.method == SamplingMethod::Exact;
  return m.method == SamplingMethod::Exact || m.method == SamplingMethod::Center;
}

// One option changed from the defaults (or all of them at once).
struct OptionCase {
  const char* name;
  double intensity = 1.0, rotate_deg = 0.0;
  const char* window = "none";
  bool l1 = false, extract_sun = false;
  NonFinite nonfinite = NonFinite::Error;
  Negative negative = Negative::Keep;
  bool nan_input = false;  // the input with a NaN texel
};
const std::vector<OptionCase>& option_cases() {
  static const std::vector<OptionCase> cases = {
      {"defaults"},
      {"intensity", 2.5},
      {"rotate", 1.0, 37.0},
      {"window hanning", 1.0, 0.0, "hanning:3"},
      {"window sloan", 1.0, 0.0, "sloan"},
      {"l1", 1.0, 0.0, "none", true},
      {"extract-sun (no sun)", 1.0, 0.0, "none", false, true},
      {"negative clamp", 1.0, 0.0, "none", false, false, NonFinite::Error, Negative::Clamp},
      {"nonfinite error", 1.0, 0.0, "none", false, false, NonFinite::Error, Negative::Keep, true},
      {"nonfinite zero", 1.0, 0.0, "none", false, false, NonFinite::Zero, Negative::Keep, true},
      {"all", 0.75, -123.0, "lanczos:2", true, true, NonFinite::Zero, Negative::Clamp, true},
  };
  return cases;
}

// The pixels of one test image: random values in [0.5, 1.5] (no texel stands out like a
// sun: the largest is at most 3x the smallest), two negative texels near the centre (inside
// every sphere map's disc) and, if asked, a NaN texel at the centre.
std::vector<float> layer_pixels(int w, int h, std::uint64_t seed, bool with_nan) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> value(0.5f, 1.5f);
  std::vector<float> p(std::size_t(3) * w * h);
  for (float& v : p) v = value(rng);
  const int centre = (h / 2) * w + w / 2;
  p[3 * (centre - 1) + 1] = -0.25f;
  p[3 * (centre - w)] = -0.5f;
  if (with_nan) p[3 * centre + 2] = std::numeric_limits<float>::quiet_NaN();
  return p;
}

// The core's projector for the layout, with the case's value policies: what stage 3 must give.
Status core_projection(const LayoutCase& lc, const std::vector<std::vector<float>>& images, const MethodSpec& m,
                       const OptionCase& oc, ShL2& radiance) {
  const ProjectOptions policies{m.method, oc.nonfinite, oc.negative, 1};
  Status st;
  if (lc.layout == Layout::Faces) {
    std::array<ImageView, kCubeFaceCount> faces;
    for (int f = 0; f < kCubeFaceCount; ++f) faces[f] = make_view(images[f].data(), lc.w, lc.h, 3);
    st = project_cube(faces, policies, radiance);
  } else {
    const ImageView image = make_view(images[0].data(), lc.w, lc.h, 3);
    switch (lc.layout) {
      case Layout::Equirect: st = project_with_method(image, m, policies, radiance); break;
      case Layout::Octahedral: st = project_sphere_map(image, SphereMap::Octahedral, policies, radiance); break;
      case Layout::Angular: st = project_sphere_map(image, SphereMap::Angular, policies, radiance); break;
      case Layout::MirrorBall: st = project_sphere_map(image, SphereMap::MirrorBall, policies, radiance); break;
      default: {
        const CubeLayout cube = lc.layout == Layout::HorizontalCross ? CubeLayout::HorizontalCross
                                : lc.layout == Layout::VerticalCross ? CubeLayout::VerticalCross
                                : lc.layout == Layout::HorizontalStrip ? CubeLayout::HorizontalStrip
                                                                       : CubeLayout::VerticalStrip;
        std::array<ImageView, kCubeFaceCount> faces;
        EXPECT_TRUE(cube_face_views(image, cube, faces).ok());
        st = project_cube(faces, policies, radiance);
      }
    }
  }
  return st;
}

Matrix3 ap1_matrix() {
  Chromaticities tag;
  for (int k = 0; k < 8; ++k) tag[k] = kAp1Tag[k];
  Matrix3 m;
  std::string problem;
  EXPECT_TRUE(rgb_to_rec709_matrix(tag, m, problem)) << problem;
  return m;
}

// The finish stage by hand (pipeline.h's formulas).
ShL2 finished_by_hand(const ShL2& projected, const OptionCase& oc) {
  const ShL2 radiance = rotate_about_y(scaled(mix_channels(projected, ap1_matrix()), oc.intensity), oc.rotate_deg);
  Window window;
  EXPECT_TRUE(parse_window(oc.window, window).ok());
  ShL2 unity;
  WindowResult factors;
  EXPECT_TRUE(apply_window(radiance_to_unity_form(radiance), window, unity, &factors).ok());
  ShL2 out = apply_band_factors(radiance, factors.factors);
  if (oc.l1)
    for (auto& channel : out.c)
      for (int i = 4; i < kShCount; ++i) channel[i] = 0.0;
  return out;
}

ConvertSettings settings_of(const LayoutCase& lc, const MethodSpec& m, const OptionCase& oc) {
  ConvertSettings s;
  s.source.layout = lc.layout == Layout::Faces ? Layout::Auto : lc.layout;
  s.source.layer = "diffuse";
  s.convert.method = m;
  s.convert.nonfinite = oc.nonfinite;
  s.convert.negative = oc.negative;
  s.convert.extract_sun = oc.extract_sun;
  s.convert.finish.intensity = oc.intensity;
  s.convert.finish.rotate_deg = oc.rotate_deg;
  EXPECT_TRUE(parse_window(oc.window, s.convert.finish.window).ok());
  s.convert.finish.l1 = oc.l1;
  return s;
}

struct Inputs {
  std::vector<std::vector<float>> images;  // one, or six faces
  std::vector<fs::path> files;
};

Inputs write_inputs(const ScratchDir& dir, const LayoutCase& lc, const std::string& tag, bool uniform, bool nan) {
  Inputs in;
  const int count = lc.layout == Layout::Faces ? kCubeFaceCount : 1;
  for (int f = 0; f < count; ++f) {
    std::vector<float> pixels = layer_pixels(lc.w, lc.h, 100 + f, nan);
    if (uniform)
      for (std::size_t t = 0; t < pixels.size(); ++t) pixels[t] = static_cast<float>(t % 3 + 1);
    const fs::path path = dir / (tag + "_" + std::to_string(f) + ".exr");
    write_layered(path, lc.w, lc.h, pixels);
    in.images.push_back(std::move(pixels));
    in.files.push_back(path);
  }
  return in;
}

IoStatus convert(const Inputs& in, const ConvertSettings& s, ShDocument& doc) {
  if (in.files.size() == 1) return convert_env_map(in.files[0], s, doc);
  std::array<fs::path, kCubeFaceCount> faces;
  for (int f = 0; f < kCubeFaceCount; ++f) faces[f] = in.files[f];
  return convert_cube_faces(faces, s, doc);
}

double norm(const ShL2& sh) {
  double s = 0;
  for (const auto& channel : sh.c)
    for (const double v : channel) s += v * v;
  return std::sqrt(s);
}

// The document states exactly the options applied.
void expect_reported(const ShDocument& doc, const MethodSpec& m, const OptionCase& oc, const std::string& what) {
  const nlohmann::json j = nlohmann::json::parse(to_json(doc));
  EXPECT_EQ(j["options"]["method"], std::string(method_name(m).view())) << what;
  Window window;
  ASSERT_TRUE(parse_window(oc.window, window).ok());
  EXPECT_EQ(j["options"]["window"], window_name(window).text) << what;
  EXPECT_EQ(j["options"]["rotate_deg"].get<double>(), oc.rotate_deg) << what;
  EXPECT_EQ(j["options"]["intensity"].get<double>(), oc.intensity) << what;
  EXPECT_EQ(j["options"].contains("l1"), oc.l1) << what;
  EXPECT_EQ(j["source"]["layer"], "diffuse") << what;
  EXPECT_EQ(j["source"]["colorspace"], "acescg") << what;
  EXPECT_TRUE(j["source"].contains("rgb_to_rec709")) << what;
  EXPECT_EQ(j.contains("sun"), oc.extract_sun) << what;
  if (oc.extract_sun) {
    EXPECT_TRUE(j["sun"].is_null()) << what << ": a sunless map has no sun";
  }
}

TEST(OptionMatrix, EveryOptionMeansTheSameWithEveryMethodAndLayout) {
  const ScratchDir dir;
  int checked = 0, refused = 0, nonfinite = 0;
  for (const LayoutCase& lc : kLayouts) {
    const std::string name = layout_name(lc.layout);
    const Inputs clean = write_inputs(dir, lc, name, false, false), with_nan = write_inputs(dir, lc, name + "_nan", false, true);
    for (const std::string& text : method_specs()) {
      MethodSpec m;
      ASSERT_TRUE(parse_method(text, m).ok());
      for (const OptionCase& oc : option_cases()) {
        const std::string what = name + " / " + text + " / " + oc.name;
        const Inputs& in = oc.nan_input ? with_nan : clean;
        ShDocument doc;
        const IoStatus st = convert(in, settings_of(lc, m, oc), doc);
        if (!method_fits(lc.layout, m) || (oc.extract_sun && lc.layout != Layout::Equirect)) {
          EXPECT_EQ(st.code, IoErrc::InvalidArgument) << what << ": " << st.message;
          ++refused;
          continue;
        }
        ShL2 projected;
        const Status core = core_projection(lc, in.images, m, oc, projected);
        if (core.code == Errc::NonFiniteTexel) {  // the NaN texel, read under NonFinite::Error
          EXPECT_EQ(st.code, IoErrc::NonFiniteTexel) << what << ": " << st.message;
          ++nonfinite;
          continue;
        }
        ASSERT_TRUE(core.ok()) << what << ": " << core.what;
        ASSERT_TRUE(st.ok()) << what << ": " << st.message;
        const ShL2 want = finished_by_hand(projected, oc);
        const double tolerance = 1e-13 * norm(want);
        for (int c = 0; c < kChannelCount; ++c)
          for (int i = 0; i < kShCount; ++i)
            EXPECT_NEAR(doc.sh.radiance.c[c][i], want.c[c][i], tolerance) << what << " c=" << c << " i=" << i;
        expect_reported(doc, m, oc, what);
        ++checked;
      }
    }
  }
  // Refused: 9 sampling methods x 11 cases on each of the 8 other layouts, center x 11 on the
  // three sphere maps, and --extract-sun (2 cases) with exact and center on the five cube
  // layouts and with exact on the three sphere maps.
  EXPECT_EQ(refused, 9 * 11 * 8 + 3 * 11 + 5 * 2 * 2 + 3 * 2);
  // exact, center, mip and is read every texel (sampling_methods.h), so the NaN is seen under
  // NonFinite::Error by exact on 9 layouts, center on 5 cube layouts and equirect, mip and is.
  EXPECT_GE(nonfinite, 9 + 6 + 2);
  // Every other fitting case is checked: 11 methods x 10 cases on equirect, exact and center
  // x 8 on five cube layouts, exact x 8 on three sphere maps.
  EXPECT_GE(checked, 11 * 10 + 5 * 2 * 8 + 3 * 8);
}

TEST(OptionMatrix, AUniformLayerGivesItsKnownL00WithEveryMethod) {
  const ScratchDir dir;
  const Matrix3 m709 = ap1_matrix();
  for (const LayoutCase& lc : kLayouts) {
    const Inputs in = write_inputs(dir, lc, std::string("uniform_") + layout_name(lc.layout), true, false);
    for (const std::string& text : method_specs()) {
      MethodSpec m;
      ASSERT_TRUE(parse_method(text, m).ok());
      if (!method_fits(lc.layout, m)) continue;
      OptionCase oc{"intensity", 1.5};
      ShDocument doc;
      const IoStatus st = convert(in, settings_of(lc, m, oc), doc);
      ASSERT_TRUE(st.ok()) << st.message;
      const double n = m.method == SamplingMethod::Riemann ? m.param : 0;
      const double relative = n > 0 ? std::numbers::pi * std::numbers::pi / (24 * n * n) * 1.01 : 1e-12;
      for (int c = 0; c < kChannelCount; ++c) {
        const double v = m709[c][0] * 1 + m709[c][1] * 2 + m709[c][2] * 3;
        const double want = 2 * std::sqrt(std::numbers::pi) * 1.5 * v;
        EXPECT_NEAR(doc.sh.radiance.c[c][0], want, relative * std::abs(want))
            << layout_name(lc.layout) << " / " << text << " c=" << c;
      }
    }
  }
}

TEST(OptionMatrix, ASunIsTakenFromTheLayerInTheOutputPrimaries) {
  // A bright disc in the layer, none in the decoy: the light comes from the layer, and its
  // irradiance is in Rec. 709 (the colour matrix applied to it as to the SH), scaled and
  // turned like the SH.
  const ScratchDir dir;
  const int w = 256, h = 128;
  std::vector<float> pixels(std::size_t(3) * w * h, 0.5f);
  const Dir3 centre = equirect_direction(0.3, 0.3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Dir3 d = equirect_direction((x + 0.5) / w, (y + 0.5) / h);
      if (d.x * centre.x + d.y * centre.y + d.z * centre.z > std::cos(2.0 * std::numbers::pi / 180))
        for (int c = 0; c < 3; ++c) pixels[3 * (std::size_t(y) * w + x) + c] = 5000.0f * (c + 1);
    }
  write_layered(dir / "sun.exr", w, h, pixels);
  OptionCase oc{"sun", 2.0, 90.0, "none", false, true};
  MethodSpec exact;
  ShDocument doc;
  ASSERT_TRUE(convert_env_map(dir / "sun.exr", settings_of({Layout::Equirect, w, h}, exact, oc), doc).ok());
  ASSERT_TRUE(doc.sun.has_value());
  // The same extraction on the layer's pixels, luminance weighted in the output primaries.
  const Matrix3 m = ap1_matrix();
  SunSearch search;
  for (int j = 0; j < 3; ++j)
    search.luminance[j] = kRec709Luminance[0] * m[0][j] + kRec709Luminance[1] * m[1][j] + kRec709Luminance[2] * m[2][j];
  std::vector<float> copy = pixels;
  std::optional<SunLight> sun;
  ASSERT_TRUE(extract_sun(make_view(copy.data(), w, h, 3), copy.data(), search, sun).ok());
  ASSERT_TRUE(sun.has_value());
  for (int c = 0; c < 3; ++c) {
    const double want = 2.0 * (m[c][0] * sun->irradiance[0] + m[c][1] * sun->irradiance[1] + m[c][2] * sun->irradiance[2]);
    EXPECT_NEAR(doc.sun->light.irradiance[c], want, 1e-12 * std::abs(want)) << c;
  }
  const Matrix3 r = rotation_about_y(90.0);
  const Dir3 d = sun->direction;
  EXPECT_NEAR(doc.sun->light.direction.x, r[0][0] * d.x + r[0][1] * d.y + r[0][2] * d.z, 1e-15);
  EXPECT_NEAR(doc.sun->light.direction.z, r[2][0] * d.x + r[2][1] * d.y + r[2][2] * d.z, 1e-15);
  // The SH is the rest of the layer: the disc's texels at the sky level, projected and finished.
  ShL2 rest;
  ASSERT_TRUE(project_equirect(make_view(copy.data(), w, h, 3), {}, rest).ok());
  const ShL2 want = finished_by_hand(rest, oc);
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i)
      EXPECT_NEAR(doc.sh.radiance.c[c][i], want.c[c][i], 1e-13 * norm(want)) << c << " " << i;
}

}  // namespace
}  // namespace shpack::io
