// bake.h - the engine of `shpack bake`: one radiance SH per probe, simulating only the
// effects the scene asks for (docs/scenes.md).
//
// Plan. Each effect is a separate pass over the probes, timed and counted on its own:
//  - direct: every light in closed form (lights.h), no rays.
//  - environment: the environment projected once (an env map exactly as `shpack convert`
//    projects it, or the gradient sky in closed form) and added to every probe, no rays.
//  - shadows: for each (probe, light) pair the planner asks whether any shape's bounding
//    sphere touches the volume between the probe and the light (the segment to a point or spot
//    light, the capsule around the segment to a sphere, disk or rect light, the cone towards
//    a directional light); if none does, the pair costs nothing and the light stays analytic.
//    Otherwise a delta light gets one shadow ray and an extended light is sampled: a cap
//    (sphere light, sun) by a product rule in (cos theta', phi') exact for L2 on every
//    stratum, a rect or disk by stratified points; the blocked part is removed from the closed
//    form, so a light that is all visible or all hidden is exact.
//  - sky_occlusion: stratified directions over the sphere; the environment's radiance in the
//    directions that hit geometry is removed.
//  - emission: the same directions; emissive geometry adds its radiance and, unless
//    sky_occlusion already removed it, hides the environment behind it.
//  - bounce:N: paths from the probe (stratified first directions, cosine-weighted after),
//    with next-event estimation to the lights (always with shadow rays), the environment and
//    the distant lights (hemisphere, ambient) on escape, and emission on hits.
// Each pass adds its own contribution, so turning one effect on changes only its own term
// and its own cost. The sum is convolved and packed once, by the caller (bake_json.h).
//
// Determinism. Every random number comes from a stream seeded by (settings.seed, effect,
// probe, light), never from the thread that runs it, and each probe's sums are formed in a
// fixed order: the result is bit-identical for any thread count.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "shpack/io/io_status.h"
#include "shpack/scene/scene.h"
#include "shpack/sh_basis.h"

namespace shpack::bake {

enum class Effect : std::uint8_t { Direct, Environment, Shadows, SkyOcclusion, Emission, Bounce };
inline constexpr std::size_t kEffectCount = 6;

// "direct", "environment", "shadows", "sky_occlusion", "emission", "bounce".
const char* effect_name(Effect effect) noexcept;

struct EffectCost {
  bool enabled = false;
  double time_ms = 0;          // wall time of the pass
  double cpu_ms = 0;           // CPU time of the pass, all threads (the cost per core)
  std::uint64_t rays = 0;      // rays traced (shadow rays included)
  std::uint64_t samples = 0;   // light samples, directions or paths
  std::uint64_t analytic = 0;  // closed forms evaluated (shadows: pairs that needed no ray)
};

// Building the ray tracer's acceleration structure (only when an effect traces rays).
struct GeometryCost {
  bool built = false;
  double time_ms = 0;
  std::uint64_t triangles = 0, spheres = 0;
};

struct BakeOptions {
  unsigned threads = 0;  // 0: all hardware threads
  // Called from the calling thread about every 100 ms during a pass and once at its end:
  // (pass name, probes done, probe count). May be empty.
  std::function<void(const char* pass, std::size_t done, std::size_t total)> progress;
  bool keep_effects = false;  // fill BakeResult::effects (tests and diagnostics)
};

struct BakeResult {
  std::vector<ShL2> radiance;  // per probe: L_c,i in Unity's frame, all effects summed
  // Per probe and effect, when BakeOptions::keep_effects: effects[probe][effect].
  std::vector<std::array<ShL2, kEffectCount>> effects;
  std::array<EffectCost, kEffectCount> costs{};  // indexed by Effect
  GeometryCost geometry;
};

// Errors name the scene file: an environment map that cannot be read, a probe inside a
// light ("probes[3] (0, 1, 0) is inside lights[2] 'lamp' (sphere)"), Embree failing.
io::IoStatus bake(const scene::Scene& scene, const BakeOptions& options, BakeResult& out);

}  // namespace shpack::bake
