// shpack preview: pixels at places whose value is known in closed form (the lit pole and the
// dark side of a sphere under a directional light, its negative ring, the colour bar's
// ends), the reference's error bound, and the command's file handling. No image hashes.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/convolution.h"
#include "shpack/io/atomic_write.h"
#include "shpack/io/json_reader.h"
#include "shpack/io/json_writer.h"
#include "shpack/io/preview.h"
#include "shpack/unity_pack.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;
using shpack_io_test::run_shpack;
using shpack_io_test::ScratchDir;
using Rgb = std::array<int, 3>;

constexpr double kPi = std::numbers::pi;
constexpr double kE = 4 * kPi;  // irradiance of the test light: mean E/pi = E/(4 pi) = 1

// E/pi of a directional light of irradiance E at angle gamma from the normal, truncated to L2:
// sum_l (A_l/pi) (2l+1)/(4 pi) P_l(cos gamma) E (addition theorem) =
// E/(4 pi) (1 + 2 cos g + (5/4) P_2(cos g)), P_2(c) = (3c^2 - 1)/2. 17E/(16 pi) at the pole,
// E/(16 pi) opposite, and a minimum of -19E/(480 pi) at cos g = -8/15.
double directional_e_over_pi(double cos_gamma) {
  return kE / (4 * kPi) * (1 + 2 * cos_gamma + 1.25 * 0.5 * (3 * cos_gamma * cos_gamma - 1));
}

// The document of that light from +Y: radiance L_i = E Y_i(+Y), with Y_i = k_i P_i.
ShJsonContent directional_document(const ScratchDir& dir) {
  ShDocument doc;
  doc.source = {{"sun.exr"}, {std::string(64, '0')}, Layout::Equirect, 64, 32};
  const double k0 = 0.5 / std::sqrt(kPi), k1 = std::sqrt(3.0) * k0, k20 = std::sqrt(5.0) / 4 / std::sqrt(kPi);
  for (auto& channel : doc.sh.radiance.c) {
    channel = {};
    channel[0] = kE * k0;
    channel[1] = kE * k1;            // P_1 = y = 1
    channel[6] = kE * k20 * (0 - 1); // P_6 = 3z^2 - 1 = -1
    channel[8] = kE * std::sqrt(15.0) / 4 / std::sqrt(kPi) * (0 - 1);  // P_8 = x^2 - y^2 = -1
  }
  doc.sh.unity_form = radiance_to_unity_form(doc.sh.radiance);
  doc.sh.unity_sh = to_unity_sh(doc.sh.unity_form);  // packed as the finish stage packs (pipeline.h)
  doc.sh.shader = to_shader_vectors(doc.sh.unity_form);
  EXPECT_TRUE(write_file_atomically(dir / "sun.json", to_json(doc)).ok());
  ShJsonContent content;
  EXPECT_TRUE(read_sh_json(dir / "sun.json", content).ok());
  return content;
}

// The tone mapping of preview.h, written out: Reinhard(k v), sRGB encoding, 8 bits.
int tone(double v, double k) {
  const double x = k * v / (1 + k * v);
  const double encoded = x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1 / 2.4) - 0.055;
  return static_cast<int>(std::lround(255 * encoded));
}

Rgb pixel(const Rgb8Image& image, std::uint32_t x, std::uint32_t y) {
  const std::uint8_t* p = image.at(x, y);
  return {p[0], p[1], p[2]};
}

void expect_grey_near(const Rgb& got, int want, const std::string& where) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want, 1) << where << " channel " << c;
}

// A 64 x 32 equirect map, dark but for its top row: a cap of 5.6 degrees about +Y.
void write_cap_map(const fs::path& path) {
  std::vector<float> pixels(64 * 32 * 3, 0.0f);
  std::fill(pixels.begin(), pixels.begin() + 64 * 3, 400.0f);
  ASSERT_TRUE(shpack_io_test::write_image(path, 64, 32, 3, pixels));
}

