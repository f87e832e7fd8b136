// light_candidates.h - the compact bright sources of an equirect map, each a candidate to be
// taken out of the map as a Unity directional light (unity_light.h): a sun, a lamp, a
// softbox, a window. They are found once, with everything a choice among them needs (the
// light, and the SH of what taking it out removes), so that the choice (light_choice.h) never
// reads the map again; remove_light_candidates takes chosen ones out of the pixels, for a caller
// that wants the map without them (the pipeline fits the lights instead, light_fit.h).
// The single brightest source of `--extract-sun` is light_extraction.h's.
//
// Finding them, with the luminance Y = w . rgb and the value policies of light_extraction.h
// (SunSearch), repeats until max_candidates are found or a stop below is reached:
//  1. the seed: the free texel of largest Y, the first in row-major order among equal ones
//     (every texel is free at the start). Stop when no texel is free, when the seed's Y is
//     not above the map's mean Y (sum_t Y_t Omega_t / 4 pi: a source no brighter than the
//     average carries at most its solid angle's share of the map's flux, a few percent), or
//     after kLightMaxSeeds seeds;
//  2. the region: the free texels connected to the seed (8 neighbours; rows continue across
//     the left and right edges, and a pole row's neighbours over the pole are half a turn
//     away) whose Y is at least kLightThreshold times the seed's. Its texels are taken;
//  3. it must be compact: its radius r, the largest angle between its centre c (the unit
//     vector along sum_t int_t w dw over its texels) and a texel centre, plus half a texel
//     diagonal, is at most kLightMaxRadiusDeg. The growth stops as soon as a texel is more
//     than twice that from the seed (no region holding it is compact), so that an overcast
//     sky or a bright wall is refused after a bounded amount of work; the texels reached so
//     far are taken, the rest stays free;
//  4. what is near joins it: the free texels as bright (step 2's threshold) within
//     r + kSunRingGapDeg of c, connected or not (a flare texel beside a sun, the panes of a
//     window split by a dark bar: the sun's disc holds every bright texel near its peak),
//     are taken into the region; c and r are computed again and r must still pass step 3;
//  5. the level around it L_ring (per channel): the solid-angle-weighted mean of every texel,
//     free or not, from r + kSunRingGapDeg to r + kSunRingGapDeg + kSunRingWidthDeg of c, as
//     the sun's sky level (light_extraction.h);
//  6. it must stand out: the seed's Y >= Y(L_ring) / kLightThreshold (a contrast of 20). So
//     every texel of the region is at least as bright as its ring
//     (LightScale below: the same with another threshold and radius);
//  7. it must matter: what its removal takes away, sum_t Y(e_t) Omega_t (below), is at least
//     kLightMinFluxShare of the map's sum_t Y_t Omega_t. A light of share s changes E/pi
//     nowhere by more than 4 s of its mean (its E/pi is at most its flux / pi, and the mean
//     of E/pi over all normals is the map's flux / (4 pi)), too little for a light of its own.
// A region passing 3 to 7 is a candidate, and every texel within the ring's outer edge of c is
// taken as well (a source there would have been counted in this one's level); one failing is
// dropped, its texels staying taken. So candidates are disjoint, come in decreasing order of
// their seeds' Y, and each is judged only once. A sun (0.27 degrees, blurred by the camera to
// a few), a lamp, a softbox or a window up to ~2 kLightMaxRadiusDeg across passes; an overcast
// sky, a bright wall or a hemisphere fails step 3, and a bright patch on a bright ground fails
// step 6.
//
// Removing one: each of its texels is set to its fill level L_ring (rounded to float, as the
// texel holds it). What is removed, e_t = L_t - L_ring per channel, gives the light as
// light_extraction.h states it for the sun: its direction d along the luminance-weighted flux
// vector, its irradiance E_c = d . m_c (within a factor cos a of the removed flux
// sum_t e_t,c Omega_t for a region of angular radius a about d), and the radiance SH of the
// removal sum_t e_t,c int_t Y_i dw (the projector's exact texel integrals, project.h), in
// Unity's frame: the projection of the map with it removed is the map's less this SH, to the
// float rounding of L_ring (2^-24 L_ring per texel). Light and SH are in the map's frame and
// colours, unscaled, like the projection of the map: the pipeline's finish stage treats them
// as it treats the map.
//
// Costs: one pass over the map for the mean and the seeds, then per seed its region, and per
// region passing step 3 walks over discs a little wider than it (steps 4 and 5, and the
// taking of a candidate's surroundings), each over the rows and columns it spans. Memory: a
// byte a texel while searching, and each candidate's texel list (8 bytes a texel).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "shpack/image_view.h"
#include "shpack/light_extraction.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

