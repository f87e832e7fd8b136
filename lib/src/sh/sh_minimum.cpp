#include "shpack/sh_minimum.h"

#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace shpack {
namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;
using Array3 = std::array<double, 3>;

// Cyclic Jacobi eigen-decomposition of a symmetric 3x3 matrix (Golub & Van Loan,
// "Matrix Computations", 4th ed., sec. 8.5.2): rotations until the off-diagonal vanishes.
// On return `a` is diagonal (the eigenvalues) and the columns of `v` are the eigenvectors.
void jacobi_eigen(Mat3& a, Mat3& v) noexcept {
  v = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int sweep = 0; sweep < 64; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off == 0.0) return;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        // Rotation angle from tan(2 phi) = 2 a_pq / (a_qq - a_pp), in the stable form
        // t = sign(theta) / (|theta| + sqrt(theta^2 + 1)).
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = std::copysign(1.0, theta) / (std::fabs(theta) + std::hypot(theta, 1.0));
        const double c = 1.0 / std::hypot(t, 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // a <- a J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // a <- J^T a
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // v <- v J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
    }
  }
}

double value_at(const ShL2& sh, int channel, const Array3& n) noexcept {
  return eval_unity_form(sh, channel, n[0], n[1], n[2]);
}

Array3 normalized(Array3 n) noexcept {
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (len == 0.0) return {0, 1, 0};
  return {n[0] / len, n[1] / len, n[2] / len};
}

}  // namespace

SphereMinimum minimum_on_sphere(const ShL2& sh, int channel) noexcept {
  const auto& s = sh.c[channel];
  Mat3 a = {{{s[8], 0.5 * s[4], 0.5 * s[7]}, {0.5 * s[4], -s[8], 0.5 * s[5]}, {0.5 * s[7], 0.5 * s[5], 3.0 * s[6]}}};
  const Array3 b = {s[3], s[1], s[2]};
  Mat3 v;
  jacobi_eigen(a, v);
  std::array<int, 3> order = {0, 1, 2};  // eigenvalues ascending
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (a[order[j]][order[j]] < a[order[i]][order[i]]) std::swap(order[i], order[j]);
  Array3 alpha, beta;
  for (int k = 0; k < 3; ++k) {
    const int e = order[k];
    alpha[k] = a[e][e];
    beta[k] = v[0][e] * b[0] + v[1][e] * b[1] + v[2][e] * b[2];
  }
  // Eigenvalues within rounding of alpha_1 (64 u of the problem's scale) are one
  // eigenspace: a zonal lobe has an exactly double eigenvalue that rounding splits, and
  // treating the split as real would divide rounding noise by rounding noise.
  const double scale = std::fabs(alpha[0]) + std::fabs(alpha[2]) + std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  for (int k = 1; k < 3; ++k)
    if (alpha[k] - alpha[0] <= 64.0 * std::numeric_limits<double>::epsilon() * scale) alpha[k] = alpha[0];
  // The stationary point for multiplier lambda, in the eigenbasis (components whose
  // eigenvalue equals lambda are left at 0: the hard case sets them).
  auto point = [&](double lambda) {
    Array3 m{};
    for (int k = 0; k < 3; ++k)
      m[k] = alpha[k] == lambda ? 0.0 : -beta[k] / (2.0 * (alpha[k] - lambda));
    return m;
  };
  auto to_world = [&](const Array3& m) {
    Array3 n{};
    for (int k = 0; k < 3; ++k)
      for (int r = 0; r < 3; ++r) n[r] += v[r][order[k]] * m[k];
    return n;
  };
  auto norm2 = [](const Array3& m) { return m[0] * m[0] + m[1] * m[1] + m[2] * m[2]; };

  SphereMinimum best{std::numeric_limits<double>::infinity(), {0, 1, 0}};
  auto consider = [&](const Array3& n_raw) {
    const Array3 n = normalized(n_raw);
    const double f = value_at(sh, channel, n);
    if (f < best.value) best = {f, {n[0], n[1], n[2]}};
  };

  // Regular case: bisection for |m(lambda)| = 1 on [alpha_1 - |b|/2, alpha_1), where
  // |m|^2 rises monotonically from <= 1 (each term <= beta_k^2 / |b|^2) to infinity when b
  // has a component in the bottom eigenspace, and otherwise to |m(alpha_1)|^2: then a root
  // exists (and the hard case below does not apply) exactly when |m(alpha_1)| > 1.
  const double b_norm = std::sqrt(norm2(b));
  double beta_bottom = 0.0;  // beta's length in the bottom eigenspace
  for (int k = 0; k < 3; ++k)
    if (alpha[k] == alpha[0]) beta_bottom += beta[k] * beta[k];
  if (beta_bottom != 0.0 || norm2(point(alpha[0])) > 1.0) {
    double lo = alpha[0] - 0.5 * b_norm, hi = alpha[0];
    for (int it = 0; it < 200 && lo < hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (norm2(point(mid)) > 1.0 ? hi : lo) = mid;
    }
    consider(to_world(point(lo)));
  }
  // Hard case (beta_1 = 0, or within rounding): lambda = alpha_1 and the free component along the
  // first eigenvector fills the rest of the unit length; both signs are candidates.
  for (int k = 0; k < 3; ++k) {
    if (k > 0 && alpha[k] != alpha[0]) break;
    Array3 m = point(alpha[0]);
    const double rest = norm2(m);
    if (rest <= 1.0) {
      m[k] = std::sqrt(1.0 - rest);
      consider(to_world(m));
      m[k] = -m[k];
      consider(to_world(m));
    }
  }
  // Guard against a degenerate eigen-decomposition: the poles of every eigen-axis.
  for (int k = 0; k < 3; ++k) {
    const Array3 e = {v[0][k], v[1][k], v[2][k]};
    consider(e);
    consider({-e[0], -e[1], -e[2]});
  }
  return best;
}

}  // namespace shpack
