// --extract-lights through the pipeline (pipeline.h stage 2, extract_from_map): on maps of
// discs over a smooth sky (disc_map.h), the lights chosen each lower the max error of what
// Unity shows, start where the one before ended, stand for drawn discs, and leave a result
// whose own view error is the last light's; a map with no compact source gives no light and
// the plain conversion, bit for bit; the first choice is the same whatever the limit; the
// finish options take part in the measure; the options are checked before any pixel is read.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "extraction/disc_map.h"
#include "shpack/document.h"
#include "shpack/light_fit.h"
#include "shpack/pipeline.h"
#include "support/test_util.h"

namespace shpack {
namespace {

using shpack_test::Disc;
using shpack_test::from_angles;
using shpack_test::RgbImage;

constexpr std::uint32_t kW = 512, kH = 256;

// A sun, a warm lamp and a cool softbox, well apart (as light_candidates_test's, at half the
// resolution).
const std::vector<Disc> kDiscs = {
    {from_angles(35, 60), 1.0, {20000, 18000, 15000}},
    {from_angles(5, -70), 3.0, {600, 400, 200}},
    {from_angles(20, 170), 9.0, {60, 70, 90}},
};

// Stages 2 to 4 on a copy of the image (stage 2 writes into it).
Conversion convert(const RgbImage& image, const ConvertOptions& options) {
  std::vector<float> pixels = image.rgb;
  MapImage map;
  map.image = make_view(pixels.data(), image.width, image.height, 3);
  map.writable = pixels.data();
  Conversion out;
  const Status st = convert_map(map, options, out);
  EXPECT_TRUE(st.ok()) << shpack_test::describe(st);
  return out;
}

ConvertOptions lights(unsigned n) {
  ConvertOptions options;
  options.extract_lights = n;
  return options;
}


TEST(ExtractLights, EachLightChosenLowersTheErrorOfWhatUnityShows) {
  const shpack_test::DiscMap map = shpack_test::draw_discs(kW, kH, kDiscs);
  const Conversion plain = convert(map.image, {});
  const Conversion out = convert(map.image, lights(kMaxExtractedLights));
  ASSERT_TRUE(plain.view_error && out.view_error);
  ASSERT_GE(out.lights.size(), 1u);
  EXPECT_LE(out.lights.size(), out.light_candidates);
  // Each disc is one candidate at every scale: its radiance is constant and its edge sharp, so
  // every threshold finds the same region (light_candidates_test, at one scale).
  EXPECT_EQ(out.light_candidates, kDiscs.size() * kLightChoiceScales.size());
  // The first starts from the plain conversion's error at the fit directions: the measure of
  // no light is stage 4 on the same exact projection, and the plain conversion's reported max
  // is searched from those directions (view_error.h), so at least that.
  EXPECT_LE(out.lights[0].error_before_pct, plain.view_error->max_pct);
  double before = out.lights[0].error_before_pct;
  std::vector<bool> disc_taken(kDiscs.size(), false);
  for (const ExtractedLight& light : out.lights) {
    EXPECT_EQ(light.error_before_pct, before);
    EXPECT_LT(light.error_after_pct, light.error_before_pct);
    before = light.error_after_pct;
    // Each stands for one of the drawn discs: its source's centre within a texel (0.7 degrees)
    // of the disc's, and the light within its reach of that (light_fit.h). No disc twice: the
    // same region found at two scales shares its texels, and a light sharing a texel with a
    // chosen one is never tried.
    const SunLight& found = light.light.light;
    EXPECT_LE(found.offset_deg, light_reach_deg(found.radius_deg) + 1e-9);
    double nearest = 180;
    std::size_t which = 0;
    for (std::size_t k = 0; k < kDiscs.size(); ++k)
      if (const double a = shpack_test::angle_deg(light.light.light.direction, kDiscs[k].centre); a < nearest) nearest = a, which = k;
    EXPECT_LT(nearest, light_reach_deg(found.radius_deg) + 0.7);
    EXPECT_FALSE(disc_taken[which]) << which;
    disc_taken[which] = true;
  }
  // The result is what the last step measured, the same exact projection less the same SH,
  // with its max searched for from the directions the step measured at: at least that.
  EXPECT_GE(out.view_error->max_pct, before);
  EXPECT_LT(out.view_error->max_pct, plain.view_error->max_pct);
  EXPECT_TRUE(out.sh.radiance != plain.sh.radiance);  // the lights are out of the SH
}

TEST(ExtractLights, NoCompactSourceGivesNoLightAndThePlainResult) {
  const shpack_test::DiscMap map = shpack_test::draw_discs(kW, kH, {});
  const Conversion plain = convert(map.image, {});
  const Conversion out = convert(map.image, lights(4));
  EXPECT_TRUE(out.lights.empty());
  EXPECT_EQ(out.light_candidates, 0u);
  EXPECT_EQ(out.sh.radiance, plain.sh.radiance);
  EXPECT_EQ(out.view_error, plain.view_error);
}

TEST(ExtractLights, TheFirstChoiceIsTheSameWhateverTheLimit) {
  const shpack_test::DiscMap map = shpack_test::draw_discs(kW, kH, kDiscs);
  const Conversion one = convert(map.image, lights(1));
  const Conversion many = convert(map.image, lights(kMaxExtractedLights));
  ASSERT_EQ(one.lights.size(), 1u);
  ASSERT_GE(many.lights.size(), 1u);
  // The same source first (later steps may move its light and refit its colour).
  EXPECT_EQ(one.lights[0].light.light.texels, many.lights[0].light.light.texels);
  EXPECT_EQ(one.lights[0].light.light.radius_deg, many.lights[0].light.light.radius_deg);
  EXPECT_EQ(one.lights[0].error_after_pct, many.lights[0].error_after_pct);
  EXPECT_GE(one.view_error->max_pct, one.lights[0].error_after_pct);  // searched from the step's directions
}

TEST(ExtractLights, TheFinishOptionsAreInTheMeasure) {
  // Rotation, intensity and the optimal window change what Unity shows: the measure of no
  // light is still the plain conversion's error with the same options at the fit directions,
  // and the result's error the last light's there (both searched further: at least those).
  const shpack_test::DiscMap map = shpack_test::draw_discs(kW, kH, kDiscs);
  ConvertOptions plain_options;
  plain_options.finish.rotate_deg = 30;
  plain_options.finish.intensity = 2;
  plain_options.finish.window.kind = WindowKind::Optimal;
  ConvertOptions options = plain_options;
  options.extract_lights = 3;
  const Conversion plain = convert(map.image, plain_options);
  const Conversion out = convert(map.image, options);
  ASSERT_GE(out.lights.size(), 1u);
  EXPECT_LE(out.lights[0].error_before_pct, plain.view_error->max_pct);
  EXPECT_GE(out.view_error->max_pct, out.lights.back().error_after_pct);
  for (int c = 0; c < kChannelCount; ++c) EXPECT_GE(out.sh.min_e_over_pi[c].value, -1e-9);  // optimal: non-negative
}

TEST(ExtractLights, TheOptionsAreCheckedFirst) {
  ConvertOptions options = lights(kMaxExtractedLights + 1);
  EXPECT_EQ(check_convert_options(options, Layout::Equirect, CubeFrame::Unity).code, Errc::InvalidArgument);
  options = lights(2);
  EXPECT_TRUE(check_convert_options(options, Layout::Equirect, CubeFrame::Unity).ok());
  EXPECT_EQ(check_convert_options(options, Layout::HorizontalCross, CubeFrame::Unity).code, Errc::InvalidArgument);
  options.extract_sun = true;
  EXPECT_EQ(check_convert_options(options, Layout::Equirect, CubeFrame::Unity).code, Errc::InvalidArgument);
  EXPECT_TRUE(needs_transform(options));
  EXPECT_FALSE(streams_rows(lights(1), Layout::Equirect));
}

}  // namespace
}  // namespace shpack
