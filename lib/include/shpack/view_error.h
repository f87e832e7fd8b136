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
#pragma once

#include <array>
#include <span>
#include <vector>

#include <optional>

#include "shpack/rotate.h"
#include "shpack/status.h"
#include "shpack/unity_light.h"
#include "shpack/unity_pack.h"
#include "shpack/view_reference.h"

namespace shpack {

inline constexpr std::size_t kViewErrorDirections = 512;

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
};

// The i-th of n spherical Fibonacci directions.
Dir3 spherical_fibonacci(std::size_t i, std::size_t n) noexcept;

// The directions are evaluated on up to `threads` threads (0: all cores), each its own slot
// (work_queue.h): the samples do not depend on the thread count.
// Errors: BadSequence (the reference is not finished), OutOfMemory.
Status sample_view_reference(const ViewReference& reference, ViewSamples& out, unsigned threads = 1) noexcept;

// What the finish stage did to the map (pipeline.h FinishOptions): the truth is mapped by it.
struct ViewTransform {
  std::optional<Matrix3> colour_matrix;  // none: identity
  double intensity = 1;
  double rotate_deg = 0;
};

// The error of `shown` (the finished, packed SH) and `lights` (finished, in Unity's form)
// against the truth.
ViewError unity_view_error(const ViewSamples& samples, const ViewTransform& transform, const UnityShaderVectors& shown,
                           std::span<const UnitySunLight> lights) noexcept;

}  // namespace shpack
