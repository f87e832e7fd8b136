// The sun of an equirect map as a light (light_extraction.h, through the pipeline's stages,
// pipeline.h): a sky with a synthetic sun disc gives back the disc's direction and
// irradiance and the SH of the sky alone, within tolerances derived below; a sky without a
// sun gives none; the Unity light's rotation and colour say what unity_light.h says.
// The command's --extract-sun is tested in tests/io/sun_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/document.h"
#include "shpack/image_view.h"
#include "shpack/light_extraction.h"
#include "shpack/pipeline.h"
#include "shpack/rotate.h"
#include "shpack/unity_light.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;
constexpr int kW = 1024, kH = 512;  // a texel is 0.35 degrees
constexpr std::array<double, 3> kSunRadiance = {20000, 18000, 15000};
constexpr double kSunRadiusDeg = 0.8;

double dot(const Dir3& a, const Dir3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double angle_deg(const Dir3& a, const Dir3& b) {
  return std::acos(std::clamp(dot(a, b) / std::sqrt(dot(a, a) * dot(b, b)), -1.0, 1.0)) / kDeg;
}
Dir3 from_angles(double elevation_deg, double lon_deg) {
  const double e = elevation_deg * kDeg, l = lon_deg * kDeg;
  return {std::cos(e) * std::cos(l), std::sin(e), std::cos(e) * std::sin(l)};
}

// A smooth sky: brighter and whiter upwards.
std::array<double, 3> sky(const Dir3& d) {
  const double up = std::max(0.0, d.y);
  return {0.2 + 0.3 * up, 0.3 + 0.3 * up, 0.5 + 0.3 * up};
}

struct SyntheticSky {
  std::vector<float> with_sun, without_sun;
  // What the test knows of the disc it drew: the flux vector of its excess over the sky
  // (exact texel integrals), hence the true direction and irradiance (light_extraction.h's
  // definitions), and the largest difference between the sky under the disc and anywhere
  // within 4 degrees.
  std::array<Dir3, 3> flux{};
  Dir3 direction;
  std::array<double, 3> irradiance{};
  double solid_angle = 0, sky_spread = 0;
};

// int over texel (x, y) of w dw, and its solid angle, in closed form.
void texel_integrals(int x, int y, Dir3& w, double& solid) {
  const double t0 = kPi * y / kH, t1 = kPi * (y + 1) / kH;
  const double p0 = (0.5 - (x + 1.0) / kW) * 2 * kPi, p1 = (0.5 - static_cast<double>(x) / kW) * 2 * kPi;
  const double sin2 = 0.5 * (t1 - t0) - 0.25 * (std::sin(2 * t1) - std::sin(2 * t0));
  const double sin_cos = 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0));
  w = {sin2 * (std::sin(p1) - std::sin(p0)), sin_cos * (p1 - p0), sin2 * (std::cos(p0) - std::cos(p1))};
  solid = (std::cos(t0) - std::cos(t1)) * (p1 - p0);
}

SyntheticSky make_sky(const Dir3& sun_centre) {
  SyntheticSky s;
  s.with_sun.resize(std::size_t{kW} * kH * 3);
  std::array<double, 3> low = {1e9, 1e9, 1e9}, high = {-1e9, -1e9, -1e9};
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const Dir3 d = equirect_direction((x + 0.5) / kW, (y + 0.5) / kH);
      const std::array<double, 3> v = sky(d);
      const bool in_sun = angle_deg(d, sun_centre) <= kSunRadiusDeg;
      for (int c = 0; c < 3; ++c) {
        s.with_sun[(static_cast<std::size_t>(y) * kW + x) * 3 + c] = static_cast<float>(in_sun ? kSunRadiance[c] : v[c]);
        if (angle_deg(d, sun_centre) <= 4) low[c] = std::min(low[c], v[c]), high[c] = std::max(high[c], v[c]);
      }
      if (!in_sun) continue;
      Dir3 w;
      double solid;
      texel_integrals(x, y, w, solid);
      s.solid_angle += solid;
      for (int c = 0; c < 3; ++c) {
        const double excess = kSunRadiance[c] - static_cast<float>(v[c]);
        s.flux[c] = {s.flux[c].x + excess * w.x, s.flux[c].y + excess * w.y, s.flux[c].z + excess * w.z};
      }
    }
  for (int c = 0; c < 3; ++c) s.sky_spread = std::max(s.sky_spread, high[c] - low[c]);
  s.without_sun.resize(s.with_sun.size());
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c)
        s.without_sun[(static_cast<std::size_t>(y) * kW + x) * 3 + c] =
            static_cast<float>(sky(equirect_direction((x + 0.5) / kW, (y + 0.5) / kH))[c]);
  const std::array<double, 3> lum = {0.2126729, 0.7151522, 0.0721750};
  Dir3 m{};
  for (int c = 0; c < 3; ++c) m = {m.x + lum[c] * s.flux[c].x, m.y + lum[c] * s.flux[c].y, m.z + lum[c] * s.flux[c].z};
  const double len = std::sqrt(dot(m, m));
  s.direction = {m.x / len, m.y / len, m.z / len};
  for (int c = 0; c < 3; ++c) s.irradiance[c] = dot(s.direction, s.flux[c]);
  return s;
}

