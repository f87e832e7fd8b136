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
//    Otherwise a delta light gets one shadow ray and an extended light is sampled: points
//    uniform in solid angle over a cap (sphere light, sun) or by area over a rect or disk,
//    from Owen-scrambled Sobol nets (sobol.h); the blocked part is removed from the closed
//    form, so a light that is all visible or all hidden is exact.
//  - sky_occlusion: directions uniform on the sphere and drawn by the environment's
//    brightness (its texels), combined by multiple importance sampling; the environment's
//    radiance in the directions that hit geometry is removed, exactly all or none of it when
//    everything or nothing is hidden.
//  - emission: directions uniform on the sphere and points of the emissive shapes (by
//    power), combined the same way; emissive geometry adds its radiance and, unless
//    sky_occlusion already removed it, hides the environment behind it.
//  - bounce:N: paths from the probe (uniform first directions, cosine-weighted after), with
//    next-event estimation from every vertex to the lights (shadow rays), the emissive
//    shapes and the environment, the last two weighed against the path's own direction by
//    multiple importance sampling; the distant lights (hemisphere, ambient) where paths
//    escape. No Russian roulette: paths end after N bounces, at most N + 1 segments, and
//    ending them early at random would add variance to save little.
// Every random effect estimates each probe as the mean of 8 independent batches, whose spread
// gives the probe's error estimate (error_estimate.h); with settings.target_error_pct each
// probe doubles its samples until the estimate meets the target or settings.max_samples
// (batch_sampling.h), measured against the probe's whole light from a short pilot of every
// effect. EffectSampling reports what each effect took and how wrong it may still be.
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
#include <optional>
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

// The costs of two passes over parts of the receivers, as one: counts and times summed.
void add_cost(EffectCost& into, const EffectCost& from) noexcept;

// Building the ray tracer's acceleration structure (when the scene has geometry: an effect
// that traces rays, or probe validity, needs it).
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
  // Next-event estimation toward emissive shapes and the environment (importance sampled),
  // weighed against the directions' own strategies by multiple importance sampling. false:
  // those strategies alone (uniform from the probe, cosine-weighted at surfaces), the former
  // estimators' design, kept for the accuracy study's comparison (`shpack bench SCENE.json`).
  bool next_events = true;
};

// ---- Probe validity (docs/scenes.md, "Probe validity"; lib/bake/src/probe_validity.h) ----
// As Unity's Adaptive Probe Volumes: a probe whose rays mostly meet back faces is inside
// geometry, and settings.invalid_probes says what it gets instead.
struct ProbeValidity {
  double backface_fraction = 0;  // share of its rays whose first hit is a back face
  bool valid = true;             // backface_fraction <= settings.validity_threshold
  // The shape most of its back-face rays hit (index into Scene::geometry), if any did.
  std::optional<std::uint32_t> backface_shape;
  // "offset": the point it was baked at instead, and the share of back faces seen from there.
  std::optional<Point3> offset_position;
  double offset_backface_fraction = 0;
  bool dilated = false;  // its SH is the distance-weighted mean of its nearest valid probes
};

struct ValidityCounts {
  std::size_t invalid = 0;  // probes with valid == false
  std::size_t moved = 0;    // of those, baked at an offset_position
  std::size_t dilated = 0;  // of those, dilated
};

// How one Monte Carlo effect (shadows, sky_occlusion, emission, bounce) sampled one probe.
struct EffectSampling {
  std::uint64_t samples = 0;  // per probe (shadows: per light, the most any light took)
  bool capped = false;        // settings.max_samples stopped it above settings.target_error_pct
  // The estimated error (about 95 % confidence) of the largest |error of E/pi| over
  // directions, per channel, in E/pi units; error_pct: in % of the probe's mean E/pi, the
  // worst channel.
  std::array<double, 3> error{};
  double error_pct = 0;
};

struct BakeResult {
  std::vector<ShL2> radiance;  // per probe: L_c,i in Unity's frame, all effects summed
  // Per probe and effect, when BakeOptions::keep_effects: effects[probe][effect].
  std::vector<std::array<ShL2, kEffectCount>> effects;
  std::array<EffectCost, kEffectCount> costs{};  // indexed by Effect
  std::vector<std::array<EffectSampling, kEffectCount>> sampling;  // per probe and effect
  std::vector<double> error_estimate_pct;  // per probe: every effect's error together, % of its mean E/pi
  GeometryCost geometry;
  // Probe validity, one per probe (all valid when the scene has no geometry), and its cost
  // (samples: probes measured; rays: validity and offset rays).
  std::vector<ProbeValidity> validity;
  ValidityCounts validity_counts;
  EffectCost validity_cost;
};

// Errors name the scene file: an environment map that cannot be read, a probe inside a
// light ("probes[3] (0, 1, 0) is inside lights[2] 'lamp' (sphere)"), Embree failing.
// It is bake_probe_range over every probe, then finish_probes.
io::IoStatus bake(const scene::Scene& scene, const BakeOptions& options, BakeResult& out);

// The probes' part of a bake that needs no other probe: probes [first, first + count) of the
// scene (a shard's, bake_part.h) measured for validity, moved by "offset", and baked; `out`
// holds those count probes, radiance, sampling and validity, but no error_estimate_pct nor
// validity_counts. Each probe's streams are keyed by its number in the whole scene, so its
// numbers are the same whichever slice bakes it. "error" refuses an invalid probe here.
io::IoStatus bake_probe_range(const scene::Scene& scene, const BakeOptions& options, std::size_t first,
                              std::size_t count, BakeResult& out);

// The rest, over every probe of the scene in `result` (the ranges' results in order): the
// invalid probes' dilation from the valid ones, each probe's error estimate, the counts.
// Errors: no valid probe to dilate from.
io::IoStatus finish_probes(const scene::Scene& scene, BakeResult& result);

}  // namespace shpack::bake
