// Tests of SH lightmaps (lightmap_bake.h) against closed forms: a plane under a uniform sky,
// a plane under a sun with a box's umbra, a furnace; determinism; bad requests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <numbers>
#include <string>

#include "bake_support.h"
#include "lightmap_raster.h"
#include "scene/scene_files.h"
#include "shpack/bake/lightmap_bake.h"
#include "shpack/bake/lightmap_output.h"
#include "shpack/lights.h"
#include "shpack/scene/scene_loader.h"
#include "surface_domain.h"

namespace shpack::bake {
namespace {

struct Lightmapped {
  scene::Scene scene;
  io::IoStatus status = io::IoStatus::success();
  LightmapBakeResult result;
};

Lightmapped bake_lightmap_scene(const std::string& name, const std::string& json, unsigned threads = 2) {
  Lightmapped b;
  b.status = scene::load_scene(shpack_test::write_scene(name + ".json", json), b.scene);
  if (!b.status.ok()) return b;
  BakeOptions options;
  options.threads = threads;
  options.keep_effects = true;  // each texel's parts and sampling, for the tests that read them
  b.status = bake_lightmaps(b.scene, options, b.result);
  return b;
}

// The SH of a radiance L over the hemisphere about n (zero below): by the Funk-Hecke theorem,
// int H(n.w) Y_lm(w) dw = lambda_l Y_lm(n), lambda_l = 2 pi int_0^1 P_l(t) dt: 2 pi, pi, 0.
ShL2 uniform_hemisphere(double radiance, const Vec3& n) {
  const std::array<double, kShCount> y = eval_basis(n.x, n.y, n.z);
  ShL2 out;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i)
      out.c[c][i] = radiance * (i == 0 ? 2 * std::numbers::pi : i < 4 ? std::numbers::pi : 0.0) * y[i];
  return out;
}

// A floor plane facing +Y (right x up = +Y in Unity's frame), 4 m a side, with a lightmap.
std::string floor_plane(int resolution, const std::string& extra = "") {
  return R"({"type": "plane", "name": "floor", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0],
             "size": [4, 4], "albedo": 0.5, "lightmap": {"resolution": [)" +
         std::to_string(resolution) + ", " + std::to_string(resolution) + "]" + extra + "}}";
}

TEST(LightmapHemisphere, GramMatrixIsExactForTheHemisphere) {
  // M(n) c for a constant radiance is the Funk-Hecke result above, for any normal.
  for (const Vec3 n : {Vec3{0, 1, 0}, Vec3{0.6, 0, 0.8}, Vec3{-0.48, 0.6, -0.64}}) {
    ShL2 constant;
    for (auto& ch : constant.c) ch[0] = 1.0 / kY0;  // radiance 1: c_0 = 1 / Y_0 = sqrt(4 pi)
    const ShL2 got = hemisphere_part(hemisphere_gram(n), constant);
    const ShL2 want = uniform_hemisphere(constant.c[0][0] * kY0, n);
    for (int i = 0; i < kShCount; ++i) EXPECT_NEAR(got.c[0][i], want.c[0][i], 1e-13) << i;
  }
  // M is a projection onto functions on the hemisphere: M + M(-n) = I (the two halves).
  const Vec3 n{0.36, 0.48, 0.8};
  const ShMatrix a = hemisphere_gram(n), b = hemisphere_gram(-1.0 * n);
  for (int i = 0; i < kShCount; ++i)
    for (int j = 0; j < kShCount; ++j) EXPECT_NEAR(a[i][j] + b[i][j], i == j ? 1.0 : 0.0, 1e-14) << i << "," << j;
}

TEST(Lightmap, PlaneUnderAUniformSkyIsExact) {
  // A uniform environment (gradient with equal colours) is band-limited, so the hemisphere's
  // SH is M(n) c exactly and the residual is 0 at every sample: each texel is the closed form
  // to rounding (relative 1e-12 over a few hundred terms of 1e-16).
  const Lightmapped b = bake_lightmap_scene("uniform_sky", R"({
    "environment": {"type": "gradient", "zenith": 0.7, "horizon": 0.7, "ground": 0.7},
    "geometry": [)" + floor_plane(4) + R"(],
    "effects": ["environment"]})");
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  ASSERT_EQ(b.result.maps.size(), 1u);
  const LightmapTexels& map = b.result.maps[0];
  EXPECT_EQ(map.used, 16u);
  EXPECT_EQ(map.points, 64u);  // 2 x 2 points per fully covered texel
  const ShL2 want = uniform_hemisphere(0.7, {0, 1, 0});
  for (std::size_t t = 0; t < 16; ++t) {
    EXPECT_EQ(map.state[t], TexelState::Baked);
    EXPECT_FLOAT_EQ(map.coverage[t], 1.0f);
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) EXPECT_NEAR(map.radiance[t].c[c][i], want.c[c][i], 1e-12) << t << " " << i;
  }
}

