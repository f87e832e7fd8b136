#include "direction_distribution.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace shpack::bake {
namespace {

using std::numbers::pi;

// The index k with cdf[k] <= u < cdf[k + 1] (cdf non-decreasing, cdf.front() = 0), skipping
// empty intervals; u is rescaled to where it falls inside [cdf[k], cdf[k + 1]), so one
// uniform number picks the interval and then a point inside it (its strata are kept).
std::uint32_t pick(const double* cdf, std::uint32_t n, double& u) noexcept {
  const double* at = std::upper_bound(cdf + 1, cdf + n + 1, u);
  std::uint32_t k = static_cast<std::uint32_t>(at - cdf) - 1;
  k = std::min(k, n - 1);
  while (k > 0 && cdf[k + 1] == cdf[k]) --k;  // u at the top: the last non-empty interval
  const double width = cdf[k + 1] - cdf[k];
  u = width > 0 ? std::clamp((u - cdf[k]) / width, 0.0, 1.0) : 0.5;
  return k;
}

}  // namespace

DirectionDistribution::DirectionDistribution(std::uint32_t cols, std::uint32_t rows,
                                             const std::function<double(std::uint32_t, std::uint32_t)>& weight,
                                             const Matrix3& rotation)
    : cols_(cols), rows_(rows), row_cdf_(rows + 1, 0.0), cell_cdf_(static_cast<std::size_t>(rows) * (cols + 1), 0.0),
      density_(static_cast<std::size_t>(rows) * cols, 0.0), rotation_(rotation) {
  std::vector<double> w(static_cast<std::size_t>(rows) * cols);
  for (std::uint32_t j = 0; j < rows; ++j) {
    double* cdf = &cell_cdf_[static_cast<std::size_t>(j) * (cols + 1)];
    for (std::uint32_t i = 0; i < cols; ++i) {
      w[static_cast<std::size_t>(j) * cols + i] = std::max(0.0, weight(i, j));
      cdf[i + 1] = cdf[i] + w[static_cast<std::size_t>(j) * cols + i];
    }
    row_cdf_[j + 1] = row_cdf_[j] + cdf[cols];
    if (cdf[cols] > 0)
      for (std::uint32_t i = 1; i <= cols; ++i) cdf[i] /= cdf[cols];
  }
  total_ = row_cdf_[rows];
  if (!(total_ > 0)) return;
  for (double& v : row_cdf_) v /= total_;
  for (std::uint32_t j = 0; j < rows; ++j) {
    // Omega(cell) = (2 pi / cols) (cos theta_j - cos theta_(j+1)).
    const double omega = 2.0 * pi / cols * (std::cos(pi * j / rows) - std::cos(pi * (j + 1) / rows));
    for (std::uint32_t i = 0; i < cols; ++i)
      density_[static_cast<std::size_t>(j) * cols + i] = w[static_cast<std::size_t>(j) * cols + i] / total_ / omega;
  }
}

DirectionSample DirectionDistribution::sample(double u1, double u2) const noexcept {
  const std::uint32_t j = pick(row_cdf_.data(), rows_, u1);
  const std::uint32_t i = pick(&cell_cdf_[static_cast<std::size_t>(j) * (cols_ + 1)], cols_, u2);
  // Uniform in solid angle inside the cell: cos theta uniform between the row's edges.
  const double c0 = std::cos(pi * j / rows_), c1 = std::cos(pi * (j + 1) / rows_);
  const double y = c0 + (c1 - c0) * u1, s = std::sqrt(std::fmax(0.0, (1.0 - y) * (1.0 + y)));
  const double lon = 2.0 * pi * (0.5 - (i + u2) / cols_);
  const Vec3d v{s * std::cos(lon), y, s * std::sin(lon)};
  const Matrix3& r = rotation_;
  const Vec3d d{r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z, r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
                r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z};
  return {d, density_[static_cast<std::size_t>(j) * cols_ + i]};
}

double DirectionDistribution::pdf(const Vec3d& d) const noexcept {
  if (empty()) return 0;
  const Matrix3& r = rotation_;  // v = R^T d
  const double vx = r[0][0] * d.x + r[1][0] * d.y + r[2][0] * d.z;
  const double vy = r[0][1] * d.x + r[1][1] * d.y + r[2][1] * d.z;
  const double vz = r[0][2] * d.x + r[1][2] * d.y + r[2][2] * d.z;
  double u = 0.5 - std::atan2(vz, vx) / (2.0 * pi);
  u -= std::floor(u);
  const double theta = std::acos(std::clamp(vy, -1.0, 1.0));
  const auto i = std::min(cols_ - 1, static_cast<std::uint32_t>(u * cols_));
  const auto j = std::min(rows_ - 1, static_cast<std::uint32_t>(theta / pi * rows_));
  return density_[static_cast<std::size_t>(j) * cols_ + i];
}

}  // namespace shpack::bake
