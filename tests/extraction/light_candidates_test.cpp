// The compact bright sources of an equirect map as candidate lights (light_candidates.h): maps
// of 0 to 3 discs of different sizes and colours over a smooth sky give back each disc, its
// texels, direction, irradiance and the SH of its removal within tolerances derived below;
// discs across the seam and over a pole are found whole, with a bright texel near one; an
// overcast sky, a bright hemisphere, a bright wall, a region wider than the largest radius, a
// patch not far brighter than its surroundings and a source carrying too little of the map's
// flux give none.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

#include "extraction/disc_map.h"
#include "shpack/image_view.h"
#include "shpack/light_candidates.h"
#include "shpack/sh_basis.h"
#include "support/equirect_oracle.h"
#include "support/test_util.h"

namespace shpack {
namespace {

using shpack_test::angle_deg;
using shpack_test::Disc;
using shpack_test::DiscMap;
using shpack_test::DrawnDisc;
using shpack_test::from_angles;
using shpack_test::kDiscDeg;
using shpack_test::kU;
using shpack_test::RgbImage;

constexpr double kPi = std::numbers::pi;
constexpr std::uint32_t kW = 1024, kH = 512;  // a texel is 0.35 degrees
// The largest texel diagonal of the map, hypot(pi/H, 2 pi/W) (at the equator): 0.50 degrees.
const double kDiagonal = std::hypot(kPi / kH, 2 * kPi / kW);
// The map holds the sky rounded to float, each texel within 2^-24 relative of the sky function
// (values below 1): the texels' spread exceeds the function's (DrawnDisc::spread) by at most
// 2 x 2^-24.
constexpr double kFloatSky = 2 * 0x1p-24;

// A sun (0.8 degrees), a warm lamp (3 degrees) and a cool softbox (9 degrees), in decreasing
// order of luminance, well apart.
const std::vector<Disc> kDiscs = {
    {from_angles(35, 60), 0.8, {20000, 18000, 15000}},
    {from_angles(5, -70), 3.0, {600, 400, 200}},
    {from_angles(20, 170), 9.0, {60, 70, 90}},
};

std::vector<LightCandidate> find(const RgbImage& image, std::size_t max_candidates = kLightCandidateCount) {
  std::vector<LightCandidate> candidates;
  const Status st = find_light_candidates(image.view(), {}, max_candidates, candidates);
  EXPECT_TRUE(st.ok()) << shpack_test::describe(st);
  return candidates;
}

std::vector<std::size_t> all_of(const std::vector<LightCandidate>& candidates) {
  std::vector<std::size_t> k(candidates.size());
  std::iota(k.begin(), k.end(), std::size_t{0});
  return k;
}

// The candidate is the drawn disc: its texels, and its light within the tolerances below.
void expect_disc(const LightCandidate& got, const DrawnDisc& want, const Disc& disc) {
  EXPECT_EQ(got.texels, want.texels);
  EXPECT_EQ(got.light.texels, want.texels.size());
  // The same exact texel solid angles summed, in closed form and by the oracle's quadrature:
  // each within a few u relative, so the sums within 1e-13 relative.
  EXPECT_NEAR(got.light.solid_angle, want.solid_angle, 1e-13 * want.solid_angle);
  // The radius: texel centres reach from R - diagonal to R from the disc's centre, the region's
  // centre is within half a diagonal of it (the centroid of a disc of whole texels) and the
  // padding adds half a diagonal.
  EXPECT_GE(got.light.radius_deg, disc.radius_deg - kDiagonal / kDiscDeg);
  EXPECT_LE(got.light.radius_deg, disc.radius_deg + 1.5 * kDiagonal / kDiscDeg);

  // The fill level is a mean of sky texels of the ring: within the spread of the sky at the disc.
  const std::array<double, 3> sky_at_disc = shpack_test::smooth_sky(disc.centre);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(got.light.sky[c], sky_at_disc[c], want.spread[c] + kFloatSky) << "c=" << c;

  // What is removed differs from the drawn excess only by the fill level against the sky under
  // each texel, by at most delta_c = spread_c + kFloatSky per texel, so each flux vector by at
  // most delta_c Omega (|sum_t delta_t int_t w| <= sum_t |delta_t| Omega_t). A vector m moved by
  // at most |dm| < |m| turns by at most asin(|dm| / |m|).
  std::array<double, 3> delta;
  for (int c = 0; c < 3; ++c) delta[c] = (want.spread[c] + kFloatSky) * want.solid_angle;
  Dir3 m{};
  for (int c = 0; c < 3; ++c)
    m = {m.x + shpack_test::kDiscLuminance[c] * want.flux[c].x, m.y + shpack_test::kDiscLuminance[c] * want.flux[c].y,
         m.z + shpack_test::kDiscLuminance[c] * want.flux[c].z};
  const double turn = std::asin(std::min(1.0, shpack_test::luminance(delta) / std::sqrt(shpack_test::dot3(m, m))));
  EXPECT_LE(angle_deg(got.light.direction, want.direction), turn / kDiscDeg + 1e-9);

  for (int c = 0; c < 3; ++c) {
    // E_c = d . m_c against d* . m*_c: |d . (m_c - m*_c)| <= delta_c, |(d - d*) . m*_c| <=
    // turn |m*_c|; rounding of sums of a few thousand terms, 1e-12 relative.
    const double m_c = std::sqrt(shpack_test::dot3(want.flux[c], want.flux[c]));
    EXPECT_NEAR(got.light.irradiance[c], want.irradiance[c], delta[c] + turn * m_c + 1e-12 * m_c) << "c=" << c;
    // And against the flux (light_extraction.h): E_c = sum_t e_t,c (d . int_t w dw), each
    // d . int_t w dw between Omega_t cos a and Omega_t for a the largest angle from d to a point
    // of the disc's patches, a <= R + diagonal + angle(d, centre); the removed excess
    // sum_t e_t,c Omega_t is the drawn flux Phi_c within delta_c (all e_t > 0 here).
    const double a = (disc.radius_deg + angle_deg(got.light.direction, disc.centre)) * kDiscDeg + kDiagonal;
    EXPECT_GE(got.light.irradiance[c], (want.excess_flux[c] - delta[c]) * std::cos(a) * (1 - 1e-12)) << "c=" << c;
    EXPECT_LE(got.light.irradiance[c], (want.excess_flux[c] + delta[c]) * (1 + 1e-12)) << "c=" << c;
  }
}

// Removing the candidates changes exactly their texels, to their fill levels, and the oracle's
// projection of what changed (sum over the changed texels of the difference times the oracle's
// int_t Y_i) is each candidate's removed SH.
void expect_removal(const RgbImage& before, const std::vector<LightCandidate>& candidates) {
  RgbImage after = before;
  ASSERT_TRUE(remove_light_candidates(after.view(), after.rgb.data(), candidates, all_of(candidates)).ok());
  std::size_t in_candidates = 0;
  for (const LightCandidate& candidate : candidates) {
    std::array<std::array<long double, 9>, 3> want{};
    std::array<double, 3> scale{};  // sum_t |e_t,c| Omega_t
    for (const LightTexel& t : candidate.texels) {
      const std::array<double, 9> b = shpack_test::texel_basis_integral(t.x, t.y, kW, kH);
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(after.at(t.x, t.y, c), static_cast<float>(candidate.light.sky[c]));
        const double e = static_cast<double>(before.at(t.x, t.y, c)) - after.at(t.x, t.y, c);  // exact
        for (int i = 0; i < 9; ++i) want[c][i] += static_cast<long double>(e) * b[i];
        scale[c] += std::fabs(e) * b[0] / kY0;
      }
    }
    in_candidates += candidate.texels.size();
    // The removed SH is of e_t = L_t - L_ring, the pixels' change of L_t - float(L_ring): they
    // differ by at most 2^-24 L_ring per texel, times |int_t Y_i| <= Omega_t. Each texel
    // integral, shpack's closed form and the oracle's quadrature, is within 80 u Omega_t of
    // the exact one (each is a few roundings of terms below 3 Omega_t, times k_i <= 1.1, and
    // the texel's edges pi j / H are themselves rounded, by u pi j / H: at most 2 u H Omega_t
    // relative, 1.1e-13 for H = 512, near the south pole), and the compensated sum adds
    // 2u |sum|: 128 u sum_t |e_t| Omega_t + 2 u H sum_t |e_t| Omega_t.
    for (int c = 0; c < 3; ++c) {
      const double rounding = 0x1p-24 * std::fabs(candidate.light.sky[c]) * candidate.light.solid_angle;
      for (int i = 0; i < 9; ++i)
        EXPECT_NEAR(candidate.removed.c[c][i], static_cast<double>(want[c][i]),
                    (128 + 2.0 * kH) * kU * scale[c] + rounding)
            << "c=" << c << " i=" << i;
    }
  }
  std::size_t changed = 0;
  for (std::size_t k = 0; k < before.rgb.size(); k += 3)
    changed += std::memcmp(&before.rgb[k], &after.rgb[k], 3 * sizeof(float)) != 0;
  EXPECT_EQ(changed, in_candidates);  // and nothing else changed
}

TEST(LightCandidates, FindsEachOfZeroToThreeDiscsItsLightAndTheShOfItsRemoval) {
  for (std::size_t n = 0; n <= kDiscs.size(); ++n) {
    SCOPED_TRACE(testing::Message() << n << " discs");
    const std::vector<Disc> discs(kDiscs.begin(), kDiscs.begin() + static_cast<std::ptrdiff_t>(n));
    const DiscMap map = shpack_test::draw_discs(kW, kH, discs);
    const std::vector<LightCandidate> candidates = find(map.image);
    ASSERT_EQ(candidates.size(), n);
    for (std::size_t k = 0; k < n; ++k) {
      SCOPED_TRACE(testing::Message() << "disc " << k);
      expect_disc(candidates[k], map.discs[k], discs[k]);  // in decreasing order of luminance
    }
    expect_removal(map.image, candidates);
  }
}

TEST(LightCandidates, FindsDiscsAcrossTheSeamAndOverAPoleWhole) {
  const std::vector<Disc> discs = {
      {from_angles(10, 180), 3.0, {500, 500, 500}},     // lon 180: columns 0 and W-1
      {from_angles(88.8, 20), 2.0, {300, 250, 200}},    // over the north pole
      {from_angles(-89.6, -40), 0.8, {900, 800, 700}},  // a small one at the south pole
  };
  const DiscMap map = shpack_test::draw_discs(kW, kH, discs);
  const std::vector<LightCandidate> candidates = find(map.image);
  ASSERT_EQ(candidates.size(), 3u);
  // Found in decreasing order of luminance: the south pole's, the seam's, the north pole's.
  for (const auto& [k, disc] : {std::pair{0, 2}, std::pair{1, 0}, std::pair{2, 1}}) {
    SCOPED_TRACE(testing::Message() << "disc " << disc);
    expect_disc(candidates[k], map.discs[disc], discs[disc]);
  }
  expect_removal(map.image, candidates);
}

// A map whose texels are `f` at their centres.
RgbImage render(const shpack_test::Sky& f) { return shpack_test::draw_discs(kW, kH, {}, f).image; }

TEST(LightCandidates, OvercastSkyBrightHemisphereWallAndGlowGiveNone) {
  // Overcast: brighter upwards, a dim ground.
  EXPECT_TRUE(find(render([](const Dir3& d) {
                return d.y > 0 ? std::array<double, 3>{0.8 + 0.4 * d.y, 0.85 + 0.4 * d.y, 0.9 + 0.4 * d.y}
                               : std::array<double, 3>{0.3, 0.3, 0.3};
              })).empty());
  // A bright hemisphere over a dark one.
  EXPECT_TRUE(find(render([](const Dir3& d) {
                return d.y > 0 ? std::array<double, 3>{100, 100, 100} : std::array<double, 3>{1, 1, 1};
              })).empty());
  // A bright wall 60 x 40 degrees.
  EXPECT_TRUE(find(render([](const Dir3& d) {
                const double elevation = std::asin(d.y) / kDiscDeg, lon = std::atan2(d.z, d.x) / kDiscDeg;
                const bool wall = std::fabs(elevation) < 20 && std::fabs(lon) < 30;
                return wall ? std::array<double, 3>{50, 45, 40} : std::array<double, 3>{1, 1, 1};
              })).empty());
  // An overcast sky brightening towards a hidden sun: a glow tens of degrees wide.
  const Dir3 sun = from_angles(30, 0);
  EXPECT_TRUE(find(render([&](const Dir3& d) {
                const double glow = 1 + 20 * std::pow(std::max(0.0, shpack_test::dot3(d, sun)), 8);
                return std::array<double, 3>{glow, glow, glow};
              })).empty());
}

// A disc of `radius_deg` whose radiance falls off slightly from its centre, so that its seed
// is at its centre and its growth stays within twice the largest radius.
Disc peaked_disc(double radius_deg) { return {from_angles(10, 30), radius_deg, {50, 50, 50}}; }
RgbImage peaked_map(double radius_deg) {
  const Disc disc = peaked_disc(radius_deg);
  return render([&](const Dir3& d) {
    const double angle = angle_deg(d, disc.centre);
    if (angle > radius_deg) return shpack_test::smooth_sky(d);
    const double v = 50 * (1 + 0.01 * std::cos(angle * kDiscDeg));
    return std::array<double, 3>{v, v, v};
  });
}

TEST(LightCandidates, RefusesARegionWiderThanTheLargestRadius) {
  // Radius plus half a diagonal (0.25 degrees) against kLightMaxRadiusDeg = 12.
  static_assert(kLightMaxRadiusDeg == 12.0);
  const std::vector<LightCandidate> inside = find(peaked_map(11.0));
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_LE(inside[0].light.radius_deg, kLightMaxRadiusDeg);
  EXPECT_LT(angle_deg(inside[0].light.direction, peaked_disc(11.0).centre), 0.1);
  EXPECT_TRUE(find(peaked_map(12.5)).empty());
}

TEST(LightCandidates, RefusesAPatchNotFarBrighterThanItsRing) {
  // A 2 degree patch of 10 in a dark gap of 1 degree, then a ground of 1: the gap keeps the
  // region to the patch (0.01 < 5% of 10; the ground is beyond r + 0.5 = 2.75 degrees, so
  // step 4 takes none of it), but its ring lies on the ground, and 10 < 20 x 1.
  const Dir3 centre = from_angles(-20, 45);
  const RgbImage image = render([&](const Dir3& d) {
    const double angle = angle_deg(d, centre);
    const double v = angle <= 2 ? 10 : angle <= 3 ? 0.01 : 1;
    return std::array<double, 3>{v, v, v};
  });
  EXPECT_TRUE(find(image).empty());
}

TEST(LightCandidates, JoinsABrightTexelNearARegionThatIsNotConnectedToIt) {
  // A sun of 0.8 degrees centred on texel (x0, y0), and a flare: texel (x0 + 4, y0) alone,
  // 4 x 0.35 cos 35 = 1.15 degrees from it, with a sky texel between (x0 + 3 is 0.86 degrees
  // out, beyond the disc, and so are its diagonal neighbours). The sun's r is about
  // 0.8 + 0.25, so the flare is within r + 0.5 (step 4): one candidate holding both.
  const std::uint32_t x0 = 341, y0 = 156;
  const Dir3 sun = equirect_direction((x0 + 0.5) / kW, (y0 + 0.5) / kH);
  const Dir3 flare = equirect_direction((x0 + 4.5) / kW, (y0 + 0.5) / kH);
  const DiscMap map =
      shpack_test::draw_discs(kW, kH, {{sun, 0.8, {20000, 18000, 15000}}, {flare, 0.01, {5000, 4000, 3000}}});
  ASSERT_EQ(map.discs[1].texels, (std::vector<LightTexel>{{x0 + 4, y0}}));
  const std::vector<LightCandidate> candidates = find(map.image);
  ASSERT_EQ(candidates.size(), 1u);
  // The disc's texels and the flare, row-major: the flare follows the disc's texels of row y0.
  std::vector<LightTexel> both = map.discs[0].texels;
  const auto after_row = std::find_if(both.begin(), both.end(), [&](const LightTexel& t) { return t.y > y0; });
  both.insert(after_row, LightTexel{x0 + 4, y0});
  EXPECT_EQ(candidates[0].texels, both);
  expect_removal(map.image, candidates);
}

TEST(LightCandidates, DropsASourceCarryingTooLittleOfTheMapsFlux) {
  // Two one-texel lamps on the horizon, far brighter than the sky around them (step 6), one
  // ten times the other: the map's flux sum_t Y_t Omega_t puts kLightMinFluxShare between their
  // fluxes, so only the brighter one is a candidate (step 7).
  const std::uint32_t y = kH / 2;
  const Dir3 bright = equirect_direction(100.5 / kW, (y + 0.5) / kH);
  const Dir3 dim = equirect_direction(600.5 / kW, (y + 0.5) / kH);
  const DiscMap map = shpack_test::draw_discs(kW, kH, {{bright, 0.01, {300, 300, 300}}, {dim, 0.01, {30, 30, 30}}});
  double map_flux = 0;
  for (std::uint32_t row = 0; row < kH; ++row) {
    const double omega = shpack_test::patch_solid_angle(shpack_test::texel_patch(0, row, kW, kH));
    for (std::uint32_t x = 0; x < kW; ++x) {
      const std::array<double, 3> v = {map.image.at(x, row, 0), map.image.at(x, row, 1), map.image.at(x, row, 2)};
      map_flux += shpack_test::luminance(v) * omega;
    }
  }
  ASSERT_LT(shpack_test::luminance(map.discs[1].excess_flux), kLightMinFluxShare * map_flux);
  ASSERT_GT(shpack_test::luminance(map.discs[0].excess_flux), kLightMinFluxShare * map_flux);
  const std::vector<LightCandidate> candidates = find(map.image);
  ASSERT_EQ(candidates.size(), 1u);
  EXPECT_EQ(candidates[0].texels, map.discs[0].texels);
}

TEST(LightCandidates, StopsAtMaxCandidates) {
  const DiscMap map = shpack_test::draw_discs(kW, kH, kDiscs);
  const std::vector<LightCandidate> all = find(map.image);
  ASSERT_EQ(all.size(), 3u);
  const std::vector<LightCandidate> two = find(map.image, 2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0], all[0]);
  EXPECT_EQ(two[1], all[1]);
  EXPECT_TRUE(find(map.image, 0).empty());
}

