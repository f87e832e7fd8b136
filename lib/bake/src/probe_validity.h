// probe_validity.h (private) - which probes are inside geometry, and what they get instead,
// as Unity's Adaptive Probe Volumes (APV) do it (docs/scenes.md, "Probe validity").
//
// Validity. From each probe, kValidityRays directions: a spherical Fibonacci set (Swinbank
// and Purser, QJRMS 2006), equal-area and well spread, turned by a uniform random rotation
// (Shoemake, "Uniform random rotations", Graphics Gems III, 1992) from the stream keyed by
// (seed, probe), so that no probe's rays line up with the scene's axes and no thread changes
// them. backface_fraction is the share whose first hit is a back face (Hit::backface). A
// plane is an open sheet with no inside, shaded on both sides: it never counts. A probe is
// invalid when the share exceeds settings.validity_threshold: APV's validity is the same
// ratio, its default threshold 0.25 (ProbeDilationSettings.dilationValidityThreshold).
//
// Offset (APV's virtual offset, "offset"). An invalid probe is baked instead at the nearest
// candidate that measures valid: along each of its rays that leaves geometry through a back
// face at distance t, the point kOffsetBias past it (APV's default geometry bias,
// VirtualOffsetSettings.outOfGeoOffset; less if the next surface along the ray is nearer than
// twice that), tried nearest first, within settings.max_offset, at most kOffsetCandidates.
// A probe with none stays invalid and is dilated.
//
// Dilation (APV's dilation with squared-distance weighting, one iteration): an invalid probe
// takes sum_j w_j L_j / sum_j w_j over its kDilationNeighbours nearest valid probes (fewer if
// fewer are valid), w_j = 1 / d_j^2, d_j the distance between the probes' own positions; if
// some lie at distance 0, the plain mean of those. Only valid (or moved) probes are read, so
// the order of the dilated ones does not matter.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "shpack/bake/bake.h"
#include "shpack/io/io_status.h"
#include "shpack/scene/scene.h"
#include "tracer.h"

namespace shpack::bake {

inline constexpr int kValidityRays = 256;
inline constexpr int kOffsetCandidates = 16;
inline constexpr double kOffsetBias = 0.01;  // metres
inline constexpr std::size_t kDilationNeighbours = 8;

// Probe k's validity under the scene's settings: measured at its position and, with
// InvalidProbes::Offset, moved if it is invalid. Its rays' stream is keyed by `stream_id`
// (its number in the whole scene, or a surface point's). Adds the rays traced to `rays`.
ProbeValidity check_probe(const Tracer& tracer, const scene::Scene& scene, std::size_t k, std::uint64_t stream_id,
                          std::uint64_t& rays);

// validity[k] is probe first + k of `scene`'s. "error" with an invalid probe fails naming the
// first and the shape around it; with `whole` (validity holds every probe), "dilate" and
// "offset" fail if probes are left to dilate and none is valid.
io::IoStatus check_invalid_probes(const scene::Scene& scene, const std::vector<ProbeValidity>& validity,
                                  std::size_t first, bool whole);

// The scene with each moved probe at its offset_position; nothing if none moved.
std::optional<scene::Scene> offset_scene(const scene::Scene& scene, const std::vector<ProbeValidity>& validity);

// After the passes ("dilate", "offset"): every invalid probe not moved takes the weighted mean
// of its nearest valid probes, in `radiance` and in each effect's part of `effects` (if kept),
// with its `sampling` (the errors by the same weights), and is marked dilated.
void dilate_invalid_probes(const scene::Scene& scene, std::vector<ProbeValidity>& validity,
                           std::vector<ShL2>& radiance, std::vector<std::array<ShL2, kEffectCount>>& effects,
                           std::vector<std::array<EffectSampling, kEffectCount>>& sampling);

ValidityCounts count_validity(const std::vector<ProbeValidity>& validity);

}  // namespace shpack::bake
