// Tests of the bake engine (bake.h): only what is asked for is simulated and paid for,
// effects compose without counting twice, shadows remove exactly what is hidden, the
// furnace, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "bake_support.h"
#include "scene/scene_files.h"
#include "shpack/bake/bake.h"
#include "shpack/convolution.h"
#include "shpack/io/convert.h"
#include "shpack/lights.h"
#include "shpack/rotate.h"
#include "shpack/scene/scene_loader.h"
#include "shpack/sky.h"
#include "support/exr_file.h"
#include "support/test_util.h"

namespace shpack::bake {
namespace {

using shpack_test::kEps;

using shpack_test::Baked;

// Loads `json` as a scene file and bakes it, keeping each effect's part.
Baked bake_json(const std::string& name, const std::string& json, unsigned threads = 2) {
  return shpack_test::bake_ok(name, json, threads);
}

const ShL2& part(const Baked& b, std::size_t probe, Effect e) {
  return b.result.effects.at(probe)[static_cast<std::size_t>(e)];
}
const EffectCost& cost(const Baked& b, Effect e) { return b.result.costs[static_cast<std::size_t>(e)]; }

// A room's worth of lights and geometry; effects are filled in by each test.
std::string scene_with(const std::string& effects, const std::string& settings = "") {
  return R"({
    "probes": {"min": [-1, 0.5, -1], "max": [1, 1.5, 1], "counts": [3, 2, 3]},
    "environment": {"type": "gradient", "zenith": [0.2, 0.4, 1.0], "horizon": [0.8, 0.9, 1.0], "ground": 0.1},
    "lights": [
      {"type": "directional", "direction": [0.3, -1, 0.2], "irradiance": [3, 3, 2.5], "angular_diameter_deg": 0.53},
      {"type": "sphere", "position": [0, 3, 0], "radius": 0.2, "power": 100},
      {"type": "point", "position": [2, 2.5, -1], "intensity": 4},
      {"type": "spot", "position": [-2, 2.5, 1], "direction": [1, -1, 0], "outer_angle_deg": 40, "intensity": 9},
      {"type": "rect", "position": [0, 2, 3], "right": [-1, 0, 0], "up": [0, 1, 0], "size": [1, 0.5], "radiance": 5},
      {"type": "disk", "position": [0, 2.9, -2], "direction": [0, -1, 0], "radius": 0.3, "radiance": 6},
      {"type": "hemisphere", "sky": [0.1, 0.1, 0.2], "ground": 0.05},
      {"type": "ambient", "radiance": 0.01}
    ],
    "geometry": [
      {"type": "box", "min": [-3, -0.1, -3], "max": [3, 0, 3], "albedo": 0.5},
      {"type": "sphere", "position": [0.5, 2.2, 0.3], "radius": 0.3, "albedo": [0.7, 0.2, 0.2], "emission": 0.5},
      {"type": "plane", "position": [0, 1.5, -3], "right": [1, 0, 0], "up": [0, 1, 0], "size": [6, 3], "albedo": 0.3}
    ],
    "effects": [)" + effects + R"(]
    )" + (settings.empty() ? "" : ", \"settings\": " + settings) + "}";
}

TEST(Bake, GeometryWithoutAVisibilityEffectTracesNoRay) {
  const Baked b = bake_json("closed_forms", scene_with(R"("direct", "environment")"));
  EXPECT_TRUE(b.result.geometry.built) << "no effect needs the ray tracer, but probe validity does";
  for (std::size_t e = 0; e < kEffectCount; ++e)
    EXPECT_EQ(b.result.costs[e].rays, 0u) << effect_name(static_cast<Effect>(e));
  EXPECT_EQ(cost(b, Effect::Direct).analytic, 18u * 8u) << "18 probes x 8 lights, each one closed form";
  EXPECT_EQ(cost(b, Effect::Environment).analytic, 18u);
  // The environment is the gradient sky's closed form, the same at every probe.
  ShL2 sky;
  ASSERT_TRUE(add_gradient_sky({0.2, 0.4, 1.0}, {0.8, 0.9, 1.0}, {0.1, 0.1, 0.1}, sky).ok());
  for (std::size_t k = 0; k < b.scene.probes.size(); ++k) EXPECT_EQ(part(b, k, Effect::Environment), sky) << "probe " << k;
  // And the direct part of probe 0 is the sum of the lights' closed forms (two of them checked
  // through lights.h directly: the point light and the ambient one).
  ShL2 point_and_ambient;
  ASSERT_TRUE(add_point_light({2, 2.5, -1}, {4, 4, 4}, b.scene.probes[0], point_and_ambient).ok());
  ASSERT_TRUE(add_ambient_light({0.01, 0.01, 0.01}, point_and_ambient).ok());
  const Baked only = bake_json("two_lights", R"({"probes": [[-1, 0.5, -1]], "effects": ["direct"], "lights": [
    {"type": "point", "position": [2, 2.5, -1], "intensity": 4}, {"type": "ambient", "radiance": 0.01}]})");
  EXPECT_EQ(only.result.radiance[0], point_and_ambient);
}

