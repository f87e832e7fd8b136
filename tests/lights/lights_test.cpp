// Tests of lights.h: every analytic light against brute-force integration of its radiance
// over the light itself (scene/light_oracle.h, independent basis), the limits that relate the
// lights to each other, and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "lights/light_oracle.h"
#include "shpack/lights.h"
#include "support/sh_oracle.h"
#include "support/sphere_points.h"
#include "support/test_util.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;
using shpack_test::kEps;
using shpack_test::OracleSh;

const Rgb kColour = {1.0, 0.5, 0.25};

// Largest |want - got| / scale over channels and coefficients, for the printed summaries;
// only cases where the oracle itself converged (its estimate below 1e-12 |L_0|) count, the
// others are only counted.
struct Worst {
  const char* name;
  double relative = 0;
  int uncertain = 0;
  ~Worst() {
    std::printf("[ measured ] %s: max |shpack - oracle| / |L_0| = %.3g (%d cases left out: oracle not converged)\n",
                name, relative, uncertain);
  }
};

// Compares got (one light added to zero) with colour * oracle.value. Tolerance: 8 times the
// oracle's own refinement estimate (geometric convergence: the fine rule's error is far
// below the coarse-fine difference) plus both sides' rounding (the oracle's bound; shpack's
// closed forms are a few dozen operations, 64 u relative to the largest term).
void expect_matches(const ShL2& got, const OracleSh& oracle, double extra_tol, Worst& worst,
                    const std::string& context) {
  const double tol = 8.0 * oracle.error + oracle.rounding + 64.0 * kEps * oracle.scale / kY0 + extra_tol;
  const bool converged = oracle.error <= 1e-12 * oracle.scale;
  worst.uncertain += converged ? 0 : 1;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) {
      const double want = kColour[c] * oracle.value[i];
      EXPECT_NEAR(got.c[c][i], want, kColour[c] * tol)
          << context << " c=" << c << " i=" << i << " oracle error " << oracle.error;
      if (c == 0 && oracle.scale > 0 && converged)
        worst.relative = std::max(worst.relative, std::fabs(got.c[c][i] - want) / oracle.scale);
    }
}

Rgb times(const Rgb& c, double s) { return {c[0] * s, c[1] * s, c[2] * s}; }

// ---- directional -------------------------------------------------------------------------

TEST(DirectionalLight, DeltaIsIrradianceTimesBasis) {
  for (const Dir3& d : shpack_test::fibonacci_sphere(40)) {
    ShL2 got;
    const Dir3 unnormalised{2 * d.x, 2 * d.y, 2 * d.z};  // the light normalises its direction
    ASSERT_TRUE(add_directional_light(unnormalised, 0.0, kColour, got).ok());
    const std::array<double, 9> y = shpack_test::unity_basis_slow(d.x, d.y, d.z);
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i)
        EXPECT_NEAR(got.c[c][i], kColour[c] * y[i], 16 * kEps) << "d=" << d << " c=" << c << " i=" << i;
  }
}

TEST(DirectionalLight, DiscMatchesBruteForceCap) {
  Worst worst{"directional with angular diameter (cap)"};
  for (const double diameter_deg : {0.53, 5.0, 30.0, 120.0, 179.0}) {
    const double a = 0.5 * diameter_deg * kPi / 180.0;
    for (const Dir3& d : shpack_test::fibonacci_sphere(6)) {
      ShL2 got;
      ASSERT_TRUE(add_directional_light(d, 2 * a, kColour, got).ok());
      // A cap of radiance E / (pi sin^2 a) has irradiance E at normal incidence.
      OracleSh oracle = shpack_test::cap_oracle(d, a, 2);
      const double radiance = 1.0 / (kPi * std::sin(a) * std::sin(a));
      for (double& v : oracle.value) v *= radiance;
      oracle.error *= radiance;
      oracle.rounding *= radiance;
      oracle.scale *= radiance;
      expect_matches(got, oracle, 0, worst, "diameter " + std::to_string(diameter_deg));
    }
  }
}