TEST(Preview, DirectionalLightLightsThePoleAndRingsWhereTheoryPutsIt) {
  const ScratchDir dir;
  const ShJsonContent content = directional_document(dir);
  PreviewSettings settings;
  settings.size = 128;
  Rgb8Image image;
  PreviewReport report;
  ASSERT_TRUE(render_preview(content, settings, image, report).ok());
  const double k = report.exposure;
  EXPECT_NEAR(k, 1.0, 1e-6);  // mean E/pi = 1

  // Top view, centre pixel: the normal is within 0.6 degrees of +Y, the lit pole.
  const std::uint32_t s = settings.size;
  const double c = (s / 2 + 0.5) * 2 / s - 1;  // the centre pixel's screen offset
  const double pole_cos = std::sqrt(1 - 2 * c * c);
  expect_grey_near(pixel(image, report.top.x + s / 2, report.top.y + s / 2), tone(directional_e_over_pi(pole_cos), k),
                   "top view centre (lit pole)");
  EXPECT_GE(pixel(image, report.top.x + s / 2, report.top.y + s / 2)[0], 230);

  // Front view, bottom centre pixel: the normal points almost straight down, the dark side.
  const double sy = 1 - 2 * (s - 1 + 0.5) / s;
  expect_grey_near(pixel(image, report.front.x + s / 2, report.front.y + s - 1), tone(directional_e_over_pi(sy), k),
                   "front view bottom (dark side)");

  // The equirect panel's row at 121.6 degrees from +Y is negative all round (the minimum is at
  // 122.2 degrees): only stripes there, magenta on black.
  const std::uint32_t ring_row = report.sh.y + 86;
  ASSERT_LT(directional_e_over_pi(std::cos(kPi * 86.5 / s)), 0.0);
  int magenta = 0;
  for (std::uint32_t x = report.sh.x; x < report.sh.x + report.sh.width; ++x) {
    const Rgb p = pixel(image, x, ring_row);
    EXPECT_TRUE(p == (Rgb{255, 0, 255}) || p == (Rgb{0, 0, 0})) << "x=" << x;
    magenta += p == Rgb{255, 0, 255};
  }
  EXPECT_GT(magenta, static_cast<int>(report.sh.width) / 4);
  // A row at 90 degrees is lit and tone-mapped (cos gamma = 0: E/pi = 1 - 5/8 = 0.375).
  expect_grey_near(pixel(image, report.sh.x + 7, report.sh.y + s / 2), tone(directional_e_over_pi(std::cos(kPi * (s / 2 + 0.5) / s)), k),
                   "equator");
  // E/pi < 0 between the roots of 15/8 c^2 + 2c + 3/8 = 0 (c = cos g), c in (-0.824, -0.243):
  // a zone covering (c1 - c0)/2 = 29% of the sphere.
  const double c0 = (-2 - std::sqrt(4 - 4 * 1.875 * 0.375)) / 3.75, c1 = (-2 + std::sqrt(4 - 4 * 1.875 * 0.375)) / 3.75;
  EXPECT_NEAR(report.negative_fraction, (c1 - c0) / 2, 0.01);
}

TEST(Preview, ReferenceIsBlackFacingAwayAndTheColourBarSpansTheError) {
  const ScratchDir dir;
  const ShJsonContent content = directional_document(dir);
  write_cap_map(dir / "cap.exr");
  PreviewSettings settings;
  settings.size = 64;
  settings.reference = dir / "cap.exr";
  settings.reference_label = "cap.exr";
  Rgb8Image image;
  PreviewReport report;
  ASSERT_TRUE(render_preview(content, settings, image, report).ok());
  ASSERT_TRUE(report.has_reference);
  // Normals below the horizon see none of the cap: the brute-force E/pi is exactly 0.
  for (std::uint32_t y = report.reference.height / 2 + 2; y < report.reference.height; ++y)
    for (std::uint32_t x = 0; x < report.reference.width; ++x)
      ASSERT_EQ(pixel(image, report.reference.x + x, report.reference.y + y), (Rgb{0, 0, 0})) << x << "," << y;
  // Top row: lit.
  EXPECT_GT(pixel(image, report.reference.x, report.reference.y)[0], 100);

  const PanelRect& bar = report.colour_bar;
  EXPECT_EQ(pixel(image, bar.x, bar.y + bar.height / 2), (Rgb{0, 0, 255}));  // -error_scale: blue
  EXPECT_EQ(pixel(image, bar.x + bar.width - 1, bar.y + bar.height / 2), (Rgb{255, 0, 0}));  // +: red
  const Rgb middle = pixel(image, bar.x + bar.width / 2, bar.y);
  for (int c = 0; c < 3; ++c) EXPECT_GE(middle[c], 250);  // 0: white
  EXPECT_GT(report.error_scale, 0.0);
  EXPECT_EQ(report.error_scale, report.max_abs_error);
  // The labels under the bar's ends are drawn (text pixels in the label band).
  const auto has_text = [&](std::uint32_t x0, std::uint32_t x1) {
    for (std::uint32_t y = bar.y + bar.height; y < image.height; ++y)
      for (std::uint32_t x = x0; x < x1; ++x)
        if (pixel(image, x, y) == (Rgb{225, 225, 225})) return true;
    return false;
  };
  EXPECT_TRUE(has_text(bar.x, bar.x + 20));
  EXPECT_TRUE(has_text(bar.x + bar.width - 20, bar.x + bar.width));
  // The error panel's extreme pixel is at a bar end colour.
  bool saturated = false;
  for (std::uint32_t y = 0; y < report.error.height; ++y)
    for (std::uint32_t x = 0; x < report.error.width; ++x) {
      const Rgb p = pixel(image, report.error.x + x, report.error.y + y);
      saturated = saturated || p == (Rgb{0, 0, 255}) || p == (Rgb{255, 0, 0});
    }
  EXPECT_TRUE(saturated);
}