// A glTF quad of 2 x 2 m in its xz-plane, front (counter-clockwise, glTF's right-handed frame)
// facing +Y, with TEXCOORD_0 all at one point (a material's UVs, which would overlap) and, when
// `second`, TEXCOORD_1 spanning [0, 1]^2: base64 buffers, one file.
std::string gltf_quad(bool second) {
  const float positions[12] = {-1, 0, 1, 1, 0, 1, 1, 0, -1, -1, 0, -1};
  const float uv0[8] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
  const float uv1[8] = {0, 1, 1, 1, 1, 0, 0, 0};
  const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  std::string bytes(reinterpret_cast<const char*>(positions), sizeof positions);
  bytes.append(reinterpret_cast<const char*>(uv0), sizeof uv0);
  bytes.append(reinterpret_cast<const char*>(uv1), sizeof uv1);
  bytes.append(reinterpret_cast<const char*>(indices), sizeof indices);
  const std::string attributes = second ? R"("POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_1": 2)" : R"("POSITION": 0, "TEXCOORD_0": 1)";
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {)" + attributes + R"(}, "indices": 3}]}],
    "buffers": [{"byteLength": )" + std::to_string(bytes.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
         shpack_test::base64(bytes) + R"("}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                    {"buffer": 0, "byteOffset": 80, "byteLength": 32}, {"buffer": 0, "byteOffset": 112, "byteLength": 12}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                  {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
}

TEST(Lightmap, GltfSecondUvSetUnderAUniformSkyIsExact) {
  // The glTF quad's TEXCOORD_1 is the lightmap; its front faces +Y in Unity's frame too (the
  // loader mirrors z and keeps the winding's side), so every texel is the closed form for +Y.
  shpack_test::write_scene("quad_uv1.gltf", gltf_quad(true));
  const Lightmapped b = bake_lightmap_scene("gltf_uv1", R"({
    "environment": {"type": "gradient", "zenith": 0.4, "horizon": 0.4, "ground": 0.4},
    "geometry": [{"type": "mesh", "name": "quad", "path": "quad_uv1.gltf", "lightmap": {"resolution": [4, 4]}}],
    "effects": ["environment"]})");
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  const LightmapTexels& map = b.result.maps[0];
  EXPECT_EQ(map.used, 16u);
  const ShL2 want = uniform_hemisphere(0.4, {0, 1, 0});
  for (std::size_t t = 0; t < 16; ++t)
    for (int i = 0; i < kShCount; ++i) EXPECT_NEAR(map.radiance[t].c[1][i], want.c[1][i], 1e-12) << t << " " << i;
}

// A 2 m quad at y = 0 from OBJ `text` (its positions and UVs, its vn if any), 2 x 2 texels,
// under a uniform sky of 0.4: every texel is the hemisphere about its shading normal.
Lightmapped bake_obj_quad(const std::string& name, const std::string& text) {
  shpack_test::write_scene(name + ".obj", text);
  return bake_lightmap_scene(name, R"({
    "environment": {"type": "gradient", "zenith": 0.4, "horizon": 0.4, "ground": 0.4},
    "geometry": [{"type": "mesh", "path": ")" + name + R"(.obj", "lightmap": {"resolution": [2, 2]}}],
    "effects": ["environment"]})");
}

void expect_texels(const Lightmapped& b, const ShL2& want, double tolerance) {
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  EXPECT_EQ(b.result.maps[0].used, 4u);
  for (std::size_t t = 0; t < 4; ++t)
    for (int i = 0; i < kShCount; ++i) EXPECT_NEAR(b.result.maps[0].radiance[t].c[0][i], want.c[0][i], tolerance);
}