TEST(DirectionalLight, SmallDiscTendsToTheDeltaWithoutABranch) {
  // g_0 - 1 = tan^2(a/2), g_2 - 1 = -2 sin^2(a/2): both O(a^2); at a = 1e-9 rad they are
  // below rounding, and the coefficients equal the delta's to a few ulp.
  const Dir3 d{0.3, 0.8, -0.52};
  ShL2 delta, disc;
  ASSERT_TRUE(add_directional_light(d, 0.0, kColour, delta).ok());
  ASSERT_TRUE(add_directional_light(d, 2e-9, kColour, disc).ok());
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i)
      EXPECT_NEAR(disc.c[c][i], delta.c[c][i], 4 * kEps * std::fabs(delta.c[c][i])) << "c=" << c << " i=" << i;
}

// ---- cone --------------------------------------------------------------------------------

TEST(ConeLight, MatchesBruteForceCapUpToTheWholeSphere) {
  Worst worst{"cone"};
  for (const double a : {1e-3, 0.4, 1.5, 2.8, kPi}) {
    const Dir3 d{-0.2, 0.5, 0.84};
    ShL2 got;
    ASSERT_TRUE(add_cone_light(d, a, kColour, got).ok());
    expect_matches(got, shpack_test::cap_oracle(d, a, 2), 0, worst, "a=" + std::to_string(a));
  }
  ShL2 sphere;
  ASSERT_TRUE(add_cone_light({0, 1, 0}, kPi, {1, 1, 1}, sphere).ok());
  EXPECT_NEAR(sphere.c[0][0], 2 * std::sqrt(kPi), 8 * kEps) << "white furnace";
}

// ---- point and sphere --------------------------------------------------------------------

TEST(PointLight, EqualsDirectionalLightOfIrradianceIOverDSquared) {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  for (int k = 0; k < 50; ++k) {
    const Point3 light{coord(rng), coord(rng), coord(rng)}, probe{coord(rng), coord(rng), coord(rng)};
    const Dir3 d{light.x - probe.x, light.y - probe.y, light.z - probe.z};
    const double dist2 = d.x * d.x + d.y * d.y + d.z * d.z;
    ShL2 point, directional;
    ASSERT_TRUE(add_point_light(light, kColour, probe, point).ok());
    ASSERT_TRUE(add_directional_light(d, 0.0, times(kColour, 1.0 / dist2), directional).ok());
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i)
        EXPECT_NEAR(point.c[c][i], directional.c[c][i], 8 * kEps * std::fabs(directional.c[c][0]) / kY0)
            << "k=" << k << " c=" << c << " i=" << i;
  }
}

TEST(SphereLight, MatchesBruteForceOverItsVisibleSurface) {
  Worst worst{"sphere (integrated over its visible surface)"};
  const Point3 centre{1.0, 2.0, -0.5};
  for (const double radius : {0.01, 0.3, 1.0}) {
    for (const double distance_over_radius : {1.01, 1.5, 4.0, 100.0}) {
      const Dir3 dir{0.48, -0.6, 0.64};
      const double r = radius * distance_over_radius;
      const Point3 probe{centre.x - r * dir.x, centre.y - r * dir.y, centre.z - r * dir.z};
      const double intensity = 3.0;  // radiance I / (pi R^2)
      ShL2 got;
      ASSERT_TRUE(add_sphere_light(centre, radius, times(kColour, intensity), probe, got).ok());
      OracleSh oracle = shpack_test::sphere_surface_oracle(centre, radius, probe, 4);
      const double radiance = intensity / (kPi * radius * radius);
      for (double& v : oracle.value) v *= radiance;
      oracle.error *= radiance;
      oracle.rounding *= radiance;
      oracle.scale *= radiance;
      expect_matches(got, oracle, 0, worst,
                     "R=" + std::to_string(radius) + " r/R=" + std::to_string(distance_over_radius));
    }
  }
}

