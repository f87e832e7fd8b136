// batch_sampling.h (private) - how many samples a Monte Carlo effect takes at one probe.
//
// An effect's estimate at a probe is the mean of kBatches independent replicates (batches),
// each over the same number m of samples (error_estimate.h). With a target (scene
// settings.target_error_pct > 0), m starts at kFirstRound and doubles, every batch keeping
// the samples it has (sobol.h), until the estimated error in % of the probe's mean E/pi is
// at most the target or kBatches * m would pass settings.max_samples; with no target, m is
// the fixed count split over the batches. The probe's mean E/pi is that of `probe_total`, an
// estimate of the probe's whole light (bake.cpp's pilot).
#pragma once

#include <algorithm>
#include <cstdint>

#include "error_estimate.h"

namespace shpack::bake {

inline constexpr std::uint32_t kFirstRound = 32;  // per batch: 256 samples to begin with
// Batches that all agree are no evidence of no error: a window that none of the first samples
// went through leaves every batch the same. So an estimate of no spread stops only after
// kBatches * m >= kTrustedAgreement samples, which see with 95 % probability any part of the
// sampling domain larger than 3 / 1024 of it (the rule of three).
inline constexpr std::uint64_t kTrustedAgreement = 1024;

struct SamplePlan {
  double target_pct = 0;     // 0: a fixed count
  std::uint64_t fixed = 0;   // samples per probe (per light) without a target
  std::uint64_t cap = 0;     // at most this many with a target
  bool measure = true;       // false: the value alone, no error estimate (bake.cpp's pilot)
};

struct Estimate {
  ShL2 value;                // the mean of the batches
  ChannelError error{};      // estimate_error of it
  std::uint64_t samples = 0; // kBatches * m
  bool capped = false;       // the cap stopped it above the target
};

inline std::uint32_t per_batch(std::uint64_t samples) noexcept {
  return static_cast<std::uint32_t>(std::clamp<std::uint64_t>((samples + kBatches - 1) / kBatches, 1, 1u << 28));
}

// state.extend(b, from, to) adds samples [from, to) to batch b; state.value(b, m) is batch b's
// estimate from its first m samples.
template <class State>
Estimate run_batches(const SamplePlan& plan, const ShL2& probe_total, State& state) {
  const bool adaptive = plan.target_pct > 0;
  std::uint32_t done = 0;
  std::uint32_t m = adaptive ? std::min(kFirstRound, per_batch(plan.cap)) : per_batch(plan.fixed);
  Batches batches;
  for (;;) {
    for (int b = 0; b < kBatches; ++b) {
      state.extend(b, done, m);
      batches[b] = state.value(b, m);
    }
    done = m;
    const std::uint64_t samples = std::uint64_t{kBatches} * m;
    const bool last = !adaptive || std::uint64_t{kBatches} * 2 * m > plan.cap;
    // While even the pointwise bound misses the target, the full estimate cannot meet it.
    if (!last && error_pct(pointwise_error(batches), probe_total) > plan.target_pct) {
      m *= 2;
      continue;
    }
    if (!adaptive && !plan.measure) return {batch_mean(batches), {}, samples, false};
    Estimate e{batch_mean(batches), estimate_error(batches), samples, false};
    if (!adaptive) return e;
    const bool agree = std::all_of(e.error.begin(), e.error.end(), [](double v) { return v == 0; });
    if (error_pct(e.error, probe_total) <= plan.target_pct && (!agree || e.samples >= kTrustedAgreement)) return e;
    if (last) {
      e.capped = true;
      return e;
    }
    m *= 2;
  }
}

}  // namespace shpack::bake
