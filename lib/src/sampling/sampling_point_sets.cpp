// mc:N, qmc:N, fib:N: the equal-weight rule (4 pi / N) sum_k L(w_k) Y(w_k) over three point
// sets (sampling_points.h): i.i.d. uniform, digitally shifted Sobol, spherical Fibonacci.
#include <numbers>
#include <random>

#include "sampling/sampling_estimator.h"
#include "sampling/sampling_points.h"
#include "sampling/sampling_projectors.h"

namespace shpack::detail {

Status project_point_set(const ImageView& image, const MethodSpec& spec,
                         const ProjectOptions& options, ShL2& radiance,
                         ProjectStats* stats) noexcept {
  const std::uint32_t n = spec.param;
  const double scale = 4.0 * std::numbers::pi / n;
  switch (spec.method) {
    case SamplingMethod::MonteCarlo: {
      std::mt19937_64 rng(spec.seed);
      auto next = [&rng]() noexcept {
        const double u1 = uniform01(rng);
        return Sample{sphere_point(u1, uniform01(rng)), 1.0};
      };
      return project_samples(image, options, n, next, scale, radiance, stats);
    }
    case SamplingMethod::QuasiMonteCarlo: {
      // Two 32-bit digital shifts from the top and bottom halves of one output.
      std::mt19937_64 rng(spec.seed);
      const std::uint64_t bits = rng();
      const auto shift1 = static_cast<std::uint32_t>(bits >> 32);
      const auto shift2 = static_cast<std::uint32_t>(bits);
      std::uint32_t k = 0;
      auto next = [&]() noexcept {
        const SobolPoint p = sobol_point(k++, shift1, shift2);
        // The centre of the point's 2^-32 cell, so that no coordinate is exactly 0 or 1.
        return Sample{sphere_point((p.u1 + 0.5) * 0x1p-32, (p.u2 + 0.5) * 0x1p-32), 1.0};
      };
      return project_samples(image, options, n, next, scale, radiance, stats);
    }
    case SamplingMethod::Fibonacci: {
      std::uint64_t k = 0;
      auto next = [&]() noexcept { return Sample{fibonacci_point(k++, n), 1.0}; };
      return project_samples(image, options, n, next, scale, radiance, stats);
    }
    default:
      return Status::error(Errc::InvalidArgument, "not a point-set method");
  }
}

}  // namespace shpack::detail
