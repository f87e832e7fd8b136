// The light candidates (light_candidates.h) of the bundled real maps (data/hdri): what each
// map yields is printed, not asserted, since no map says what its lights are; what holds for
// any map is asserted: at most the candidates asked for, disjoint, each within the largest
// radius, each texel at least as bright as its fill level in luminance, and the removed SH's
// L00 equal to Y00 times the removed flux.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/light_candidates.h"
#include "shpack/sh_basis.h"
#include "support/exr_file.h"
#include "support/rgb_image.h"
#include "support/test_util.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::array<double, 3> kY = kRec709Luminance;

double luminance(const std::array<double, 3>& v) { return kY[0] * v[0] + kY[1] * v[1] + kY[2] * v[2]; }
std::array<double, 3> texel(const shpack_test::RgbImage& image, LightTexel t) {
  return {image.at(t.x, t.y, 0), image.at(t.x, t.y, 1), image.at(t.x, t.y, 2)};
}
double solid_angle(const shpack_test::RgbImage& image, std::uint32_t y) {
  return (std::cos(kPi * y / image.height) - std::cos(kPi * (y + 1) / image.height)) * 2 * kPi / image.width;
}

class RealMapCandidates : public testing::TestWithParam<std::string> {};

TEST_P(RealMapCandidates, AreDisjointCompactAndReported) {
  shpack_test::RgbImage image;
  std::string error;
  ASSERT_TRUE(shpack_test::read_exr_rgb(shpack_test::hdri_path(GetParam()), image, error)) << error;
  std::vector<LightCandidate> candidates;
  ASSERT_TRUE(find_light_candidates(image.view(), {}, kLightCandidateCount, candidates).ok());
  ASSERT_LE(candidates.size(), kLightCandidateCount);

  // The map's luminous flux sum_t Y_t Omega_t, the scale of each candidate's share.
  double map_flux = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) map_flux += luminance(texel(image, {x, y})) * solid_angle(image, y);

  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  std::printf("%-9s %zu candidate(s); share = removed flux / map flux (luminance)\n", GetParam().c_str(),
              candidates.size());
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const LightCandidate& c = candidates[k];
    EXPECT_LE(c.light.radius_deg, kLightMaxRadiusDeg);
    EXPECT_EQ(c.light.texels, c.texels.size());
    double removed = 0, scale = 0;  // sum_t Y(e_t) Omega_t and sum_t |Y(e_t)| Omega_t
    for (const LightTexel& t : c.texels) {
      EXPECT_TRUE(seen.insert({t.x, t.y}).second) << "texel " << t.x << "," << t.y << " in two candidates";
      const std::array<double, 3> v = texel(image, t);
      const double e = luminance(v) - luminance(c.light.sky);
      // Step 6 makes every region texel at least its ring's level (light_candidates.h); the
      // fill is that level rounded to float, 2^-24 relative.
      EXPECT_GE(e, -0x1p-23 * luminance(c.light.sky));
      removed += e * solid_angle(image, t.y);
      scale += std::fabs(e) * solid_angle(image, t.y);
    }
    // L00 = k0 sum_t e_t Omega_t (int_t Y_0 = k0 Omega_t): both sums of the same terms, 1e-12.
    const std::array<double, 3> l00 = {c.removed.c[0][0], c.removed.c[1][0], c.removed.c[2][0]};
    EXPECT_NEAR(luminance(l00), kY0 * removed, 1e-12 * kY0 * scale);
    const Dir3& d = c.light.direction;
    std::printf("  %2zu  elevation %6.2f  azimuth %7.2f  radius %6.2f deg  %6llu texels  peak Y %9.1f  "
                "fill Y %7.3f  E_Y %9.4f  share %6.2f%%\n",
                k, std::asin(d.y) * 180 / kPi, std::atan2(d.z, d.x) * 180 / kPi, c.light.radius_deg,
                static_cast<unsigned long long>(c.light.texels), c.peak, luminance(c.light.sky),
                luminance(c.light.irradiance), 100 * removed / map_flux);
  }
}

INSTANTIATE_TEST_SUITE_P(Hdri, RealMapCandidates,
                         testing::Values("city", "courtyard", "forest", "interior", "night", "studio", "sunrise",
                                         "sunset"));

}  // namespace
}  // namespace shpack