TEST(SphereLight, TendsToThePointLightAsTheRadiusShrinks) {
  // |g_0 - 1| = (1 - cos a)/(1 + cos a) <= sin^2 a and |g_2 - 1| = 1 - cos a <= sin^2 a, with
  // sin a = R/r: |sphere_i - point_i| <= (I/r^2) |Y_i(d)| (R/r)^2; and it is O(R^2): halving
  // R quarters the difference (to 1%, the next term being O(R^4)).
  const Point3 centre{0, 3, 4}, probe{0, 0, 0};
  const double r = 5.0;
  ShL2 point;
  ASSERT_TRUE(add_point_light(centre, kColour, probe, point).ok());
  double previous = 0;
  for (const double radius : {0.4, 0.2, 0.1, 0.05}) {
    ShL2 sphere;
    ASSERT_TRUE(add_sphere_light(centre, radius, kColour, probe, sphere).ok());
    double diff = 0;
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) {
        const double bound = std::fabs(point.c[c][i]) * (radius / r) * (radius / r) + 8 * kEps * point.c[c][0];
        EXPECT_LE(std::fabs(sphere.c[c][i] - point.c[c][i]), bound) << "R=" << radius << " c=" << c << " i=" << i;
        diff = std::max(diff, std::fabs(sphere.c[c][i] - point.c[c][i]));
      }
    if (previous > 0) {
      EXPECT_NEAR(previous / diff, 4.0, 0.04) << "R=" << radius;
    }
    previous = diff;
  }
  ShL2 zero_radius;
  ASSERT_TRUE(add_sphere_light(centre, 0.0, kColour, probe, zero_radius).ok());
  EXPECT_EQ(zero_radius, point) << "R = 0 is the point light";
}

// ---- spot --------------------------------------------------------------------------------

TEST(SpotLight, IsThePointLightTimesTheKhrFalloff) {
  const SpotLight spot{{0, 4, 0}, {0, -1, 0}, 0.3, 0.7};
  for (const double t : {0.0, 0.2, 0.3, 0.31, 0.45, 0.6, 0.69, 0.7, 0.71, 1.5, 3.0}) {
    // Probe at angle t from the axis, 4 m from the light.
    const Point3 probe{4 * std::sin(t), 4 - 4 * std::cos(t), 0};
    // KHR_lights_punctual's reference: scale = 1/(cos inner - cos outer), offset = -cos outer * scale,
    // attenuation = saturate(cd * scale + offset)^2.
    const double scale = 1.0 / (std::cos(0.3) - std::cos(0.7)), offset = -std::cos(0.7) * scale;
    const double att = std::pow(std::clamp(std::cos(t) * scale + offset, 0.0, 1.0), 2);
    ShL2 got, point;
    ASSERT_TRUE(add_spot_light(spot, kColour, probe, got).ok());
    ASSERT_TRUE(add_point_light(spot.position, times(kColour, att), probe, point).ok());
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i)
        EXPECT_NEAR(got.c[c][i], point.c[c][i], 64 * kEps * kColour[c] / 16) << "t=" << t << " c=" << c << " i=" << i;
  }
  // A hard edge: inner == outer.
  const SpotLight hard{{0, 4, 0}, {0, -1, 0}, 0.5, 0.5};
  EXPECT_EQ(spot_falloff(hard, std::cos(0.49)), 1.0);
  EXPECT_EQ(spot_falloff(hard, std::cos(0.51)), 0.0);
}

// ---- rect --------------------------------------------------------------------------------

struct AreaCase {
  Point3 probe;
  const char* what;
};

TEST(RectLight, MatchesBruteForceAreaIntegral) {
  Worst worst{"rect (closed form)"};
  // A tilted 2 x 1 rectangle; probes on the axis, off to the side, grazing, close, far.
  const double c45 = std::sqrt(0.5);
  const RectLight rect{{0.5, 2.0, 1.0}, {c45, 0, c45}, {0, 1, 0}, 2.0, 1.0};  // normal (-c45, 0, c45)
  const Point3 c = rect.centre;
  // s along the normal, plus an offset.
  const auto along = [&](double s, double ox, double oy, double oz) {
    return Point3{c.x - s * c45 + ox, c.y + oy, c.z + s * c45 + oz};
  };
  // In-plane offsets are multiples of the right vector (c45, 0, c45) and of up (0, 1, 0).
  const AreaCase cases[] = {{along(3.0, 0, 0, 0), "on axis, 3"},       {along(0.2, 0, 0, 0), "on axis, 0.2"},
                            {along(1.0, 1.5, 0.7, 1.5), "beside"},     {along(0.05, 0.5, 0.3, 0.5), "close"},
                            {along(0.02, 2.0, 0, 2.0), "grazing"},     {along(50.0, 5, -3, 5), "far"}};
  for (const AreaCase& k : cases) {
    ShL2 front;
    ASSERT_TRUE(add_rect_light(rect, kColour, k.probe, front).ok());
    ASSERT_GT(front.c[0][0], 0) << k.what << ": the probe must see the light's front";
  }
  for (const AreaCase& k : cases) {
    ShL2 got;
    ASSERT_TRUE(add_rect_light(rect, kColour, k.probe, got).ok());
    expect_matches(got, shpack_test::rect_oracle(rect, k.probe, 8), 0, worst, k.what);
  }
}

