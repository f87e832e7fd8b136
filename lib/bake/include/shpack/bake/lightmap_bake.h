// lightmap_bake.h - SH lightmaps: per texel of a shape's lightmap UVs, the SH of the radiance
// arriving over the hemisphere about the surface, in Unity's world frame (docs/lightmaps.md).
//
// Each texel is the mean over the points that stand for its covered footprint
// (lightmap_raster.h); each point is baked by the probes' engine (bake.h) with every effect
// the scene asks for, gathering over its hemisphere only, and lifted off the surface by the
// engine's ray offset. Texels whose points mostly see back faces (under geometry) are invalid
// and take the mean of their valid neighbours in the same chart, ring by ring; then every
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
  double time_ms = 0;                 // the whole lightmap bake, wall time
};

// Errors name the scene file: UVs outside [0, 1], overlapping charts, a lightmap no triangle
// covers, and the probe bake's own errors.
io::IoStatus bake_lightmaps(const scene::Scene& scene, const BakeOptions& options, LightmapBakeResult& out);

}  // namespace shpack::bake