TEST(Bake, TurningAnEffectOnChangesOnlyItsOwnPartAndCost) {
  const std::string base = R"("direct", "environment")";
  const Baked without = bake_json("base", scene_with(base));
  for (const std::string extra : {"shadows", "sky_occlusion", "emission", "bounce:2"}) {
    const Baked with = bake_json(extra.substr(0, 6), scene_with(base + ", \"" + extra + "\""));
    const Effect own = extra == "shadows"         ? Effect::Shadows
                       : extra == "sky_occlusion" ? Effect::SkyOcclusion
                       : extra == "emission"      ? Effect::Emission
                                                  : Effect::Bounce;
    EXPECT_GT(cost(with, own).rays, 0u) << extra;
    for (std::size_t e = 0; e < kEffectCount; ++e) {
      if (static_cast<Effect>(e) == own) continue;
      EXPECT_EQ(with.result.costs[e].rays, without.result.costs[e].rays) << extra << " / " << effect_name(static_cast<Effect>(e));
      EXPECT_EQ(with.result.costs[e].enabled, without.result.costs[e].enabled) << extra;
      for (std::size_t k = 0; k < with.scene.probes.size(); ++k)
        EXPECT_EQ(with.result.effects[k][e], without.result.effects[k][e])
            << extra << " changed " << effect_name(static_cast<Effect>(e)) << " at probe " << k;
    }
    // The total is the old total plus the new part, exactly as summed (fixed order).
    bool own_nonzero = false;
    for (std::size_t k = 0; k < with.scene.probes.size(); ++k)
      own_nonzero = own_nonzero || !(part(with, k, own) == ShL2{});
    EXPECT_TRUE(own_nonzero) << extra << " contributed nothing";
  }
}

TEST(Bake, ALightNoOccluderCanTouchStaysAnalyticWithShadows) {
  // A point light and a spot above the probe, the only shape far to the side.
  const Baked b = bake_json("untouched", R"({
    "probes": [[0, 0, 0], [0.5, 0, 0]],
    "lights": [{"type": "point", "position": [0, 3, 0], "intensity": 1},
               {"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "outer_angle_deg": 30, "intensity": 1},
               {"type": "sphere", "position": [0, 4, 0], "radius": 0.5, "intensity": 1}],
    "geometry": [{"type": "sphere", "position": [5, 1, 0], "radius": 1}],
    "effects": ["direct", "shadows"]})");
  EXPECT_EQ(cost(b, Effect::Shadows).rays, 0u);
  EXPECT_EQ(cost(b, Effect::Shadows).analytic, 6u);
  for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(part(b, k, Effect::Shadows), ShL2{}) << "probe " << k;
}

TEST(Bake, AnOccluderThatHidesALightWhollyRemovesExactlyItsContribution) {
  // Each light alone above a probe enclosed from above by a large box lid.
  for (const std::string light :
       {R"({"type": "sphere", "position": [0, 3, 0], "radius": 0.4, "intensity": [1, 2, 3]})",
        R"({"type": "point", "position": [0.3, 3, 0], "intensity": 2})",
        R"({"type": "rect", "position": [0, 3, 0], "right": [1, 0, 0], "up": [0, 0, 1], "size": [1, 2], "radiance": 3})",
        R"({"type": "disk", "position": [0, 3, 0], "direction": [0, -1, 0], "radius": 0.7, "radiance": 3})",
        R"({"type": "directional", "direction": [0, -1, 0.1], "irradiance": 5, "angular_diameter_deg": 4})"}) {
    const Baked b = bake_json("hidden", R"({"probes": [[0, 0, 0]], "lights": [)" + light + R"(],
      "geometry": [{"type": "box", "min": [-50, 1, -50], "max": [50, 1.5, 50]}],
      "effects": ["direct", "shadows"]})");
    EXPECT_GT(cost(b, Effect::Shadows).rays, 0u) << light;
    ShL2 minus = part(b, 0, Effect::Direct);
    for (auto& ch : minus.c)
      for (double& v : ch) v = -v;
    EXPECT_EQ(part(b, 0, Effect::Shadows), minus) << light;
    EXPECT_EQ(b.result.radiance[0], ShL2{}) << light << ": nothing is left";
  }
}