TEST(RectLight, IsOneSided) {
  const RectLight rect{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 1.0};  // emits along +Z
  ShL2 behind, in_plane, front;
  ASSERT_TRUE(add_rect_light(rect, kColour, {0.1, 0.2, -1.0}, behind).ok());
  ASSERT_TRUE(add_rect_light(rect, kColour, {3.0, 0.2, 0.0}, in_plane).ok());
  ASSERT_TRUE(add_rect_light(rect, kColour, {0.1, 0.2, 1.0}, front).ok());
  EXPECT_EQ(behind, ShL2{});
  EXPECT_EQ(in_plane, ShL2{});
  EXPECT_GT(front.c[0][0], 0);
  EXPECT_LT(front.c[0][2], 0) << "light arrives from -Z as the probe at +Z sees it";
}

// ---- disk --------------------------------------------------------------------------------

TEST(DiskLight, MatchesBruteForceAreaIntegral) {
  Worst worst{"disk (rim trapezoid rule)"};
  const DiskLight disk{{-1.0, 1.0, 2.0}, {0.36, -0.48, 0.8}, 0.75};
  const Point3 c = disk.centre;
  const auto at = [&](double h, double sx, double sy) {
    // h along the normal, plus an in-plane offset along two vectors orthogonal to it.
    const Dir3 a{0.8, 0.6, 0}, b{-0.48, 0.64, 0.6};
    return Point3{c.x + h * 0.36 + sx * a.x + sy * b.x, c.y - h * 0.48 + sx * a.y + sy * b.y,
                  c.z + h * 0.8 + sx * a.z + sy * b.z};
  };
  const AreaCase cases[] = {{at(2.0, 0, 0), "on axis"},      {at(0.1, 0, 0), "on axis, close"},
                            {at(1.0, 1.2, 0.4), "beside"},   {at(0.05, 0.7, 0.0), "close to the rim"},
                            {at(0.02, 2.0, 0.0), "grazing"}, {at(40.0, 3.0, 1.0), "far"}};
  int max_nodes = 0;
  double max_estimate = 0;
  for (const AreaCase& k : cases) {
    ShL2 got;
    DiskQuadrature q;
    ASSERT_TRUE(add_disk_light(disk, kColour, k.probe, got, &q).ok());
    const OracleSh oracle = shpack_test::disk_oracle(disk, k.probe, 8);
    // shpack's own estimate is relative to Omega; coefficients are k_i times moments.
    expect_matches(got, oracle, 1.1 * q.error_estimate * oracle.scale / kY0, worst,
                   std::string(k.what) + " nodes " + std::to_string(q.nodes_used));
    max_nodes = std::max(max_nodes, q.nodes_used);
    max_estimate = std::max(max_estimate, q.error_estimate);
  }
  std::printf("[ measured ] disk: up to %d rim nodes, largest self-estimate %.3g (relative to Omega)\n",
              max_nodes, max_estimate);
}

// ---- zonal about +Y ----------------------------------------------------------------------

