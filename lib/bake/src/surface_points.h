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

// Each point's validity (its backface fraction, probe_validity.h), nothing moved: the caller
// dilates within its charts, and bakes only the points worth baking.
io::IoStatus surface_validity(const scene::Scene& points, const BakeOptions& options,
                              std::vector<ProbeValidity>& out, EffectCost& cost, GeometryCost& geometry);

// `points.probes` are the points, already lifted off their surface along the normal so that
// rays leaving them do not meet it; normals[k] is point k's unit normal; label(k) names it in
// messages. Settings (seed, samples, target) are the scene's; the stream of point k is keyed
// by k, so the caller passes the points in an order of their own, independent of threads.
// group[k] is the value point k is averaged into (a texel), the points of a group consecutive:
// settings.target_error_pct is the target of each group's mean, not of each point (bake.cpp,
// Engine::groups).
io::IoStatus bake_surface_points(const scene::Scene& points, const std::vector<Vec3d>& normals,
                                 const std::vector<std::uint32_t>& group,
                                 const std::function<std::string(std::size_t)>& label, const BakeOptions& options,
                                 BakeResult& out);

}  // namespace shpack::bake
