// direction_distribution.h (private) - importance sampling of the environment: directions
// drawn with a density proportional to its brightness (pbrt-v4's piecewise-constant 2-D
// distribution, Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed., A.5).
//
// The domain is the equirect grid of the environment's own frame (conventions.h: theta from
// +Y, u = 0.5 - lon / 2 pi), cut into cells that are whole blocks of texels. A cell's weight
// is its radiance (the mean of the three channels, so no colour is under-sampled) integrated
// over its solid angle; inside a cell the direction is uniform in solid angle (uniform in
// cos theta and in longitude). So pdf(d) = P(cell) / Omega(cell) exactly, which multiple
// importance sampling needs, and a map's texels are the cells (or blocks of them) it reads.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "shpack/rotate.h"
#include "tracer.h"

namespace shpack::bake {

struct DirectionSample {
  Vec3d dir;
  double pdf = 0;  // per steradian
};

class DirectionDistribution {
 public:
  DirectionDistribution() = default;
  // weight(col, row): the cell's weight (>= 0); the grid is cols x rows cells over the
  // sphere, cell (i, j) spanning u in [i / cols, (i + 1) / cols) and theta in
  // [j pi / rows, (j + 1) pi / rows). `rotation`: world = R * environment frame.
  DirectionDistribution(std::uint32_t cols, std::uint32_t rows,
                        const std::function<double(std::uint32_t, std::uint32_t)>& weight, const Matrix3& rotation);

  bool empty() const noexcept { return total_ <= 0; }
  DirectionSample sample(double u1, double u2) const noexcept;  // (u1, u2) uniform in [0, 1)^2
  double pdf(const Vec3d& d) const noexcept;                    // d unit

 private:
  std::uint32_t cols_ = 0, rows_ = 0;
  std::vector<double> row_cdf_;   // rows + 1 entries, 0 .. 1
  std::vector<double> cell_cdf_;  // per row, cols + 1 entries, 0 .. 1 within the row
  std::vector<double> density_;   // per cell: P(cell) / Omega(cell)
  double total_ = 0;
  Matrix3 rotation_{};
};

}  // namespace shpack::bake
