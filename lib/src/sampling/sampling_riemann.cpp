// riemann:N - the textbook irradiance-map sum: an N x 2N grid of (theta, lon) cells, the
// basis and the radiance at each cell centre, weight sin(theta) dtheta dlon with
// dtheta = pi / N and dlon = 2 pi / (2N). The weights are the midpoint rule for
// int sin(theta) dtheta and are not renormalised: they sum to 4 pi (1 + pi^2/(24 N^2) + ...).
#include <cmath>

#include "common/angles.h"
#include "sampling/sampling_estimator.h"
#include "sampling/sampling_projectors.h"

namespace shpack::detail {

Status project_riemann(const ImageView& image, std::uint32_t n, const ProjectOptions& options,
                       ShL2& radiance, ProjectStats* stats) noexcept {
  const std::uint64_t columns = 2 * std::uint64_t{n};
  const double cell = kPi / n;  // dtheta = dlon
  std::uint64_t k = 0;
  // Row-major over the grid, the cell centres of conventions.h's (u, t) parametrisation.
  auto next = [&]() noexcept {
    const std::uint64_t row = k / columns, column = k % columns;
    ++k;
    const double t = (static_cast<double>(row) + 0.5) / n;
    const double u = (static_cast<double>(column) + 0.5) / static_cast<double>(columns);
    return Sample{equirect_direction(u, t), std::sin(equirect_theta(t)) * cell * cell};
  };
  return project_samples(image, options, columns * n, next, 1.0, radiance, stats);
}

}  // namespace shpack::detail