TEST(LightCandidates, SameCandidatesTwiceThroughAnyViewAndWithNonFiniteTexels) {
  DiscMap map = shpack_test::draw_discs(kW, kH, kDiscs);
  const std::vector<LightCandidate> first = find(map.image);
  EXPECT_EQ(find(map.image), first);
  // The same texels as RGBA, bottom row first, read through a negative row stride.
  std::vector<float> rgba(std::size_t{4} * kW * kH, 0.25f);
  for (std::uint32_t y = 0; y < kH; ++y)
    for (std::uint32_t x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) rgba[(std::size_t{kH - 1 - y} * kW + x) * 4 + c] = map.image.at(x, y, c);
  ImageView flipped = make_view(rgba.data(), kW, kH, 4);
  flipped.data += std::int64_t{kH - 1} * kW * 16;
  flipped.row_stride = -std::int64_t{kW} * 16;
  std::vector<LightCandidate> through_view;
  ASSERT_TRUE(find_light_candidates(flipped, {}, kLightCandidateCount, through_view).ok());
  EXPECT_EQ(through_view, first);
  // An Inf and a NaN texel far from the discs are read as 0 (light_extraction.h's policy):
  // neither a seed nor in a ring. Only the mean of step 1 moves, and it stops no seed here.
  map.image.at(10, 400, 0) = std::numeric_limits<float>::infinity();
  map.image.at(11, 400, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(find(map.image), first);
}

TEST(LightCandidates, RefusesViewsItCannotReadOrWrite) {
  const DiscMap map = shpack_test::draw_discs(256, 128, {{from_angles(30, 0), 8.0, {100, 100, 100}}});
  std::vector<LightCandidate> candidates;
  ImageView half = map.image.view();
  half.type = PixelType::F16;
  EXPECT_EQ(find_light_candidates(half, {}, 4, candidates).code, Errc::InvalidArgument);
  ImageView empty = map.image.view();
  empty.data = nullptr;
  EXPECT_EQ(find_light_candidates(empty, {}, 4, candidates).code, Errc::BadView);
  ASSERT_TRUE(find_light_candidates(map.image.view(), {}, 4, candidates).ok());
  ASSERT_EQ(candidates.size(), 1u);

  RgbImage pixels = map.image;
  const std::vector<std::size_t> first = {0}, beyond = {1};
  EXPECT_EQ(remove_light_candidates(pixels.view(), nullptr, candidates, first).code, Errc::InvalidArgument);
  EXPECT_EQ(remove_light_candidates(pixels.view(), pixels.rgb.data(), candidates, beyond).code, Errc::InvalidArgument);
  std::vector<LightCandidate> outside = candidates;
  outside[0].texels.push_back({256, 0});
  EXPECT_EQ(remove_light_candidates(pixels.view(), pixels.rgb.data(), outside, first).code, Errc::InvalidArgument);
  EXPECT_EQ(pixels.rgb, map.image.rgb);  // nothing written by a call that failed
  EXPECT_TRUE(remove_light_candidates(pixels.view(), pixels.rgb.data(), candidates, {}).ok());
  EXPECT_EQ(pixels.rgb, map.image.rgb);
  EXPECT_TRUE(remove_light_candidates(pixels.view(), pixels.rgb.data(), candidates, first).ok());
  EXPECT_NE(pixels.rgb, map.image.rgb);
}

}  // namespace
}  // namespace shpack