// For a map whose SH is exact (uniform radiance: E/pi = R, nothing truncated), the whole
// difference is the reference's, which must stay within its stated bound.
TEST(Preview, ReferenceErrorStaysWithinItsBound) {
  const ScratchDir dir;
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "grey.exr", 64, 32, {0.5f, 1.0f, 2.0f}));
  ASSERT_EQ(run_shpack(dir, {"convert", (dir / "grey.exr").string(), "-o", (dir / "grey.json").string()}).exit_code, 0);
  ShJsonContent content;
  ASSERT_TRUE(read_sh_json(dir / "grey.json", content).ok());
  PreviewSettings settings;
  settings.size = 32;
  settings.reference = dir / "grey.exr";
  Rgb8Image image;
  PreviewReport report;
  ASSERT_TRUE(render_preview(content, settings, image, report).ok());
  const double bound = report.reference_bound_luminance;
  for (int c = 0; c < 3; ++c) EXPECT_GT(report.reference_bound[c], 0.0);  // cells cut by the terminator
  // ShadeSH9 in float adds a few u of the mean (u = 2^-24).
  EXPECT_LE(report.max_abs_error, bound + 1e-6 * report.mean_luminance);
  // The bound itself (view_reference.h): a cell the horizon cuts adds at most P r / pi, P its
  // flux L Omega and r its radius (pi/(2H) + pi/W here: 0.098, the map's texels being its
  // cells); the cut cells lie within 2r of the horizon, a band of at most 8 pi r of the
  // sphere, so the bound is at most 8 r^2 of L: 7.7 % of the mean.
  const double r = kPi / (2 * 32) + kPi / 64;
  EXPECT_LT(bound, 8 * r * r * report.mean_luminance);
}

// The reference turns with the document's --rotate: a map brighter towards +X, converted
// with a 90 degree turn, still matches its SH (L = 1 + x is nearly band-limited).
TEST(Preview, ReferenceFollowsTheDocumentsRotation) {
  const ScratchDir dir;
  const int w = 128, h = 64;
  std::vector<float> pixels;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double t = kPi * (y + 0.5) / h, lon = (0.5 - (x + 0.5) / w) * 2 * kPi;
      const auto v = static_cast<float>(1 + std::sin(t) * std::cos(lon));
      pixels.insert(pixels.end(), {v, v, v});
    }
  ASSERT_TRUE(shpack_io_test::write_image(dir / "x.exr", w, h, 3, pixels));
  ASSERT_EQ(run_shpack(dir, {"convert", (dir / "x.exr").string(), "--rotate", "90", "-o", (dir / "x.json").string()})
                .exit_code,
            0);
  ShJsonContent content;
  ASSERT_TRUE(read_sh_json(dir / "x.json", content).ok());
  ASSERT_EQ(content.rotate_deg, 90.0);
  PreviewSettings settings;
  settings.size = 32;
  settings.reference = dir / "x.exr";
  Rgb8Image image;
  PreviewReport report;
  ASSERT_TRUE(render_preview(content, settings, image, report).ok());
  // Unturned, the two would differ by up to (2/3) sqrt(2) = 0.94 (E/pi = 1 + (2/3) x).
  EXPECT_LT(report.max_abs_error, 0.01);
}