constexpr const char* kObjQuad = "v -1 0 -1\nv -1 0 1\nv 1 0 1\nv 1 0 -1\nvt 0 0\nvt 0 1\nvt 1 1\nvt 1 0\n";

TEST(Lightmap, ObjTextureCoordinatesAreTheLightmapUvs) {
  // OBJ's only UV set, v up as Unity's; the quad's (v1 - v0) x (v2 - v0) is +Y, its front.
  expect_texels(bake_obj_quad("obj_uv", std::string(kObjQuad) + "f 1/1 2/2 3/3 4/4\n"),
                uniform_hemisphere(0.4, {0, 1, 0}), 1e-12);
}

TEST(Lightmap, ObjNormalsAreTheShadingNormals) {
  // The same quad, its vn tilted 45 degrees towards +X on every corner: each texel is the
  // hemisphere about the shading normal n = (1, 1, 0)/sqrt 2, not about the quad's own +Y. A
  // vn of any length is made unit (here 2 (1, 1, 0)). Shading normals are kept in float
  // (relative rounding 2^-24 = 6e-8 per component) and the L1 coefficients are linear in n
  // with factor pi L Y_1 = 0.61, so the values are exact to 1e-7; 1e-6 leaves room.
  const double h = 1 / std::sqrt(2.0);
  expect_texels(bake_obj_quad("obj_vn", std::string(kObjQuad) + "vn 2 2 0\nf 1/1/1 2/2/1 3/3/1 4/4/1\n"),
                uniform_hemisphere(0.4, {h, h, 0}), 1e-6);
}

TEST(Lightmap, GltfWithOnlyTexcoord0IsRefusedInOneLine) {
  shpack_test::write_scene("quad_uv0.gltf", gltf_quad(false));
  const Lightmapped b = bake_lightmap_scene("gltf_uv0", R"({
    "environment": {"type": "gradient", "zenith": 0.4, "horizon": 0.4, "ground": 0.4},
    "geometry": [{"type": "mesh", "path": "quad_uv0.gltf", "lightmap": {"resolution": [4, 4]}}],
    "effects": ["environment"]})");
  EXPECT_FALSE(b.status.ok());
  EXPECT_NE(b.status.message.find("only one UV set (TEXCOORD_0)"), std::string::npos) << b.status.message;
  EXPECT_EQ(b.status.message.find('\n'), std::string::npos);
}

TEST(Lightmap, SunAndBoxCastAnExactUmbra) {
  // A delta sun straight down over a box floating above the floor: texels wholly under the
  // box's 1 x 1 m footprint get nothing, the others the sun's closed form E Y_i(up); the box's
  // edges lie on texel edges (8 texels over 4 m), so no texel is partly lit. A delta light
  // takes one shadow ray per point, exact either way.
  const Lightmapped b = bake_lightmap_scene("sun_box", R"({
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 2}],
    "geometry": [)" + floor_plane(8) + R"(,
      {"type": "box", "min": [-0.5, 0.5, -0.5], "max": [0.5, 1, 0.5], "albedo": 0.5}],
    "effects": ["direct", "shadows"]})");
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  const LightmapTexels& map = b.result.maps[0];
  const std::array<double, kShCount> y = eval_basis(0, 1, 0);
  // Texel (i, j): x runs along the plane's up (+X) with u, z along right (+Z) with v... the
  // texel's centre decides: the box covers |x|, |z| < 0.5, i.e. the middle 2 x 2 texels.
  std::size_t dark = 0;
  for (std::size_t t = 0; t < 64; ++t) {
    const bool lit = map.radiance[t].c[0][0] != 0;
    if (!lit) {
      ++dark;
      for (int i = 0; i < kShCount; ++i) EXPECT_EQ(map.radiance[t].c[1][i], 0.0);
      const std::size_t i = t % 8, j = t / 8;
      EXPECT_TRUE(i >= 3 && i <= 4 && j >= 3 && j <= 4) << i << "," << j;
    } else {
      for (int i = 0; i < kShCount; ++i) EXPECT_NEAR(map.radiance[t].c[2][i], 2 * y[i], 1e-12);
    }
  }
  EXPECT_EQ(dark, 4u);
}