TEST(Bake, ASmallerSphereCentredInFrontOfASphereLightLeavesTheDifferenceOfTwoCaps) {
  // Light: radius 1 at distance 10 (half-angle a_L = asin 0.1); occluder: radius 0.25 at
  // distance 5 on the same axis (a_O = asin 0.05). The visible part is the cap a_L minus the
  // cap a_O, of the light's radiance L = I / (pi R^2).
  const int samples = 512;
  const Baked b = bake_json("two_caps", R"({"probes": [[0, 0, 0]],
    "lights": [{"type": "sphere", "position": [0, 10, 0], "radius": 1, "intensity": [3, 2, 1]}],
    "geometry": [{"type": "sphere", "position": [0, 5, 0], "radius": 0.25}],
    "effects": ["direct", "shadows"], "settings": {"shadow_samples": )" + std::to_string(samples) + "}}");
  const Rgb radiance = {3 / std::numbers::pi, 2 / std::numbers::pi, 1 / std::numbers::pi};
  ShL2 big, small;
  ASSERT_TRUE(add_cone_light({0, 1, 0}, std::asin(0.1), radiance, big).ok());
  ASSERT_TRUE(add_cone_light({0, 1, 0}, std::asin(0.05), radiance, small).ok());
  // Tolerance: the light's points are uniform in (1 - cos theta', phi) over its cap, a
  // scrambled (0, m, 2)-net per batch (m = samples / 8), and the hidden set is the strip
  // 1 - cos theta' < (1 - cos a_O) of that square, whose edge is parallel to an axis: each
  // batch has one point in every 1/m-wide strip of it, so its count of hidden points is within
  // 1 of m times the hidden share. The visible points' sum then differs from the integral by at
  // most one point's worth, and the smooth rest of each point's value by at most the same
  // again: 2 (Omega_L / m) L max|Y_i|, Omega_L = 2 pi (1 - cos a_L).
  const double m = samples / 8.0;
  const double stratum = 2 * std::numbers::pi * (1 - std::sqrt(0.99)) / m;
  const std::array<double, kShCount> max_y = {kY0, kY1, kY1, kY1, kY2 / 2, kY2 / 2, 2 * kY20, kY2 / 2, kY22};
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) {
      const double want = big.c[c][i] - small.c[c][i];
      const double tol = 2 * stratum * radiance[c] * max_y[i] + 64 * kEps * big.c[c][0];
      EXPECT_NEAR(b.result.radiance[0].c[c][i], want, tol) << "c=" << c << " i=" << i;
    }
}

TEST(Bake, FurnaceClosedSphereGivesTheGeometricSeries) {
  // A probe inside a closed sphere of albedo a emitting Le: every path sees Le at each of its
  // vertices, weighted a^k, so after N bounces the radiance is Le (1 - a^(N+1)) / (1 - a) in
  // every direction. Emission and each bounce are found both by the paths' own directions and
  // by points of the emitter (next-event estimation), so the estimate is unbiased but not
  // exact: the test holds it to the bake's own promise, the largest error over directions
  // below twice its error estimate, and that estimate below 2 % at 2048 samples (about
  // 1 / sqrt(2048) of the light, times the spread of the weights).
  const double a = 0.5, le = 2.0;
  const int paths = 2048;
  for (int n = 1; n <= 4; ++n) {
    const Baked b = bake_json("furnace", R"({"probes": [[0.1, -0.2, 0.05]],
      "geometry": [{"type": "sphere", "position": [0, 0, 0], "radius": 1, "albedo": 0.5, "emission": 2}],
      "effects": ["emission", "bounce:)" + std::to_string(n) + R"("],
      "settings": {"sky_samples": )" + std::to_string(paths) + R"(, "bounce_samples": )" + std::to_string(paths) +
      R"(, "target_error_pct": 0, "invalid_probes": "keep"}})");
    const double want = le * (1 - std::pow(a, n + 1)) / (1 - a);
    ShL2 uniform;
    ASSERT_TRUE(add_ambient_light({want, want, want}, uniform).ok());
    const double estimate = b.result.error_estimate_pct[0];
    EXPECT_LT(estimate, 2.0) << "N=" << n;
    EXPECT_LE(shpack_test::max_error_pct(b.result.radiance[0], uniform), 2 * estimate) << "N=" << n;
    EXPECT_EQ(cost(b, Effect::Bounce).samples, static_cast<std::uint64_t>(paths));
  }
}

TEST(Bake, AnEnclosedProbeSeesNoSkyAndOneInTheOpenAllOfIt) {
  const Baked b = bake_json("enclosed", R"({"probes": [[0, 0.5, 0], [3, 0.5, 0]],
    "environment": {"type": "gradient", "zenith": [0.2, 0.4, 1.0], "horizon": [0.8, 0.9, 1.0], "ground": 0.1},
    "geometry": [{"type": "box", "min": [-1, 0, -1], "max": [1, 1, 1]}],
    "effects": ["environment", "sky_occlusion"], "settings": {"invalid_probes": "keep"}})");
  EXPECT_EQ(b.result.radiance[0], ShL2{}) << "inside the box: the sky is all hidden, exactly";
  // Outside, the box hides a little: the occlusion takes radiance away, never adds it.
  EXPECT_LT(part(b, 1, Effect::SkyOcclusion).c[0][0], 0.0);
  EXPECT_GT(b.result.radiance[1].c[0][0], 0.0);
}