TEST(Preview, CommandWritesThePngItRendersAndStatesTheNumbers) {
  const ScratchDir dir;
  const std::string map = shpack_io_test::hdri("studio.exr").string();
  ASSERT_EQ(run_shpack(dir, {"convert", map, "-o", (dir / "s.json").string()}).exit_code, 0);
  const shpack_io_test::CliRun run =
      run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "s.png").string(), "--input", map, "--size", "48"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_NE(run.out.find("reference: exact E/pi of the map's texels, error <= "), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("sh - reference (luminance): max |error| "), std::string::npos) << run.out;

  ShJsonContent content;
  ASSERT_TRUE(read_sh_json(dir / "s.json", content).ok());
  PreviewSettings settings;
  settings.size = 48;
  settings.reference = map;
  settings.reference_label = "studio.exr";
  Rgb8Image want;
  PreviewReport report;
  ASSERT_TRUE(render_preview(content, settings, want, report).ok());
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open((dir / "s.png").string());
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().width, static_cast<int>(want.width));
  ASSERT_EQ(in->spec().height, static_cast<int>(want.height));
  ASSERT_EQ(in->spec().nchannels, 3);
  std::vector<std::uint8_t> got(want.pixels.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, got.data()));
  EXPECT_TRUE(got == want.pixels);
}

TEST(Preview, CommandErrorsNameTheFileAndKeepTheOutput) {
  const ScratchDir dir;
  const std::string map = shpack_io_test::hdri("studio.exr").string();
  ASSERT_EQ(run_shpack(dir, {"convert", map, "-o", (dir / "s.json").string()}).exit_code, 0);
  ASSERT_EQ(run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "p.png").string()}).exit_code, 0);
  const std::vector<char> good = shpack_io_test::read_bytes(dir / "p.png");

  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "square.exr", 8, 8, {1.0f, 1.0f, 1.0f}));
  shpack_io_test::CliRun run = run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "p.png").string(),
                                                "--input", (dir / "square.exr").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "square.exr").string() +
                         ": the layout of a 8x8 image is ambiguous: it fits octahedral, angular and mirrorball\n");
  // Any layout convert reads, named as convert names it.
  run = run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "octahedral.png").string(), "--input",
                         (dir / "square.exr").string(), "--input-layout", "octahedral"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  run = run_shpack(dir, {"preview", (dir / "missing.json").string(), "-o", (dir / "p.png").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "missing.json").string() + ": no such file\n");
  EXPECT_EQ(shpack_io_test::read_bytes(dir / "p.png"), good);

  run = run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "p.jpg").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
  EXPECT_EQ(run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "q.png").string(), "--size", "8"}).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir / "p.jpg"));
  EXPECT_FALSE(fs::exists(dir / "q.png"));
}

}  // namespace
// A document with lights taken out: what Unity shows is the SH plus each light's Lambert term
// (view_error.h), so the preview adds them to every panel and to the mean its tone mapping
// and percentages use. The same map with its sun taken out then shows the same total light:
// the sun's Unity irradiance E_c = d . m_c is its removed flux within a factor cos a
// (light_extraction.h, a <= 5 degrees: 0.4 %), and a light's mean over the sphere is E/(4 pi).
TEST(Preview, ExtractedLightsAreWhatUnityShowsAndAreMarked) {
  const ScratchDir dir;
  const std::string map = shpack_io_test::hdri("sunrise.exr");
  ASSERT_EQ(run_shpack(dir, {"convert", map, "-o", (dir / "plain.json").string()}).exit_code, 0);
  ASSERT_EQ(run_shpack(dir, {"convert", map, "--extract-sun", "-o", (dir / "sun.json").string()}).exit_code, 0);
  ShJsonContent plain, sun;
  ASSERT_TRUE(read_sh_json(dir / "plain.json", plain).ok());
  ASSERT_TRUE(read_sh_json(dir / "sun.json", sun).ok());
  EXPECT_TRUE(plain.lights.empty());
  ASSERT_EQ(sun.lights.size(), 1u);
  PreviewSettings settings;
  settings.size = 32;
  settings.reference = map;
  Rgb8Image image;
  PreviewReport with_plain, with_sun;
  ASSERT_TRUE(render_preview(plain, settings, image, with_plain).ok());
  ASSERT_TRUE(render_preview(sun, settings, image, with_sun).ok());
  EXPECT_NEAR(with_sun.mean_luminance, with_plain.mean_luminance, 0.005 * with_plain.mean_luminance);
  // The convert document's view error: 24.7 % plain, 4.7 % with the sun (docs/accuracy.md);
  // the preview's luminance error over its pixels tells the same story.
  EXPECT_LT(with_sun.max_abs_error, 0.5 * with_plain.max_abs_error);
  // The light's ring, cyan, on the E/pi panel around the sun's direction.
  std::size_t cyan = 0;
  for (std::uint32_t y = 0; y < with_sun.sh.height; ++y)
    for (std::uint32_t x = 0; x < with_sun.sh.width; ++x)
      if (pixel(image, with_sun.sh.x + x, with_sun.sh.y + y) == Rgb{0, 255, 255}) ++cyan;
  EXPECT_GT(cyan, 8u);
  // The input as stored, a 2:1 map fitted into 2S x S: all of it.
  EXPECT_EQ(with_sun.input.width, 2 * settings.size);
  EXPECT_EQ(with_sun.input.height, settings.size);
  EXPECT_EQ(with_sun.input.y + with_sun.input.height + 2, image.height);
}