TEST(Lightmap, SunPenumbraUnderABoxEdgeIsHalf) {
  // A sun of 10 degrees straight down over a box long in z whose side x = 0.5 rises from 0.5 to
  // 1 m: from a floor point with x = 0.5 exactly, the vertical plane through the edge holds the
  // sun's centre, so the box hides exactly half of the sun's cap (by the symmetry about that
  // plane); points at x = +-1.5 see all of it and are exact. A 2 x 2 map over 4 m puts one
  // column of sub-texel points at x = +-0.5 and one at x = +-1.5, so every texel's L0 is
  // (1/2 + 1/2 + 1 + 1) / 4 = 3/4 of the sun's closed form. The half is estimated from points
  // of the cap; its error is the texel's reported estimate (about 95 %), held to twice it.
  const Lightmapped b = bake_lightmap_scene("penumbra", R"({
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 2, "angular_diameter_deg": 10}],
    "geometry": [)" + floor_plane(2) + R"(,
      {"type": "box", "min": [-0.5, 0.5, -3], "max": [0.5, 1, 3], "albedo": 0.5}],
    "effects": ["direct", "shadows"],
    "settings": {"target_error_pct": 0.5}})");
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  const LightmapTexels& map = b.result.maps[0];
  ShL2 sun;
  ASSERT_TRUE(add_directional_light({0, 1, 0}, 10 * std::numbers::pi / 180, {2, 2, 2}, sun).ok());
  for (std::size_t t = 0; t < 4; ++t) {
    const double want = 0.75 * sun.c[0][0];
    // error_pct is of the texel's mean E/pi, whose L0 part is c_0 Y_0: the L0 error allowed.
    const double allowed = 2 * map.error_pct[t] / 100 * map.radiance[t].c[0][0];
    EXPECT_GT(map.error_pct[t], 0.0f);
    EXPECT_NEAR(map.radiance[t].c[0][0], want, allowed) << t;
  }
}

TEST(Lightmap, TexelsAcrossAShadowEdgeMeetTheTargetAsAWhole) {
  // A sun 40 degrees wide over a box whose edge x = 0 is 1 m above the floor: the penumbra is
  // x in (-tan 20, tan 20) = (-0.36, 0.36), three texels of an 8 x 8 map over 2 m, whose
  // points see different shares m_k of the sun. Held each to sqrt(K) t times its own light,
  // a texel's error reaches t sqrt(K sum m_k^2) / sum m_k > t (Cauchy-Schwarz: equal only
  // for equal m_k); against the texel's mean light it is at most t (bake.cpp, Engine::groups).
  // The bound holds up to the pilot's estimate of that mean (64 samples a point, pooled over
  // the texel's points: a few %), so the test allows 1.1 t.
  const Lightmapped b = bake_lightmap_scene("texel_target", R"({
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1, "angular_diameter_deg": 40}],
    "geometry": [{"type": "plane", "name": "floor", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0],
                  "size": [2, 2], "lightmap": {"resolution": [8, 8]}},
                 {"type": "box", "min": [-100, 1, -100], "max": [0, 2, 100]}],
    "effects": ["direct", "shadows"],
    "settings": {"target_error_pct": 1}})");
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  const LightmapTexels& map = b.result.maps[0];
  // Texels at the umbra's edge (about 1 % of the sun) reach settings.max_samples first: those
  // say so (capped) and are not held to the target.
  constexpr auto kShadows = static_cast<std::size_t>(Effect::Shadows);
  float worst = 0;
  std::size_t capped = 0;
  for (std::size_t t = 0; t < map.state.size(); ++t) {
    if (map.state[t] != TexelState::Baked) continue;
    if (map.sampling[t][kShadows].capped)
      ++capped;
    else
      worst = std::max(worst, map.error_pct[t]);
  }
  EXPECT_LE(capped, 8u);  // one row of the 8
  EXPECT_GT(worst, 0.5f);  // the penumbra's texels are sampled up to their target
  EXPECT_LE(worst, 1.1f);
}

