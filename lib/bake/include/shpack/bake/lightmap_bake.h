// lightmap_bake.h - SH lightmaps: per texel of a shape's lightmap UVs, the SH of the radiance
// arriving over the hemisphere about the surface, in Unity's world frame (docs/lightmaps.md).
//
// Each texel is the mean over the points that stand for its covered footprint
// (lightmap_raster.h); each point is baked by the probes' engine (bake.h) with every effect
// the scene asks for, gathering over its hemisphere only, and lifted off the surface by the
// engine's ray offset. Texels whose points mostly see back faces (under geometry) are invalid
// and take the mean of their valid neighbours in the same chart, ring by ring (a chart with
// no valid texel keeps them as baked, at the fixed sample counts); then every
// chart is padded by `padding` rings of unused texels, each the mean of its filled neighbours
// of one chart, so that bilinear filtering does not bleed black or another chart's light.
// Deterministic for any thread count, as the probe bake.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shpack/bake/bake.h"

namespace shpack::bake {

enum class TexelState : std::uint8_t { Unused, Baked, Dilated, Padded };

struct LightmapTexels {
  std::uint32_t width = 0, height = 0;
  std::vector<ShL2> radiance;         // per texel, row 0 at the top: L_c,i in Unity's frame
  std::vector<TexelState> state;
  std::vector<float> coverage;        // the share of the texel's square its chart covers
  std::vector<float> error_pct;       // per texel, % of its own mean E/pi (Baked texels)
  std::vector<float> backface;        // per texel, mean backface fraction of its points
  // Per Baked texel and effect, as the probes' BakeResult::effects and ::sampling (the mean
  // of its points; samples per point, their mean; the error that of the mean), when
  // BakeOptions::keep_effects; zero for the other texels (dilation and padding fill only
  // `radiance`).
  std::vector<std::array<ShL2, kEffectCount>> effects;
  std::vector<std::array<EffectSampling, kEffectCount>> sampling;
  std::uint64_t points = 0;           // baked points
  std::uint64_t degenerate = 0;       // triangles without area, skipped
  std::uint64_t shared = 0;           // texels two charts cover, each holding the one covering most of it
  std::uint64_t used = 0, dilated = 0, padded = 0, invalid_kept = 0;
};

struct LightmapBakeResult {
  std::vector<LightmapTexels> maps;   // one per Scene::lightmaps entry
  std::array<EffectCost, kEffectCount> costs{};
  GeometryCost geometry;
  EffectCost validity_cost;
  double time_ms = 0;                 // the whole lightmap bake, wall time (merged: the parts' sum)
};

// Errors name the scene file: UVs outside [0, 1], overlapping charts, a lightmap no triangle
// covers, and the probe bake's own errors. It is bake_lightmap_texels of every used texel,
// then finish_lightmaps.
io::IoStatus bake_lightmaps(const scene::Scene& scene, const BakeOptions& options, LightmapBakeResult& out);

// ---- The parts of a lightmap bake that shards split (bake_part.h) ----
// The used texels (those a triangle covers) of all of a scene's lightmaps are numbered map
// after map, texel by texel in each map's row order.
struct TexelRef {
  std::uint32_t map = 0;    // index into Scene::lightmaps
  std::uint32_t texel = 0;  // row * width + column
  friend bool operator==(const TexelRef&, const TexelRef&) = default;
};

// Used texels baked, before dilation and padding, which need their charts: per texel its
// value, error estimate (% of its mean E/pi), mean backface fraction of its points, and
// whether none of its points is valid (for dilation); effects and sampling per texel when
// BakeOptions::keep_effects, else empty.
struct LightmapTexelPart {
  std::vector<TexelRef> texels;
  std::vector<ShL2> radiance;
  std::vector<float> error_pct, backface;
  std::vector<std::uint8_t> invalid;
  std::vector<std::array<ShL2, kEffectCount>> effects;
  std::vector<std::array<EffectSampling, kEffectCount>> sampling;
  std::array<EffectCost, kEffectCount> costs{};
  GeometryCost geometry;
  EffectCost validity_cost;
  double time_ms = 0;  // wall time of baking these texels
};

// The number of points of each used texel, in the numbering above (the planner's cost).
io::IoStatus lightmap_texel_points(const scene::Scene& scene, std::vector<std::uint32_t>& points);

// Used texels [first, first + count) baked: each point's streams are keyed by its number
// among all of the scene's lightmap points, so a texel's numbers are the same whichever
// slice bakes it.
io::IoStatus bake_lightmap_texels(const scene::Scene& scene, const BakeOptions& options, std::size_t first,
                                  std::size_t count, LightmapTexelPart& out);

// Every map from the part of every used texel, in order: invalid texels dilated within their
// charts (a chart with no valid texel keeps them as baked), charts padded.
io::IoStatus finish_lightmaps(const scene::Scene& scene, const LightmapTexelPart& all, LightmapBakeResult& out);

}  // namespace shpack::bake