TEST(Preview, ABakeDocumentsProbeAndAWrongInputAreSaid) {
  const ScratchDir dir;
  const std::string map = shpack_io_test::hdri("sunset.exr");
  std::string scene = R"({"probes": [[0, 1, 0], [1, 1, -1]], "environment": {"type": "map", "path": ")";
  scene.append(map).append(R"("}, "effects": ["environment"]})");
  shpack_io_test::write_bytes(dir / "scene.json", std::vector<char>(scene.begin(), scene.end()));
  ASSERT_EQ(run_shpack(dir, {"bake", (dir / "scene.json").string(), "-o", (dir / "bake.json").string()}).exit_code, 0);
  const std::string png = (dir / "p.png").string();
  shpack_io_test::CliRun run = run_shpack(dir, {"preview", (dir / "bake.json").string(), "-o", png});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("a bake document of 2 probes: choose one (preview --probe N)"), std::string::npos) << run.err;
  run = run_shpack(dir, {"preview", (dir / "bake.json").string(), "-o", png, "--probe", "1"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  run = run_shpack(dir, {"preview", (dir / "bake.json").string(), "-o", png, "--probe", "2"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("no probe 2 (it has 2)"), std::string::npos) << run.err;
  // A probe's coefficients are those the bake document holds for it.
  ShJsonContent probe;
  ASSERT_TRUE(read_sh_json(dir / "bake.json", probe, 1).ok());
  const nlohmann::json doc = nlohmann::json::parse(shpack_io_test::text_of(dir / "bake.json"));
  EXPECT_EQ(probe.shader.SHAr[3], doc["probes"][1]["shader"]["unity_SHAr"][3].get<float>());
  // --input that is not the document's source: a warning, and the image is still made.
  ASSERT_EQ(run_shpack(dir, {"convert", map, "-o", (dir / "s.json").string()}).exit_code, 0);
  run = run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", png, "--input",
                         shpack_io_test::hdri("city.exr").string()});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("is not the file the document was made from"), std::string::npos) << run.err;
}

// The labels: DejaVu Sans when Debian's font is installed (install-deps installs it), a
// tenth of the spheres' size high, 11 pixels at least; the panels move down with them.
TEST(Preview, TextIsATrueTypeFontThatScalesWithTheSize) {
  ShJsonContent content;
  content.unity_sh[0][0] = content.unity_sh[1][0] = content.unity_sh[2][0] = 0.5f;
  content.shader.SHAr[3] = content.shader.SHAg[3] = content.shader.SHAb[3] = 0.5f;
  PreviewSettings settings;
  Rgb8Image image;
  PreviewReport small, large;
  settings.size = 64;
  ASSERT_TRUE(render_preview(content, settings, image, small).ok());
  settings.size = 512;
  ASSERT_TRUE(render_preview(content, settings, image, large).ok());
  const bool font = std::filesystem::is_regular_file("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
  EXPECT_EQ(small.truetype_text, font);
  if (font) {
    EXPECT_EQ(small.front.y, 11u + 4u);  // the line, and its spacing
    EXPECT_EQ(large.front.y, 512u / 10 + 4u);
  }
}

}  // namespace shpack::io