TEST(Lightmap, LightAcrossTheHorizonKeepsItsUpperHalf) {
  // A sphere light whose centre lies in the floor's plane, off the floor: the tangent plane of
  // every floor point holds the direction to its centre, so exactly half its cap is above the
  // horizon and the L0 term is half the closed form (the lift of 1e-4 m tilts that by 3e-5
  // relative). The horizon is the only occluder here: no geometry, no rays.
  const Lightmapped b = bake_lightmap_scene("horizon", R"({
    "lights": [{"type": "sphere", "position": [4, 0, 0], "radius": 0.5, "intensity": 3}],
    "geometry": [)" + floor_plane(2) + R"(],
    "effects": ["direct"],
    "settings": {"target_error_pct": 0.5}})");
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  const LightmapTexels& map = b.result.maps[0];
  // The four texels' points are the 16 points (+-0.5, +-1.5)^2; their mean L0 against half
  // the mean closed form, within twice the worst texel's estimate plus the lift's tilt.
  const scene::SceneLight& light = b.scene.lights[0];
  double got = 0, half = 0, worst = 0;
  for (std::size_t t = 0; t < 4; ++t) {
    got += map.radiance[t].c[0][0] / 4;
    worst = std::max(worst, static_cast<double>(map.error_pct[t]));
  }
  for (const double x : {-1.5, -0.5, 0.5, 1.5})
    for (const double z : {-1.5, -0.5, 0.5, 1.5}) {
      ShL2 whole;
      ASSERT_TRUE(add_sphere_light(light.position, light.radius, light.colour, {x, 0, z}, whole).ok());
      half += 0.5 * whole.c[0][0] / 16;
    }
  EXPECT_GT(worst, 0.0);
  EXPECT_NEAR(got, half, 2 * worst / 100 * got + 1e-4 * half);
}

TEST(Lightmap, FurnaceConvergesToTheAnalyticValue) {
  // A closed box whose walls, and the lightmapped plane inside it, all emit Le and reflect
  // albedo a: after N bounces the radiance leaving every surface is Le (1 + a + ... + a^N),
  // uniform, so the plane's upper hemisphere sees that everywhere (uniform_hemisphere).
  // The Monte Carlo error is bounded by the bake's own estimate (about 95 % confidence); the
  // worst of 16 texels is held to twice the worst estimate.
  const double le = 0.5, a = 0.6;
  const Lightmapped b = bake_lightmap_scene("furnace", R"({
    "geometry": [
      {"type": "box", "min": [-3, -1, -3], "max": [3, 3, 3], "albedo": 0.6, "emission": 0.5},
      {"type": "plane", "name": "floor", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0],
       "size": [2, 2], "albedo": 0.6, "emission": 0.5, "lightmap": {"resolution": [4, 4]}}],
    "effects": ["emission", "bounce:3"],
    "settings": {"target_error_pct": 2, "max_samples": 16384}})");
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  const LightmapTexels& map = b.result.maps[0];
  const ShL2 want = uniform_hemisphere(le * (1 + a + a * a + a * a * a), {0, 1, 0});
  double worst = 0, worst_estimate = 0;
  for (std::size_t t = 0; t < 16; ++t) {
    worst = std::max(worst, shpack_test::max_error_pct(map.radiance[t], want));
    worst_estimate = std::max(worst_estimate, static_cast<double>(map.error_pct[t]));
  }
  EXPECT_GT(worst_estimate, 0.0);
  EXPECT_LE(worst, 2 * worst_estimate);
}

TEST(Lightmap, SameResultForAnyThreadCount) {
  const std::string json = R"({
    "environment": {"type": "gradient", "zenith": [0.2, 0.4, 1.0], "horizon": [0.8, 0.9, 1.0], "ground": 0.1},
    "lights": [{"type": "sphere", "position": [0, 2, 0], "radius": 0.3, "power": 50}],
    "geometry": [)" + floor_plane(6, R"(, "l2": true)") + R"(,
      {"type": "box", "min": [-0.5, 0.5, -0.5], "max": [0.5, 1, 0.5], "albedo": 0.5}],
    "effects": ["direct", "shadows", "environment", "sky_occlusion", "bounce:1"],
    "settings": {"target_error_pct": 0, "sky_samples": 128, "bounce_samples": 64, "shadow_samples": 64}})";
  const Lightmapped one = bake_lightmap_scene("threads_1", json, 1);
  const Lightmapped two = bake_lightmap_scene("threads_2", json, 2);
  ASSERT_TRUE(one.status.ok()) << one.status.message;
  ASSERT_TRUE(two.status.ok()) << two.status.message;
  for (std::size_t t = 0; t < one.result.maps[0].radiance.size(); ++t)
    EXPECT_EQ(one.result.maps[0].radiance[t], two.result.maps[0].radiance[t]) << t;
}

