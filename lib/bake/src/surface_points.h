// surface_points.h (private) - the engine baking points on surfaces (lightmap texels'
// samples, lightmap_bake.h) instead of probes: each point gathers the light over the
// hemisphere about its normal (surface_domain.h), with every effect of bake.h.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "shpack/bake/bake.h"
#include "tracer.h"

namespace shpack::bake {

// Surface points carry stream keys of their own, apart from the probes' (a probe's key is its
// number, below 2^32): point k of a scene's lightmap points is kSurfaceStreams + k.
inline constexpr std::uint64_t kSurfaceStreams = std::uint64_t{1} << 40;

// Each point's validity (its backface fraction, probe_validity.h), nothing moved: the caller
// dilates within its charts. stream_ids[k] keys point k's rays.
io::IoStatus surface_validity(const scene::Scene& points, const std::vector<std::uint64_t>& stream_ids,
                              const BakeOptions& options, std::vector<ProbeValidity>& out, EffectCost& cost,
                              GeometryCost& geometry);

struct SurfacePoints {
  std::vector<Vec3d> normals;  // per point, unit
  // Per point, the value it is averaged into (a texel), the points of a group consecutive:
  // settings.target_error_pct is the target of each group's mean, not of each point
  // (bake.cpp, Engine::groups).
  std::vector<std::uint32_t> group;
  std::vector<bool> untargeted;            // per point: the fixed counts, no target
  std::vector<std::uint64_t> stream_ids;   // per point, the key of its streams (sampling.h)
  std::function<std::string(std::size_t)> label;  // names point k in messages
};

// `points.probes` are the points, already lifted off their surface along the normal so that
// rays leaving them do not meet it. Settings (seed, samples, target) are the scene's; each
// point's streams are keyed by its stream id, so its numbers do not depend on which other
// points are baked with it, nor on the threads.
io::IoStatus bake_surface_points(const scene::Scene& points, const SurfacePoints& surface, const BakeOptions& options,
                                 BakeResult& out);

}  // namespace shpack::bake
