// light_choice.h - which light candidates (light_candidates.h) to take out of a map: chosen
// greedily by how much each lowers the caller's measure of the error of what Unity shows.
//
// The measure is the caller's (the pipeline's: the SH of the map minus the chosen candidates'
// removed SH, finished and packed, plus their Unity lights, against the exact E/pi of the
// map): error_of(chosen, error) sets `error` to the max error, in percent of the mean E/pi,
// with the candidates `chosen` (indices into the candidates, in the order chosen) taken out.
//
// The choice: e_0 = error_of({}); then, while fewer than max_lights are chosen, every
// candidate not yet chosen and sharing no texel with a chosen one (candidates pooled from
// searches at several scales overlap; those of one search never do) is tried as the next one, and the one giving the smallest error is
// chosen if that error is below the current one (strictly: a light that does not lower the
// error is never added); among equal errors the lowest index wins (candidates come brightest
// seed first). It stops when no candidate lowers the error, when max_lights are chosen or when
// none is left. Deterministic: the same measure gives the same choice.
//
// Cost: at most 1 + sum_{s < n} (K - s) calls of error_of for K candidates, N = max_lights and
// n <= min(N, K) steps: at most 1 + K N, and at most K N when K >= 1 and N >= 2 (the sum
// is then at most K N - N (N - 1)/2), and K^2 comparisons of two candidates' texel lists
// (linear in their lengths) as lights are chosen. Nothing else is costly: the candidates carry what the
// measure needs (light_candidates.h), so the map is not read again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "shpack/light_candidates.h"
#include "shpack/status.h"

namespace shpack {

// The caller's measure by reference: neither owned nor copied, so it must outlive the call;
// it must not throw (report a failure through its Status).
class LightErrorMeasure {
 public:
  template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, LightErrorMeasure> &&
             std::is_invocable_r_v<Status, F&, std::span<const std::size_t>, double&>)
  LightErrorMeasure(F&& measure) noexcept  // implicit, so that a lambda can be passed as it is
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(measure)))),
        call_([](void* object, std::span<const std::size_t> chosen, double& error) -> Status {
          return (*static_cast<std::remove_reference_t<F>*>(object))(chosen, error);
        }) {}

  Status operator()(std::span<const std::size_t> chosen, double& error) const { return call_(object_, chosen, error); }

 private:
  void* object_;
  Status (*call_)(void*, std::span<const std::size_t>, double&);
};

// One step of the choice.
struct ChosenLight {
  std::size_t candidate = 0;  // index into the candidates
  double error_before = 0;    // max error with the lights chosen before it
  double error_after = 0;     // with it too: < error_before
  friend bool operator==(const ChosenLight&, const ChosenLight&) = default;
};

struct LightChoice {
  std::vector<ChosenLight> lights;  // in the order chosen
  double error_without = 0;         // e_0, with no light taken out
  std::uint64_t evaluations = 0;    // calls of error_of
  friend bool operator==(const LightChoice&, const LightChoice&) = default;
};

// Chooses up to max_lights of `candidates` as above into `choice`. With `settle`, each step
// ends with settle(chosen, error): the caller may change how it shows the lights chosen so far
// (the pipeline moves their directions, light_fit.h) and lower `error` (never raise it); the
// step's error_after is the settled error, and error_of sees the settled lights from then on.
// Errors: what error_of returns (the choice so far is kept), InvalidArgument when it gives an
// error that is not finite, OutOfMemory.
Status choose_lights(std::span<const LightCandidate> candidates, std::size_t max_lights, LightErrorMeasure error_of,
                     LightChoice& choice, std::optional<LightErrorMeasure> settle = std::nullopt) noexcept;

}  // namespace shpack