// The raster of one shape (labelled "geometry[0]") on a side x side map.
bool raster_of(const scene::SceneShape& shape, std::uint32_t side, LightmapRaster& raster) {
  scene::LightmapTarget target;
  target.label = "geometry[0]";
  target.width = target.height = side;
  target.shapes = {0};
  std::string error;
  const bool ok = rasterize_lightmap(target, {shape}, raster, error);
  EXPECT_TRUE(ok) << error;
  return ok;
}

TEST(Lightmap, UnusedTexelsAreMarkedAndChartsPadded) {
  // One triangle over the lower-left half of an 8 x 8 map: texels above the diagonal are
  // unused, except those padding reaches (2 rings); none is black-and-used.
  scene::SceneShape tri;
  tri.label = "geometry[0]";
  tri.vertices = {0, 0, 0, 1, 0, 0, 0, 0, 1};
  tri.indices = {0, 1, 2};
  tri.uv = {0, 0, 1, 0, 0, 1};
  LightmapRaster raster;
  ASSERT_TRUE(raster_of(tri, 8, raster));
  double covered = 0;
  for (const float c : raster.coverage) covered += c;
  EXPECT_NEAR(covered, 32.0, 1e-5);  // half of 64 texels, exactly (clipped areas)
  // Row 0 is the top (v = 1): its only used texel is the leftmost, which the diagonal halves.
  EXPECT_NEAR(raster.coverage[0], 0.5, 1e-6);
  EXPECT_EQ(raster.chart[7], -1);
}

TEST(Lightmap, TexelWhereTwoChartsMeetHoldsOnlyTheOneCoveringMostOfIt) {
  // Two charts side by side in the atlas, u in [0, 0.6] and [0.6, 1], one texel over both; on
  // the mesh they are 5 m apart (y = 0 and y = 5). The texel is chart A's (0.6 of it): its
  // points are the sub-square centres A contains (u = 0.25, two of them), none of B's, whose
  // light is another surface's. Its coverage is A's share, 0.6 (clipped areas, exact up to
  // float UVs: 1e-6).
  scene::SceneShape two;
  two.label = "geometry[0]";
  two.vertices = {0, 0, 0, 0.6f, 0, 0, 0.6f, 0, 1, 0, 0, 1, 0.6f, 5, 0, 1, 5, 0, 1, 5, 1, 0.6f, 5, 1};
  two.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  two.uv = {0, 0, 0.6f, 0, 0.6f, 1, 0, 1, 0.6f, 0, 1, 0, 1, 1, 0.6f, 1};
  LightmapRaster raster;
  ASSERT_TRUE(raster_of(two, 1, raster));
  EXPECT_NEAR(raster.coverage[0], 0.6, 1e-6);
  EXPECT_EQ(raster.shared, 1u);
  ASSERT_EQ(raster.points.size(), 2u);
  for (const TexelPoint& p : raster.points) {
    EXPECT_EQ(p.position.y, 0.0);
    EXPECT_NEAR(p.position.x, 0.25, 1e-6);
  }
}

TEST(Lightmap, OverlappingChartsAndBadUvsAreRefused) {
  scene::SceneShape two;
  two.label = "geometry[0] 'quad'";
  two.vertices = {0, 0, 0, 1, 0, 0, 0, 0, 1, 5, 0, 0, 6, 0, 0, 5, 0, 1};
  two.indices = {0, 1, 2, 3, 4, 5};
  two.uv = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};  // the second triangle reuses the first's UVs
  scene::LightmapTarget target;
  target.label = "geometry[0] 'quad'";
  target.width = target.height = 4;
  target.shapes = {0};
  LightmapRaster raster;
  std::string error;
  EXPECT_FALSE(rasterize_lightmap(target, {two}, raster, error));
  EXPECT_NE(error.find("overlap"), std::string::npos) << error;
  two.uv[0] = 1.5f;
  EXPECT_FALSE(rasterize_lightmap(target, {two}, raster, error));
  EXPECT_NE(error.find("outside [0, 1]"), std::string::npos) << error;
}