TEST(Bake, TheSameResultForAnyThreadCount) {
  const std::string json = scene_with(R"("direct", "environment", "shadows", "sky_occlusion", "emission", "bounce:2")",
                                      R"({"seed": 11, "shadow_samples": 32, "sky_samples": 64, "bounce_samples": 64})");
  const Baked one = bake_json("threads1", json, 1), three = bake_json("threads3", json, 3);
  ASSERT_EQ(one.result.radiance.size(), three.result.radiance.size());
  for (std::size_t k = 0; k < one.result.radiance.size(); ++k)
    EXPECT_EQ(one.result.radiance[k], three.result.radiance[k]) << "probe " << k;
  for (std::size_t e = 0; e < kEffectCount; ++e)
    EXPECT_EQ(one.result.costs[e].rays, three.result.costs[e].rays) << effect_name(static_cast<Effect>(e));
}

TEST(Bake, APreethamSkyIsProjectedOnceAndAddedToEveryProbe) {
  const Baked b = bake_json("preetham", R"({"probes": [[0, 0, 0], [5, 1, 2]],
    "environment": {"type": "preetham", "to_sun": [0.5, 0.6, 0.2], "turbidity": 3, "ground": 0.1, "intensity": 0.5},
    "effects": ["environment"]})");
  const PreethamSky& sky = b.scene.environment.preetham;  // the sun direction normalised by the loader
  EXPECT_EQ(sky.turbidity, 3.0);
  EXPECT_EQ(sky.intensity, 0.5);
  EXPECT_EQ(sky.ground, (Rgb{0.1, 0.1, 0.1}));
  EXPECT_NEAR(sky.sun.y, 0.6 / std::sqrt(0.65), 1e-15);
  ShL2 want;
  ASSERT_TRUE(add_preetham_sky(sky, want).ok());
  for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(b.result.radiance[k], want) << "probe " << k;
}

TEST(Bake, AnEnvironmentMapIsProjectedAsConvertDoesItAndLookedUpForRays) {
  // A 64 x 32 equirect map, bright in one corner region, turned and scaled by the scene.
  shpack_test::RgbImage image(64, 32);
  for (std::uint32_t y = 0; y < 32; ++y)
    for (std::uint32_t x = 0; x < 64; ++x) image.set(x, y, 0.1f + (x < 8 && y < 8 ? 5.0f : 0.0f), 0.2f, 0.3f * y / 32);
  std::string error;
  ASSERT_TRUE(shpack_test::write_exr_rgb(shpack_test::scene_scratch() / "map.exr", image, error)) << error;
  const Baked b = bake_json("map", R"({"probes": [[0, 0.5, 0], [4, 0.5, 0]],
    "environment": {"type": "map", "path": "map.exr", "rotation_deg": 30, "intensity": 2},
    "geometry": [{"type": "box", "min": [-1, 0, -1], "max": [1, 1, 1]}],
    "effects": ["environment", "sky_occlusion"], "settings": {"invalid_probes": "keep"}})");
  Conversion projection;
  ASSERT_TRUE(io::convert_file(shpack_test::scene_scratch() / "map.exr", {}, projection).ok());
  const ShL2 want = rotate_about_y(scaled(projection.sh.radiance, 2.0), 30.0);
  for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(part(b, k, Effect::Environment), want) << "probe " << k;
  EXPECT_EQ(b.result.radiance[0], ShL2{}) << "inside the box the map is all hidden";
  EXPECT_LT(part(b, 1, Effect::SkyOcclusion).c[0][0], 0.0) << "outside, the box hides some of it";
}

TEST(Bake, AProbeInsideALightIsAnErrorNamingBoth) {
  scene::Scene scene;
  const auto path = shpack_test::write_scene("inside.json", R"({"probes": [[0, 0, 0], [0, 2.9, 0]],
    "lights": [{"type": "ambient", "radiance": 1},
               {"type": "sphere", "name": "lamp", "position": [0, 3, 0], "radius": 0.5, "intensity": 1}],
    "effects": ["direct"]})");
  ASSERT_TRUE(scene::load_scene(path, scene).ok());
  BakeResult result;
  const io::IoStatus st = bake(scene, {}, result);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.message, path.string() + ": probes[1] (0, 2.9, 0) is inside lights[1] 'lamp' (probe inside the sphere light)");
}

}  // namespace
}  // namespace shpack::bake
