// sampling_estimator.h (private) - the weighted-sample estimator shared by the point
// methods of sampling_methods.h:
//
//   L_c,i  ~=  scale * sum_k w_k L_c(texel(d_k)) Y_i(d_k)
//
// Terms are added in sample order with Neumaier sums (accumulate.h), one per channel and
// coefficient, so the result depends only on the samples, never on timing.
#pragma once

#include <array>
#include <cstdint>

#include "common/accumulate.h"
#include "sampling/sampling_texel.h"
#include "shpack/conventions.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack::detail {

struct SampleSum {
  NeumaierSum sum[kChannelCount][kShCount];

  // Adds w * rgb_c * Y_i(d); d must be a unit vector.
  void add(const Dir3& d, double weight, const std::array<double, 3>& rgb) noexcept {
    const std::array<double, kShCount> y = eval_basis(d.x, d.y, d.z);
    for (int c = 0; c < kChannelCount; ++c) {
      const double wl = weight * rgb[c];
      for (int i = 0; i < kShCount; ++i) sum[c][i].add(wl * y[i]);
    }
  }

  ShL2 result(double scale) const noexcept {
    ShL2 out;
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) out.c[c][i] = scale * sum[c][i].value();
    return out;
  }
};

// A sample of a point method: a unit direction and its quadrature weight.
struct Sample {
  Dir3 direction;
  double weight = 1.0;
};

// Runs the estimator over `count` samples, next_sample() being called once per sample in
// order (it may keep state, e.g. a random generator). `image` must be resolved.
template <class NextSample>
Status project_samples(const ImageView& image, const ProjectOptions& options, std::uint64_t count,
                       NextSample&& next_sample, double scale, ShL2& radiance,
                       ProjectStats* stats) noexcept {
  TexelReader reader(image, options);
  SampleSum sum;
  std::array<double, 3> rgb;
  for (std::uint64_t k = 0; k < count; ++k) {
    const Sample s = next_sample();
    if (!reader.read(s.direction, rgb)) return reader.nonfinite_error();
    sum.add(s.direction, s.weight, rgb);
  }
  radiance = sum.result(scale);
  if (stats != nullptr) *stats = stats_from_counts(reader.counts());
  return Status::success();
}

}  // namespace shpack::detail
