// ShLeastSquares and lsq:N - least-squares fit of the 9 coefficients to point samples.
//
// For samples (d_k, v_k) the fit minimises |A c - v|^2 per channel, A_ki = Y_i(d_k). It
// keeps the QR factorisation A = Q R up to date one row at a time (G. H. Golub, C. F. Van
// Loan, "Matrix Computations", 4th ed., sec. 6.5.2, updating by Givens rotations): the new
// row a is rotated against R's rows 0..8 in turn, each rotation zeroing one entry of a, and
// the same rotations are applied to the values, which accumulate Q^T v. Then R c = Q^T v
// by back substitution. Rotations are orthogonal, so rounding stays at the level of A's
// own condition number (not its square, as with the normal equations A^T A c = A^T v).
// Order: rows in the order added, rotations in index order: deterministic.
#include <algorithm>
#include <cmath>

#include "sampling/sampling_points.h"
#include "sampling/sampling_projectors.h"
#include "sampling/sampling_texel.h"

namespace shpack {
namespace {

constexpr double kRankTolerance = 1e-10;  // |R_ii| <= this * max |R_jj|: rank deficient

}  // namespace

void ShLeastSquares::add(const Dir3& direction, const std::array<double, 3>& value) noexcept {
  std::array<double, kShCount> row = eval_basis(direction.x, direction.y, direction.z);
  std::array<double, kChannelCount> v = value;
  for (int i = 0; i < kShCount; ++i) {
    if (row[i] == 0.0) continue;
    // Rotation in the plane of R's row i and the new row that zeroes row[i]:
    // [c s; -s c] [R_ii; row_i] = [r; 0], r = hypot(R_ii, row_i) > 0.
    const double r = std::hypot(r_[i][i], row[i]);
    const double c = r_[i][i] / r, s = row[i] / r;
    r_[i][i] = r;
    row[i] = 0.0;
    for (int j = i + 1; j < kShCount; ++j) {
      const double rij = r_[i][j];
      r_[i][j] = c * rij + s * row[j];
      row[j] = c * row[j] - s * rij;
    }
    for (int ch = 0; ch < kChannelCount; ++ch) {
      const double q = qt_value_[i][ch];
      qt_value_[i][ch] = c * q + s * v[ch];
      v[ch] = c * v[ch] - s * q;
    }
  }
  ++count_;
}

Status ShLeastSquares::solve(ShL2& radiance) const noexcept {
  if (count_ < kShCount)
    return Status::error(Errc::InvalidArgument, "least squares needs at least 9 samples");
  double largest = 0.0;
  for (int i = 0; i < kShCount; ++i) largest = std::max(largest, std::fabs(r_[i][i]));
  for (int i = 0; i < kShCount; ++i)
    if (!(std::fabs(r_[i][i]) > kRankTolerance * largest))
      return Status::error(Errc::InvalidArgument,
                           "least-squares samples do not determine all 9 coefficients");
  ShL2 out;
  for (int ch = 0; ch < kChannelCount; ++ch) {
    for (int i = kShCount - 1; i >= 0; --i) {
      double rest = qt_value_[i][ch];
      for (int j = i + 1; j < kShCount; ++j) rest -= r_[i][j] * out.c[ch][j];
      out.c[ch][i] = rest / r_[i][i];
    }
  }
  radiance = out;
  return Status::success();
}

namespace detail {

Status project_least_squares(const ImageView& image, std::uint32_t n, const ProjectOptions& options,
                             ShL2& radiance, ProjectStats* stats) noexcept {
  TexelReader reader(image, options);
  ShLeastSquares fit;
  std::array<double, 3> rgb;
  for (std::uint32_t k = 0; k < n; ++k) {
    const Dir3 d = fibonacci_point(k, n);
    if (!reader.read(d, rgb)) return reader.nonfinite_error();
    fit.add(d, rgb);
  }
  if (Status st = fit.solve(radiance); !st.ok()) return st;
  if (stats != nullptr) *stats = stats_from_counts(reader.counts());
  return Status::success();
}

}  // namespace detail
}  // namespace shpack