TEST(ZonalLights, HemisphereGradientAndAmbientMatchBruteForce) {
  Worst worst{"hemisphere, gradient sky, ambient"};
  const Rgb sky = {2, 3, 4}, ground = {0.5, 0.25, 0.125};
  ShL2 hemi;
  ASSERT_TRUE(add_hemisphere_light(sky, ground, hemi).ok());
  for (int c = 0; c < kChannelCount; ++c) {
    const OracleSh o = shpack_test::zonal_y_oracle({sky[c], 0}, {ground[c], 0}, 2);
    for (int i = 0; i < kShCount; ++i)
      EXPECT_NEAR(hemi.c[c][i], o.value[i], 8 * o.error + o.rounding) << "hemisphere c=" << c << " i=" << i;
  }
  const Rgb zenith = {0.2, 0.4, 1.0}, horizon = {0.8, 0.9, 1.0};
  ShL2 gradient;
  ASSERT_TRUE(add_gradient_sky(zenith, horizon, ground, gradient).ok());
  for (int c = 0; c < kChannelCount; ++c) {
    const OracleSh o = shpack_test::zonal_y_oracle({horizon[c], zenith[c] - horizon[c]}, {ground[c], 0}, 2);
    for (int i = 0; i < kShCount; ++i) {
      EXPECT_NEAR(gradient.c[c][i], o.value[i], 8 * o.error + o.rounding) << "gradient c=" << c << " i=" << i;
      worst.relative = std::max(worst.relative, std::fabs(gradient.c[c][i] - o.value[i]) / o.scale);
    }
  }
  ShL2 ambient;
  ASSERT_TRUE(add_ambient_light(kColour, ambient).ok());
  for (int c = 0; c < kChannelCount; ++c) {
    EXPECT_NEAR(ambient.c[c][0], 2 * std::sqrt(kPi) * kColour[c], 4 * kEps) << "c=" << c;
    for (int i = 1; i < kShCount; ++i) EXPECT_EQ(ambient.c[c][i], 0.0) << "c=" << c << " i=" << i;
  }
}

// ---- errors ------------------------------------------------------------------------------

TEST(LightErrors, ProbeInsideAndBadParametersLeaveTheOutputUntouched) {
  ShL2 out;
  out.c[1][4] = 42;
  const ShL2 before = out;
  EXPECT_EQ(add_sphere_light({0, 0, 0}, 1.0, kColour, {0.5, 0, 0}, out).code, Errc::ProbeInsideLight);
  EXPECT_EQ(add_sphere_light({0, 0, 0}, 1.0, kColour, {1.0, 0, 0}, out).code, Errc::ProbeInsideLight)
      << "on the surface counts as inside";
  EXPECT_EQ(add_point_light({1, 2, 3}, kColour, {1, 2, 3}, out).code, Errc::ProbeInsideLight);
  EXPECT_EQ(add_spot_light({{1, 2, 3}, {0, -1, 0}, 0.1, 0.2}, kColour, {1, 2, 3}, out).code,
            Errc::ProbeInsideLight);
  EXPECT_EQ(add_directional_light({0, 0, 0}, 0.0, kColour, out).code, Errc::InvalidArgument);
  EXPECT_EQ(add_directional_light({0, 1, 0}, kPi, kColour, out).code, Errc::InvalidArgument);
  EXPECT_EQ(add_directional_light({0, 1, 0}, 0.0, {1, -1, 0}, out).code, Errc::InvalidArgument);
  EXPECT_EQ(add_sphere_light({0, 0, 0}, -1.0, kColour, {5, 0, 0}, out).code, Errc::InvalidArgument);
  EXPECT_EQ(add_spot_light({{0, 0, 0}, {0, -1, 0}, 0.5, 0.2}, kColour, {1, 1, 1}, out).code,
            Errc::InvalidArgument);
  EXPECT_EQ(add_rect_light({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, 1, 1}, kColour, {0, 0, 1}, out).code,
            Errc::InvalidArgument);
  EXPECT_EQ(add_rect_light({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1}, kColour, {0, 0, 1}, out).code,
            Errc::InvalidArgument);
  EXPECT_EQ(add_disk_light({{0, 0, 0}, {0, 0, 1}, 0}, kColour, {0, 0, 1}, out).code, Errc::InvalidArgument);
  EXPECT_EQ(add_hemisphere_light({1, std::nan(""), 1}, kColour, out).code, Errc::InvalidArgument);
  EXPECT_EQ(add_ambient_light({1, 1, INFINITY}, out).code, Errc::InvalidArgument);
  EXPECT_EQ(out, before);
}

}  // namespace
}  // namespace shpack
