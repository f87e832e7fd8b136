#include "shpack/light_choice.h"

#include <algorithm>
#include <cmath>
#include <new>

namespace shpack {
namespace {

// error_of on one set, counted, with a non-finite error refused.
Status measure(const LightErrorMeasure& error_of, std::span<const std::size_t> chosen, LightChoice& choice,
               double& error) {
  ++choice.evaluations;
  if (Status st = error_of(chosen, error); !st.ok()) return st;
  if (!std::isfinite(error)) return Status::error(Errc::InvalidArgument, "the light error measure is not finite");
  return Status::success();
}

// The greedy steps of light_choice.h; may throw std::bad_alloc (the chosen set).
Status choose(std::span<const LightCandidate> candidates, std::size_t max_lights, const LightErrorMeasure& error_of,
              const std::optional<LightErrorMeasure>& settle, LightChoice& choice) {
  const std::size_t count = candidates.size();
  if (Status st = measure(error_of, {}, choice, choice.error_without); !st.ok()) return st;
  const std::size_t steps = std::min(max_lights, count);  // at most
  std::vector<std::size_t> trial;  // the chosen ones, then the one tried
  trial.reserve(steps);
  std::vector<bool> taken(count, false);
  double current = choice.error_without;
  while (trial.size() < steps) {
    std::size_t best = count;
    double best_error = current;
    trial.push_back(0);
    for (std::size_t k = 0; k < count; ++k) {
      if (taken[k]) continue;
      trial.back() = k;
      double error = 0;
      if (Status st = measure(error_of, trial, choice, error); !st.ok()) return st;
      if (error < best_error) best = k, best_error = error;  // strict: the lowest index keeps a tie
    }
    if (best == count) break;
    trial.back() = best;
    if (settle) {
      double settled = best_error;
      if (Status st = (*settle)(trial, settled); !st.ok()) return st;
      if (!std::isfinite(settled) || settled > best_error)
        return Status::error(Errc::InvalidArgument, "settling the lights raised the error");
      best_error = settled;
    }
    for (std::size_t k = 0; k < count; ++k)  // itself, and every candidate sharing a texel with it
      if (!taken[k]) taken[k] = k == best || share_a_texel(candidates[best], candidates[k]);
    choice.lights.push_back({best, current, best_error});
    current = best_error;
  }
  return Status::success();
}

}  // namespace

Status choose_lights(std::span<const LightCandidate> candidates, std::size_t max_lights, LightErrorMeasure error_of,
                     LightChoice& choice, std::optional<LightErrorMeasure> settle) noexcept {
  choice = {};
  try {
    choice.lights.reserve(std::min(max_lights, candidates.size()));
    return choose(candidates, max_lights, error_of, settle, choice);
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the chosen lights");
  }
}

}  // namespace shpack