TEST(Lightmap, HugeResolutionIsRefusedBeforeAllocation) {
  scene::Scene scene;
  const io::IoStatus st = scene::load_scene(shpack_test::write_scene("huge.json", R"({
    "environment": {"type": "gradient", "zenith": 1, "horizon": 1, "ground": 1},
    "geometry": [{"type": "plane", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0], "size": [1, 1],
                  "lightmap": {"resolution": [1000000, 1000000]}}],
    "effects": ["environment"]})"), scene);
  EXPECT_FALSE(st.ok());
  EXPECT_NE(st.message.find("texels a side"), std::string::npos) << st.message;
}

TEST(Lightmap, ImagesPackTheProbesShaderVectors) {
  const Lightmapped b = bake_lightmap_scene("images", R"({
    "environment": {"type": "gradient", "zenith": 0.7, "horizon": 0.7, "ground": 0.7},
    "geometry": [)" + floor_plane(2) + R"(],
    "effects": ["environment"]})");
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  std::vector<LightmapImage> images;
  std::string error;
  ASSERT_TRUE(lightmap_images(b.scene.lightmaps[0], b.result.maps[0], images, error)) << error;
  ASSERT_EQ(images.size(), 4u);  // SHAr, SHAg, SHAb, texels
  // E/pi at the normal, from SHAr: dot(SHAr, (n, 1)). For a uniform L over the upper
  // hemisphere, E(up) = pi L, so E/pi = L = 0.7 (float rounding of the packing: 1e-6).
  const std::vector<float>& a = images[0].pixels;
  EXPECT_NEAR(a[1] + a[3], 0.7, 1e-6);
}

TEST(Lightmap, UnityPackageShipsTheSidecarsHlsl) {
  // The package's include and the sidecar's "hlsl" are one text.
  std::ifstream in(std::string(SHPACK_SOURCE_DIR) + "/unity/Runtime/ShpackLightmap.hlsl", std::ios::binary);
  ASSERT_TRUE(in);
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), lightmap_hlsl());
}

}  // namespace
}  // namespace shpack::bake

namespace shpack::bake {
namespace {

TEST(Lightmap, BundledGltfExampleHasSixChartsThatCoverTheirArea) {
  // bench/scenes/box_lightmap.json (scripts/make_lightmap_example.py): a floor of 0.60 x 0.60
  // of the UV square and five box faces of 0.28 x 0.28 each, 0.04 (2.56 texels) apart, so no
  // texel holds two charts and the clipped coverage of a 64 x 64 map is
  // 64^2 (0.36 + 5 x 0.0784) = 3080.192 texels, exactly up to float rounding.
  scene::Scene scene;
  const io::IoStatus st = scene::load_scene(std::string(SHPACK_SOURCE_DIR) + "/bench/scenes/box_lightmap.json", scene);
  ASSERT_TRUE(st.ok()) << st.message;
  ASSERT_EQ(scene.lightmaps.size(), 1u);
  LightmapRaster raster;
  std::string error;
  ASSERT_TRUE(rasterize_lightmap(scene.lightmaps[0], scene.geometry, raster, error)) << error;
  double covered = 0;
  for (const float c : raster.coverage) covered += c;
  EXPECT_NEAR(covered, 4096 * (0.36 + 5 * 0.0784), 1e-2);
  EXPECT_EQ(raster.shared, 0u);
  std::vector<std::int32_t> charts(raster.chart.begin(), raster.chart.end());
  std::sort(charts.begin(), charts.end());
  charts.erase(std::unique(charts.begin(), charts.end()), charts.end());
  EXPECT_EQ(charts.size(), 7u);  // six charts and -1, the unused texels
}

}  // namespace

}  // namespace shpack::bake