// Stages 2 to 4 (convert_map) on a copy of `pixels` (the transform writes into it), and the
// document of the result (stage 5).
ShDocument convert(std::vector<float> pixels, const ConvertOptions& options) {
  MapImage map;
  map.layout = Layout::Equirect;
  map.image = make_view(pixels.data(), kW, kH, 3);
  map.writable = pixels.data();
  Conversion conversion;
  const Status st = convert_map(map, options, conversion);
  EXPECT_TRUE(st.ok()) << st.what;
  return make_document({}, {}, options, conversion);
}

// Converts both images of the sky with and without --extract-sun and checks the sun and the rest.
void check_extraction(const Dir3& sun_centre, double rotate_deg, const std::string& what) {
  SCOPED_TRACE(what);
  const SyntheticSky s = make_sky(sun_centre);
  ConvertOptions plain;
  plain.finish.rotate_deg = rotate_deg;
  plain.finish.intensity = 0.5;
  ConvertOptions extracting = plain;
  extracting.extract_sun = true;
  const ShDocument rest = convert(s.with_sun, extracting);
  const ShDocument sky_only = convert(s.without_sun, plain);
  const ShDocument no_sun = convert(s.without_sun, extracting);

  // No sun in the sky alone, and then the document is the plain conversion's.
  EXPECT_TRUE(no_sun.sun_extraction);
  EXPECT_FALSE(no_sun.sun.has_value());
  EXPECT_EQ(no_sun.sh.radiance, sky_only.sh.radiance);

  ASSERT_TRUE(rest.sun.has_value());
  const SunLight& sun = rest.sun->light;
  const Matrix3 r = rotation_about_y(rotate_deg);
  const Dir3 d = s.direction;
  const Dir3 want = {r[0][0] * d.x + r[0][1] * d.y + r[0][2] * d.z, r[1][0] * d.x + r[1][1] * d.y + r[1][2] * d.z,
                     r[2][0] * d.x + r[2][1] * d.y + r[2][2] * d.z};
  // The direction: the removed flux differs from the drawn one only by the sky estimate
  // (ring mean instead of the true sky under the disc, at most sky_spread per texel), which
  // turns the flux vector by at most spread / (sun radiance) radians: below 1e-4 degrees here.
  EXPECT_LT(angle_deg(sun.direction, want), 1e-4);
  EXPECT_LT(angle_deg(d, sun_centre), 0.1);  // and the drawn disc's centroid is its centre, to a third of a texel
  // The irradiance: the same sky estimate, at most sky_spread * solid angle per channel (times
  // the intensity 0.5), a few 1e-6 of E.
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(sun.irradiance[c], 0.5 * s.irradiance[c], 0.5 * s.sky_spread * s.solid_angle) << "c=" << c;
    EXPECT_GT(sun.irradiance[c], 0);
  }
  // The rest is the sky: the two images differ only on the disc, each texel by at most
  // sky_spread, so each coefficient by at most 0.5 * sky_spread * solid angle * max |Y|, where
  // a unit band-l function, rotated or not, is at most sqrt((2l + 1) / (4 pi)) <= 0.631 in
  // magnitude (addition theorem), plus rounding.
  const double tol = 0.5 * s.sky_spread * s.solid_angle * 0.631 + 1e-12;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i)
      EXPECT_NEAR(rest.sh.radiance.c[c][i], sky_only.sh.radiance.c[c][i], tol) << "c=" << c << " i=" << i;
  // And the sun's part is gone: without extraction it adds E Y_0 = 0.5 * E * 0.282 to L_00.
  const ShDocument whole = convert(s.with_sun, plain);
  EXPECT_GT(whole.sh.radiance.c[0][0] - rest.sh.radiance.c[0][0], 0.9 * 0.5 * s.irradiance[0] * 0.2820948);

  // The transform alone: extract_sun on the pixels gives the light in the map's frame,
  // unscaled (the same bounds without the intensity), and the pipeline's light is that one
  // finished (pipeline.h finish_light).
  std::vector<float> pixels = s.with_sun;
  ImageView view = make_view(pixels.data(), kW, kH, 3);
  ASSERT_TRUE(resolve_view(view).ok());  // extract_sun takes a resolved view
  std::optional<SunLight> found;
  ASSERT_TRUE(extract_sun(view, pixels.data(), {}, found).ok());
  ASSERT_TRUE(found.has_value());
  EXPECT_LT(angle_deg(found->direction, d), 1e-4);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(found->irradiance[c], s.irradiance[c], s.sky_spread * s.solid_angle) << "c=" << c;
  EXPECT_EQ(finish_light(*found, plain.finish).light, sun);
  std::vector<float> clear = s.without_sun;
  view = make_view(clear.data(), kW, kH, 3);
  ASSERT_TRUE(resolve_view(view).ok());
  ASSERT_TRUE(extract_sun(view, clear.data(), {}, found).ok());
  EXPECT_FALSE(found.has_value());
  EXPECT_EQ(clear, s.without_sun);  // no sun: the map is used whole
}

