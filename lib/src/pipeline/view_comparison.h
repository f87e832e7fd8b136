// view_comparison.h (private) - what Unity shows against the truth at one direction
// (view_error.h states the measure), shared by the measure at the samples (view_error.cpp)
// and the search between them (view_error_search.cpp).
#pragma once

#include <array>
#include <span>

#include "shpack/view_error.h"

namespace shpack::detail {

// One direction's errors: per channel, % of the channel's mean; where Unity shows it (output
// frame); the largest channel's bound, % of its mean.
struct PointError {
  std::array<double, 3> error{};
  Dir3 shown_at;
  double bound = 0;
  double worst() const noexcept;
};

class ViewComparison {
 public:
  ViewComparison(const ViewSamples& samples, const ViewTransform& finish, const UnityShaderVectors& shown,
                 std::span<const UnitySunLight> lights) noexcept;

  // False for a black map (no positive channel mean): nothing to be wrong about.
  bool active() const noexcept { return active_; }
  // At direction d of the map's frame, whose reference value is v.
  PointError at(const Dir3& d, const ReferenceValue& v) const noexcept;
  // Folds a point into max_pct, max_channel, max_direction and bound_pct.
  static void fold(const PointError& p, ViewError& e) noexcept;

 private:
  const ViewTransform& finish_;
  const UnityShaderVectors& shown_;
  std::span<const UnitySunLight> lights_;
  std::array<double, 3> mean_{};
  Matrix3 rotation_{};
  bool active_ = false;
};

}  // namespace shpack::detail
