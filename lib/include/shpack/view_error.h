// view_error.h - the error of what Unity shows: ShadeSH9 on the packed float vectors plus the
// Lambert term of every extracted light, against the exact E/pi of the input map
// (view_reference.h), in percent of the map's mean E/pi.
//
// Directions: kViewErrorDirections points of the spherical Fibonacci set in the map's frame,
//   z_i = 1 - (2 i + 1)/N, phi_i = 2 pi i / golden ratio,
// spaced about sqrt(4 pi / N) = 9 degrees apart. The truth at d_i, in the output's colours and
// frame, is k M E(d_i)/pi (the finish stage's intensity k and colour matrix M), shown by Unity
// at R d_i (its rotation R), where Unity's value is shade_sh9 (unity_pack.h) plus, for each
// light, colour * intensity * max(0, n . -forward) (unity_light.h).
//
// Per channel c with mean m_c = k (M mean)_c of the truth (the largest channel's mean for a
// channel whose mean is not positive):
//   max_pct   = 100 max_i |shown_c(d_i) - truth_c(d_i)| / m_c, over channels too;
//   rms_pct   = 100 max_c sqrt(mean_i (shown - truth)^2) / m_c;
//   bound_pct = 100 max_{i,c} k (|M| bound)_c(d_i) / m_c: each error above is within it of
//               the error against the exact E/pi, up to rounding.
//
// Between the directions (searched_view_error). The 512 directions are also where the lights
// are fitted (light_fit.h), so the error there is a training error: a fitted light's colour
// and direction are exactly what makes it small at them, and the peaks move between them. The
// reported max is therefore searched for: the error at the 512, and, when lights are shown,
// at kViewCheckDirections more (a spherical Fibonacci set of another size, none of whose
// points is one of the 512: z = 1 - (2 j + 1)/1024 is never 1 - (2 i + 1)/512, odd against
// even numerators), then a pattern search from each of the kViewSearchSeeds worst of them
// (at least kViewSeedSeparationDeg apart): kViewSearchPoints points on a circle of radius r
// about the current point, moving to the worst point when it is worse, else halving r, from
// kViewSearchStartDeg down to kViewSearchEndDeg (at most 4 moves at one radius). max_pct,
// its channel and direction, and bound_pct are taken over every direction evaluated; rms_pct
// stays the mean over the 512 (the searched ones are not a uniform sample).
//
// The tolerance. Near its peak the error is Lipschitz with a constant s of about 8 m per
// radian (m the channel's mean): the truth's gradient is |grad E/pi| = |int_{n.w > 0} L w_t dw|
// / pi <= Phi / pi = 4 m (Phi = int L dw = 4 pi m), and what Unity shows tracks it, its own
// slope about as large; the error's is at most their sum. A search ends at a point p not below
// the kViewSearchPoints = 6 points of its last circle, of radius r_end = kViewSearchEndDeg,
// and those 7 points leave no point within r_end of p farther than r_end / sqrt(3) from one of
// them, so nothing within r_end of p is above |e(p)| + s r_end / sqrt(3) = 8 m (pi/180) / 32 /
// sqrt(3) = 0.25 % of m (kViewSearchTolerancePct). Which basins are searched is a choice, not
// a bound: those of the worst 8 of 512 (1536 with lights) well-spread directions.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "shpack/rotate.h"
#include "shpack/status.h"
#include "shpack/unity_light.h"
#include "shpack/unity_pack.h"
#include "shpack/view_reference.h"

namespace shpack {

inline constexpr std::size_t kViewErrorDirections = 512;
inline constexpr std::size_t kViewCheckDirections = 1024;
inline constexpr std::size_t kViewSearchSeeds = 8;
inline constexpr double kViewSeedSeparationDeg = 5.0;  // about the 512's covering radius
inline constexpr int kViewSearchPoints = 6;
inline constexpr double kViewSearchStartDeg = 4.0;
inline constexpr double kViewSearchEndDeg = 1.0 / 32;
inline constexpr double kViewSearchTolerancePct = 0.25;  // 100 s r_end / (sqrt(3) m), derived above

struct ViewError {
  double max_pct = 0, rms_pct = 0, bound_pct = 0;
  int max_channel = 0;  // where max_pct is reached: channel and direction (output frame)
  Dir3 max_direction;
  friend bool operator==(const ViewError&, const ViewError&) = default;
};

// The reference sampled once at the directions above, for any number of comparisons.
struct ViewSamples {
  std::vector<Dir3> directions;         // map frame
  std::vector<ReferenceValue> values;   // the reference there, map colours, unscaled
  std::array<double, 3> mean{};         // mean_e_over_pi
  // The reference itself when the samples were given it (the second sample_view_reference):
  // searched_view_error evaluates it between the directions, on up to `threads` threads.
  std::shared_ptr<const ViewReference> reference;
  unsigned threads = 1;
};

// The i-th of n spherical Fibonacci directions.
Dir3 spherical_fibonacci(std::size_t i, std::size_t n) noexcept;

// The directions are evaluated on up to `threads` threads (0: all cores), each its own slot
// (work_queue.h): the samples do not depend on the thread count.
// Errors: BadSequence (the reference is not finished), OutOfMemory.
Status sample_view_reference(const ViewReference& reference, ViewSamples& out, unsigned threads = 1) noexcept;
// The same, keeping the reference in the samples for searched_view_error.
Status sample_view_reference(ViewReference&& reference, ViewSamples& out, unsigned threads = 1) noexcept;

// What the finish stage did to the map (pipeline.h FinishOptions): the truth is mapped by it.
struct ViewTransform {
  std::optional<Matrix3> colour_matrix;  // none: identity
  double intensity = 1;
  double rotate_deg = 0;
};

// The error of `shown` (the finished, packed SH) and `lights` (finished, in Unity's form)
// against the truth, at the samples' directions.
ViewError unity_view_error(const ViewSamples& samples, const ViewTransform& transform, const UnityShaderVectors& shown,
                           std::span<const UnitySunLight> lights) noexcept;

// The same with its max searched for between the directions (above) when the samples hold
// their reference, else unity_view_error. Errors: OutOfMemory.
Status searched_view_error(const ViewSamples& samples, const ViewTransform& transform, const UnityShaderVectors& shown,
                           std::span<const UnitySunLight> lights, ViewError& out) noexcept;

}  // namespace shpack