TEST(SunExtraction, FindsTheDiscItsIrradianceAndTheSkysSh) {
  check_extraction(from_angles(35, 60), 0, "elevation 35");
}

TEST(SunExtraction, WrapsAroundTheSeamAndOverThePole) {
  check_extraction(from_angles(10, 180), 0, "on the -X seam");  // lon 180: columns 0 and W-1
  check_extraction(from_angles(89.6, 20), 0, "at the pole");     // the disc crosses the top row
}

TEST(SunExtraction, TurnsAndScalesWithTheMap) { check_extraction(from_angles(20, -30), 90, "rotate 90"); }

TEST(SunExtraction, SetsTheGreyOfAGreyAndAlphaMapAndLeavesItsAlpha) {
  // Grey + alpha (image_view.h: 2 channels): the projector reads channel 0 only, so the sun's
  // texels get the sky level there and their alpha stays what it was.
  const Dir3 centre = from_angles(35, 60);
  std::vector<float> pixels(std::size_t{kW} * kH * 2);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const Dir3 d = equirect_direction((x + 0.5) / kW, (y + 0.5) / kH);
      const std::size_t i = (static_cast<std::size_t>(y) * kW + x) * 2;
      pixels[i] = angle_deg(d, centre) <= kSunRadiusDeg ? 20000.0f : static_cast<float>(sky(d)[1]);
      pixels[i + 1] = 0.5f;
    }
  ImageView view = make_view(pixels.data(), kW, kH, 2);
  ASSERT_TRUE(resolve_view(view).ok());
  std::optional<SunLight> sun;
  ASSERT_TRUE(extract_sun(view, pixels.data(), {}, sun).ok());
  ASSERT_TRUE(sun.has_value());
  std::size_t at_sky = 0;
  for (std::size_t i = 0; i < pixels.size(); i += 2) {
    EXPECT_EQ(pixels[i + 1], 0.5f) << "texel " << i / 2;
    at_sky += pixels[i] == static_cast<float>(sun->sky[0]);
  }
  EXPECT_GE(at_sky, sun->texels);
}

TEST(SunExtraction, UnityLightShinesAwayFromTheSunWithColourTimesIntensityEOverPi) {
  SunLight sun;
  sun.direction = from_angles(35, 60);
  sun.irradiance = {6.0, 4.5, 3.0};
  const UnitySunLight light = unity_sun_light(sun);
  EXPECT_NEAR(dot(light.forward, sun.direction), -1.0, 1e-15);
  // The quaternion turns +Z into forward: v' = v + 2 w (q x v) + 2 q x (q x v).
  const auto& q = light.quaternion;
  const Dir3 z = {0, 0, 1};
  const Dir3 t = {2 * (q[1] * z.z - q[2] * z.y), 2 * (q[2] * z.x - q[0] * z.z), 2 * (q[0] * z.y - q[1] * z.x)};
  const Dir3 v = {z.x + q[3] * t.x + (q[1] * t.z - q[2] * t.y), z.y + q[3] * t.y + (q[2] * t.x - q[0] * t.z),
                  z.z + q[3] * t.z + (q[0] * t.y - q[1] * t.x)};
  EXPECT_NEAR(v.x, light.forward.x, 1e-12);
  EXPECT_NEAR(v.y, light.forward.y, 1e-12);
  EXPECT_NEAR(v.z, light.forward.z, 1e-12);
  // Unity's Euler angles of that forward: pitch 35 degrees down, yaw from +Z towards +X.
  EXPECT_NEAR(light.euler_deg[0], 35.0, 1e-12);
  EXPECT_NEAR(light.euler_deg[1], std::atan2(light.forward.x, light.forward.z) / kDeg, 1e-12);
  EXPECT_EQ(light.euler_deg[2], 0.0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(light.colour[c] * light.intensity, sun.irradiance[c] / kPi, 1e-15);
  EXPECT_EQ(light.colour[0], 1.0);
  EXPECT_NEAR(light.colour_srgb[0], 1.0, 1e-15);
}

}  // namespace
}  // namespace shpack
