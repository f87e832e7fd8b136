// The light fit (light_fit.h) on view samples made by hand: a map whose light above L2 is
// exactly that of one directional light gives back its colour and, from a direction a few
// degrees off, its direction; on random truths the fit is no worse than any non-negative
// colours it may choose (an independent scan) and keeps the SH non-negative where the map's is;
// a light is moved only within its reach.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "shpack/convolution.h"
#include "shpack/light_fit.h"
#include "shpack/sh_basis.h"
#include "support/test_util.h"

namespace shpack {
namespace {

constexpr std::array<double, 3> kNoBandFactors = {1.0, 1.0, 1.0};

// h(t) of light_fit.h, written from the clamped cosine's series: max(0, t) less its bands 0..2
// (1/4, t/2, (5/16) P2(t)).
double above_l2(double t) { return std::max(0.0, t) - (0.25 + 0.5 * t + (5.0 / 16.0) * 0.5 * (3 * t * t - 1)); }

// A map whose SH shows E/pi = s everywhere (radiance L00 only) and whose truth is that plus
// x_c h(n . l) per channel: the light above L2 of a delta of colour x_c towards l over a
// uniform sky.
struct PlantedMap {
  ViewSamples samples;
  ShL2 projected;
};

PlantedMap planted(const Dir3& l, const std::array<double, 3>& x, double s) {
  PlantedMap out;
  for (std::size_t i = 0; i < kViewErrorDirections; ++i) {
    const Dir3 n = spherical_fibonacci(i, kViewErrorDirections);
    out.samples.directions.push_back(n);
    ReferenceValue value;
    const double t = n.x * l.x + n.y * l.y + n.z * l.z;
    for (int c = 0; c < 3; ++c) value.e_over_pi[c] = s + x[c] * above_l2(t);
    out.samples.values.push_back(value);
  }
  // The mean of h over the sphere is 0 (its bands 0..2 are gone, and max(0, t) has mean 1/4).
  out.samples.mean = {s, s, s};
  for (int c = 0; c < 3; ++c) out.projected.c[c][0] = s / kUnityScale[0];
  return out;
}

// The fit's side of the map (prepare_light_fit), with no band factors.
LightFitProblem problem_of(const PlantedMap& map) {
  LightFitProblem problem;
  EXPECT_TRUE(prepare_light_fit(map.samples, map.projected, kNoBandFactors, problem).ok());
  return problem;
}

Dir3 unit(double x, double y, double z) {
  const double r = std::sqrt(x * x + y * y + z * z);
  return {x / r, y / r, z / r};
}

TEST(LightFit, GivesBackThePlantedColour) {
  const Dir3 l = unit(0.3, 0.8, -0.5);
  // S - x g >= 0 needs x <= s / max g = s / (17/16): x = 0.9 s at most.
  const std::array<double, 3> x = {0.2, 0.5, 0.9};
  const PlantedMap map = planted(l, x, 1.0);
  LightFit fit;
  ASSERT_TRUE(fit_light_colours(problem_of(map), std::vector<Dir3>{l}, fit).ok());
  ASSERT_EQ(fit.irradiance.size(), 1u);
  // The error |x' - x| max |h| is 0 only at x' = x: the LP's vertex, up to the rounding of a
  // few pivots on O(1) numbers (1e-9 with room); E = pi x.
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(fit.irradiance[0][c], std::numbers::pi * x[c], 1e-9) << c;
    EXPECT_NEAR(fit.max_pct[c], 0.0, 1e-7) << c;
  }
  // Its SH is the delta's: E Y(l).
  const ShL2 sh = fitted_lights_sh(std::vector<Dir3>{l}, fit);
  const auto y = eval_basis(l.x, l.y, l.z);
  for (int i = 0; i < kShCount; ++i) EXPECT_NEAR(sh.c[1][i], std::numbers::pi * x[1] * y[i], 1e-9);
}

TEST(LightFit, NoLightLeavesTheMapsOwnError) {
  const PlantedMap map = planted(unit(0, 1, 0), {0.5, 0.5, 0.5}, 1.0);
  LightFit fit;
  ASSERT_TRUE(fit_light_colours(problem_of(map), {}, fit).ok());
  EXPECT_TRUE(fit.irradiance.empty());
  // max |b| = 0.5 max |h|; h's largest magnitude over the samples, computed the same way.
  double most = 0;
  for (const Dir3& n : map.samples.directions) most = std::max(most, std::abs(0.5 * above_l2(n.y)));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(fit.max_pct[c], 100 * most, 1e-12);
}

TEST(LightFit, IsNoWorseThanAnyColoursOfARandomScan) {
  // Random smooth truths and two fixed lights: the fitted max error is at most that of every
  // non-negative pair of colours that keeps the SH non-negative where the map's is (the
  // feasible set), here scanned on a grid; and the fit itself keeps that constraint.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const std::vector<Dir3> lights = {unit(0.2, 0.9, 0.1), unit(-0.7, 0.1, 0.6)};
  for (int trial = 0; trial < 6; ++trial) {
    PlantedMap map = planted(lights[0], {0.3, 0.3, 0.3}, 1.0);
    std::array<double, kShCount> wiggle{};
    for (double& w : wiggle) w = 0.1 * u(rng);
    for (std::size_t i = 0; i < map.samples.directions.size(); ++i) {
      const Dir3& n = map.samples.directions[i];
      const auto p = basis_polynomials(n.x, n.y, n.z);
      double extra = 0;
      for (int k = 0; k < kShCount; ++k) extra += wiggle[k] * p[k] * p[(k + 3) % kShCount];  // bands up to 4
      for (double& v : map.samples.values[i].e_over_pi) v += extra;
    }
    LightFit fit;
    ASSERT_TRUE(fit_light_colours(problem_of(map), lights, fit).ok());
    const ShL2 unity = radiance_to_unity_form(map.projected);
    auto error_of = [&](double x0, double x1, bool& feasible) {
      double worst = 0;
      feasible = x0 >= 0 && x1 >= 0;
      for (std::size_t i = 0; i < map.samples.directions.size(); ++i) {
        const Dir3& n = map.samples.directions[i];
        const double t0 = n.x * lights[0].x + n.y * lights[0].y + n.z * lights[0].z;
        const double t1 = n.x * lights[1].x + n.y * lights[1].y + n.z * lights[1].z;
        const double s = eval_unity_form(unity, 0, n.x, n.y, n.z);
        const double sh_left = s - x0 * (std::max(0.0, t0) - above_l2(t0)) - x1 * (std::max(0.0, t1) - above_l2(t1));
        feasible = feasible && sh_left >= std::min(s, 0.0) - 1e-12;
        const double shown = sh_left + x0 * std::max(0.0, t0) + x1 * std::max(0.0, t1);
        worst = std::max(worst, std::abs(shown - map.samples.values[i].e_over_pi[0]));
      }
      return 100 * worst;
    };
    bool feasible = false;
    const double x0 = fit.irradiance[0][0] / std::numbers::pi, x1 = fit.irradiance[1][0] / std::numbers::pi;
    // The fit's own error, recomputed independently, is what it reports, and it is feasible.
    EXPECT_NEAR(error_of(x0, x1, feasible), fit.max_pct[0], 1e-7);
    EXPECT_TRUE(feasible);
    for (double a = 0; a <= 1.0; a += 0.05) {
      for (double b = 0; b <= 1.0; b += 0.05) {
        const double e = error_of(a, b, feasible);
        if (feasible) {
          EXPECT_LE(fit.max_pct[0], e + 1e-7) << trial << ": " << a << ", " << b;
        }
      }
    }
  }
}

TEST(LightFit, RefiningFindsThePlantedDirectionWithinReach) {
  const Dir3 l = unit(0.3, 0.8, -0.5);
  const PlantedMap map = planted(l, {0.4, 0.5, 0.6}, 1.0);
  // A source 3 degrees off the planted light, reach 5 degrees: the search moves the light back;
  // compass steps end at 0.25 degrees on two tangent axes, so within sqrt(2) x 0.25 of it.
  const Dir3 e = unit(l.y, -l.x, 0);  // a tangent
  const double a = 3.0 * std::numbers::pi / 180;
  const Dir3 source = unit(std::cos(a) * l.x + std::sin(a) * e.x, std::cos(a) * l.y + std::sin(a) * e.y,
                           std::cos(a) * l.z + std::sin(a) * e.z);
  std::vector<Dir3> directions = {source};
  const std::vector<double> reach = {5.0};
  ASSERT_TRUE(refine_light_directions(problem_of(map), std::vector<Dir3>{source}, reach,
                                      directions)
                  .ok());
  EXPECT_LT(angle_deg(directions[0], l), std::sqrt(2.0) * 0.25 + 1e-9);
  EXPECT_LE(angle_deg(directions[0], source), 5.0 + 1e-9);
  // With a reach of 1 degree it cannot get there: it stops within the reach.
  directions = {source};
  ASSERT_TRUE(refine_light_directions(problem_of(map), std::vector<Dir3>{source},
                                      std::vector<double>{1.0}, directions)
                  .ok());
  EXPECT_LE(angle_deg(directions[0], source), 1.0 + 1e-9);
  EXPECT_GT(angle_deg(directions[0], l), 1.9);
}

TEST(LightFit, RefusesBadDirections) {
  const PlantedMap map = planted(unit(0, 1, 0), {0.5, 0.5, 0.5}, 1.0);
  LightFit fit;
  EXPECT_EQ(fit_light_colours(problem_of(map), std::vector<Dir3>{{0, 0, 0}}, fit).code,
            Errc::InvalidArgument);
  std::vector<Dir3> directions = {{0, 1, 0}};
  EXPECT_EQ(refine_light_directions(problem_of(map), {}, std::vector<double>{1.0},
                                    directions)
                .code,
            Errc::InvalidArgument);
}

TEST(LightFit, AngleIsAccurateNearZero) {
  EXPECT_DOUBLE_EQ(angle_deg({0, 0, 1}, {0, 0, 1}), 0.0);
  const double a = 1e-7;  // acos(cos a) would lose it entirely
  EXPECT_NEAR(angle_deg({0, 0, 1}, {std::sin(a), 0, std::cos(a)}), a * 180 / std::numbers::pi, 1e-18);
  EXPECT_NEAR(angle_deg({1, 0, 0}, {0, 1, 0}), 90.0, 1e-12);
}

}  // namespace
}  // namespace shpack