inline constexpr double kLightThreshold = 0.05;                  // of the seed's luminance, step 2
inline constexpr double kLightMaxRadiusDeg = 12.0;               // step 3: a window ~20 degrees across
inline constexpr double kLightMinFluxShare = 0.0005;             // step 7: 0.05%
inline constexpr std::size_t kLightMaxSeeds = 256;               // step 1
inline constexpr std::size_t kLightCandidateCount = 16;          // what a caller asks for by default

// The scale of one search: step 2's threshold (step 6's contrast being its inverse, so that
// every texel of a region is at least as bright as its ring) and step 3's largest radius.
// The defaults are the constants above.
struct LightScale {
  double threshold = kLightThreshold;
  double max_radius_deg = kLightMaxRadiusDeg;
};

// The scales `--extract-lights` searches at (pipeline.h), each on the whole map, their
// candidates pooled for one choice (light_choice.h, which never takes two that share a texel):
// a threshold of 5 % keeps a source's soft halo with it, 10 % and 20 % split a bright cluster
// (a softbox beside its reflection, a lamp on a lit wall) into the parts Unity's lights show
// best; regions up to 25 degrees take in a window or a patch of sky. Measured on the bundled
// maps (docs/accuracy.md), each scale is the best one on some map.
inline constexpr std::array<LightScale, 3> kLightChoiceScales = {{{0.05, 25.0}, {0.1, 25.0}, {0.2, 25.0}}};

// A texel of the map: column x from the left, row y from the top.
struct LightTexel {
  std::uint32_t x = 0, y = 0;
  friend bool operator==(const LightTexel&, const LightTexel&) = default;
};

struct LightCandidate {
  // As extract_sun's: direction, irradiance, `sky` the fill level L_ring its texels are set
  // to, radius r of step 3 (degrees), solid angle and count of its texels.
  SunLight light;
  double peak = 0;                 // Y of its seed
  ShL2 removed;                    // radiance SH of what removing it takes away (above)
  std::vector<LightTexel> texels;  // its texels, row-major

  friend bool operator==(const LightCandidate&, const LightCandidate&) = default;
};

// Finds up to max_candidates candidates of an equirect view (resolve_view is applied) of F32
// texels (1 channel grey, or R, G, B first) into `candidates` (cleared first), in the order
// found, with the threshold and largest radius of `scale`. The map is only read.
// Errors: BadView (resolve_view), InvalidArgument for a view that is not F32, OutOfMemory.
Status find_light_candidates(const ImageView& image, const SunSearch& search, std::size_t max_candidates,
                             std::vector<LightCandidate>& candidates, const LightScale& scale = {}) noexcept;

// The searches at each of `scales` (in that order) on one map, their candidates pooled into
// `candidates` (cleared first): those of one search are disjoint, those of two may share
// texels. What the searches share, the map's mean luminance and the first pass over its
// tiles, is done once. Errors: those of find_light_candidates.
Status find_light_candidates_at_scales(const ImageView& image, const SunSearch& search, std::size_t max_candidates,
                                       std::span<const LightScale> scales,
                                       std::vector<LightCandidate>& candidates) noexcept;

// True when the two candidates share a texel (their texels are row-major, as found).
bool share_a_texel(const LightCandidate& a, const LightCandidate& b) noexcept;

// Sets the texels of candidates[k] for every k in `chosen` to its fill level in `pixels`, the
// writable packed memory the view points into (as extract_sun), so that the projector sees the
// rest of the map. Nothing is written if it fails.
// Errors: BadView (resolve_view), InvalidArgument for a view that is not writable packed F32,
// an index not below candidates.size() or a texel outside the view.
Status remove_light_candidates(const ImageView& image, float* pixels, std::span<const LightCandidate> candidates,
                               std::span<const std::size_t> chosen) noexcept;

}  // namespace shpack
