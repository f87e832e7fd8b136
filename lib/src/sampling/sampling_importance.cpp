// is:N - importance sampling of the texels by luminance, with a defensive floor.
//
//   P_t = q_t / Q,  q_t = (max(lum_t, 0) + eps * mean) * Omega_t,  Q = sum_t q_t,
//   mean = sum_t lum_t Omega_t / (4 pi)          (eps = kImportanceFloor)
//
// A sample draws texel t with probability P_t, then a direction w uniform in solid angle
// inside t (cos(theta) uniform between the row's edges, lon uniform across the column), so
// w has density P_t / Omega_t and the term L_t Y(w) Omega_t / P_t is an unbiased estimate
// of int L Y dw over the piecewise-constant image. The sampled texel is read directly (it
// is, by construction, the texel w falls in), so no rounding at a texel edge can pair a
// value with the wrong probability.
//
// The CDF is one double per texel, cumulated in row-major order. P_t is taken as the
// difference of consecutive CDF entries, the very numbers the search compares against, so
// the probabilities used in the estimate are those the sampler realises. With the floor,
// every q_t >= eps/(1 + eps) Omega_t Q / (4 pi) ~ 0.2 Q/(W H), far above the CDF's rounding
// (~ 2^-53 Q) for any image that fits in memory.
#include <algorithm>
#include <cmath>
#include <new>
#include <random>
#include <vector>

#include "common/accumulate.h"
#include "common/angles.h"
#include "projection/equirect_weights.h"
#include "sampling/importance_density.h"
#include "sampling/sampling_estimator.h"
#include "sampling/sampling_points.h"
#include "sampling/sampling_projectors.h"

namespace shpack::detail {
namespace {

// Exact solid angle of every texel of row j (equirect_weights.h: the k0 weight is the
// integral of P_0 = 1 over one texel).
double row_solid_angle(std::uint32_t j, std::uint32_t height, std::uint32_t width) noexcept {
  return exact_row_weights(j, height, width).k0;
}

}  // namespace

Status project_importance(const ImageView& image, std::uint32_t n, std::uint64_t seed,
                          const ProjectOptions& options, ShL2& radiance,
                          ProjectStats* stats) noexcept {
  const std::uint32_t width = image.width, height = image.height;
  std::vector<double> cdf;
  std::vector<float> planes;
  try {
    cdf.resize(std::size_t{width} * height);
    planes.resize(std::size_t{3} * width);
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the importance-sampling CDF");
  }

  // Pass 1: every texel once, row by row with the row loader of project_equirect (this is
  // where the value policies and ProjectStats come from); cdf[t] = max(lum_t, 0) Omega_t.
  TexelCounts counts;
  NeumaierSum luminance_integral;
  for (std::uint32_t y = 0; y < height; ++y) {
    if (Status st = load_image_row(image, y, options, planes, counts); !st.ok()) return st;
    const double omega = row_solid_angle(y, height, width);
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::array<double, 3> rgb = {planes[x], planes[width + x],
                                         planes[2 * std::size_t{width} + x]};
      const double q = std::max(luminance(rgb), 0.0) * omega;
      cdf[std::size_t{y} * width + x] = q;
      luminance_integral.add(q);
    }
  }
  // Pass 2: add the floor and cumulate. An image with no positive luminance is sampled
  // uniformly in solid angle.
  const double mean = luminance_integral.value() / (4.0 * kPi);
  const bool uniform = !(mean > 0.0);
  const double floor_density = uniform ? 1.0 : kImportanceFloor * mean;
  double running = 0.0;
  for (std::uint32_t y = 0; y < height; ++y) {
    const double floor_q = floor_density * row_solid_angle(y, height, width);
    for (std::uint32_t x = 0; x < width; ++x) {
      double& c = cdf[std::size_t{y} * width + x];
      running += (uniform ? 0.0 : c) + floor_q;
      c = running;
    }
  }
  const double total = running;

  // Sampling. The values were checked in pass 1; re-reads are not counted again.
  std::mt19937_64 rng(seed);
  TexelReader sample_reader(image, options);
  SampleSum sum;
  std::array<double, 3> rgb;
  for (std::uint32_t k = 0; k < n; ++k) {
    const double target = uniform01(rng) * total;
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), target);
    const std::size_t t = std::min<std::size_t>(it - cdf.begin(), cdf.size() - 1);
    const double p = cdf[t] - (t == 0 ? 0.0 : cdf[t - 1]);  // P_t Q
    const auto x = static_cast<std::uint32_t>(t % width), y = static_cast<std::uint32_t>(t / width);

    // Uniform in solid angle inside texel (x, y): cos(theta) uniform on [mu1, mu0].
    const double mu0 = std::cos(kPi * y / height), mu1 = std::cos(kPi * (y + 1.0) / height);
    const double mu = mu0 + (mu1 - mu0) * uniform01(rng);
    const double s = std::sqrt(std::max(0.0, (1.0 - mu) * (1.0 + mu)));
    const double lon = equirect_lon((x + uniform01(rng)) / width);
    const Dir3 d = {s * std::cos(lon), mu, s * std::sin(lon)};

    (void)sample_reader.read(x, y, rgb);  // cannot fail: pass 1 saw every texel
    sum.add(d, row_solid_angle(y, height, width) * (total / p), rgb);
  }
  radiance = sum.result(1.0 / n);
  if (stats != nullptr) *stats = stats_from_counts(counts);
  return Status::success();
}

}  // namespace shpack::detail
