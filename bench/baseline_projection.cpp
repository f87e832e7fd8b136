#include "baseline_projection.h"

#include <cmath>
#include <numbers>

#include "shpack/conventions.h"

namespace shpack::bench {

ShL2 baseline_project(const float* rgb, unsigned width, unsigned height) {
  ShL2 out;
  const double pi = std::numbers::pi;
  for (unsigned j = 0; j < height; ++j) {
    for (unsigned i = 0; i < width; ++i) {
      const Dir3 d = equirect_direction((i + 0.5) / width, (j + 0.5) / height);
      const double solid_angle =
          (2.0 * pi / width) * (std::cos(pi * j / height) - std::cos(pi * (j + 1.0) / height));
      const auto y = eval_basis(d.x, d.y, d.z);
      const float* p = rgb + 3 * (std::size_t{j} * width + i);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < kShCount; ++k) out.c[c][k] += p[c] * y[k] * solid_angle;
    }
  }
  return out;
}

}  // namespace shpack::bench
