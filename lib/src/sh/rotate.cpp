#include "shpack/rotate.h"

#include <cmath>

#include "common/angles.h"

namespace shpack {
namespace {

constexpr double kSqrt3Over2 = 0.866025403784438646763723170752936183;  // sqrt(3)/2

struct SinCos {
  double sin, cos;
};

// sin and cos of an angle in degrees, exact at multiples of 90. fmod is exact; then
// r = 90 q + rem with |rem| <= 45: for q != 0, r and 90 q have the same sign and
// |r| / |90 q| is in [1/2, 3/2], so r - 90 q is exact (Sterbenz). Only rem is rounded to
// radians, and the quadrant q is applied by exact symmetries.
SinCos sincos_degrees(double degrees) noexcept {
  const double r = std::fmod(degrees, 360.0);
  const double q = std::nearbyint(r / 90.0);
  const double rem = r - 90.0 * q;
  const double x = rem * kDegree;
  const double s = std::sin(x), c = std::cos(x);
  switch (((static_cast<int>(q) % 4) + 4) % 4) {
    case 0: return {s, c};
    case 1: return {c, -s};    // 90 + x
    case 2: return {-s, -c};   // 180 + x
    default: return {-c, s};   // 270 + x
  }
}

// Symmetric matrices A_i of the band-2 polynomials on the unit sphere, P_i(v) = v^T A_i v
// (constants homogenised: 3z^2 - 1 = 2z^2 - x^2 - y^2), in index order 4..8. They are
// traceless and mutually orthogonal under <A, B> = tr(A B); kBand2Norm = <A_i, A_i>.
constexpr double kBand2Poly[5][3][3] = {
    {{0, 0.5, 0}, {0.5, 0, 0}, {0, 0, 0}},   // 4: xy
    {{0, 0, 0}, {0, 0, 0.5}, {0, 0.5, 0}},   // 5: yz
    {{-1, 0, 0}, {0, -1, 0}, {0, 0, 2}},     // 6: 3z^2 - 1
    {{0, 0, 0.5}, {0, 0, 0}, {0.5, 0, 0}},   // 7: xz
    {{1, 0, 0}, {0, -1, 0}, {0, 0, 0}},      // 8: x^2 - y^2
};
constexpr double kBand2Norm[5] = {0.5, 0.5, 6.0, 0.5, 2.0};

// Index of the band-1 coefficient of world axis j (x, y, z): Unity's order y, z, x.
constexpr int kAxisIndex[3] = {3, 1, 2};

}  // namespace

Matrix3 rotation_about_y(double degrees) noexcept {
  const SinCos a = sincos_degrees(degrees);
  return {{{a.cos, 0.0, -a.sin}, {0.0, 1.0, 0.0}, {a.sin, 0.0, a.cos}}};
}

ShL2 rotate_about_y(const ShL2& sh, double degrees) noexcept {
  // Y_i(R v) = sum_j M_ij Y_j(v) with R = R_y(alpha) (rotate.h), c, s of alpha and
  // C, S of 2 alpha. Substituting x' = c x - s z, y' = y, z' = s x + c z:
  //   band 1:  z' = s x + c z,  x' = c x - s z
  //   xy:  x'y' = c xy - s yz                 yz:  y'z' = s xy + c yz
  //   xz:  x'z' = (S/2)(x^2 - z^2) + C xz,    and x^2 - z^2 = (P8 - P6)/2 on the sphere
  //   3z'^2 - 1 = ((1 + 3C)/4) P6 + 3S P7 + (3/2) s^2 P8
  //   x'^2 - y'^2 = (s^2/2) P6 - S P7 + ((3 + C)/4) P8
  // (x^2 = (P8 + 1 - z^2)/2, z^2 = (P6 + 1)/3 on the sphere). With Y_i = k_i P_i and
  // k2 = 2 k4 = 2 sqrt(3) k3 this is, in Y, the orthogonal matrix below (rows i = 6, 7, 8;
  // 1 - C = 2 s^2 is used to avoid cancellation at small angles):
  //   Y6:  (1 + 3C)/4        (sqrt3/2) S    (sqrt3/2) s^2
  //   Y7: -(sqrt3/2) S        C             S/2
  //   Y8:  (sqrt3/2) s^2     -S/2           (3 + C)/4
  const SinCos a = sincos_degrees(degrees);
  const SinCos a2 = sincos_degrees(2.0 * std::fmod(degrees, 360.0));  // exact doubling
  const double c = a.cos, s = a.sin, cc = a2.cos, ss = a2.sin;
  const double s_sq = s * s;
  ShL2 out;
  for (int ch = 0; ch < kChannelCount; ++ch) {
    const std::array<double, kShCount>& f = sh.c[ch];
    std::array<double, kShCount>& g = out.c[ch];
    g[0] = f[0];
    g[1] = f[1];
    g[2] = c * f[2] + s * f[3];
    g[3] = c * f[3] - s * f[2];
    g[4] = c * f[4] - s * f[5];
    g[5] = s * f[4] + c * f[5];
    g[6] = 0.25 * (1.0 + 3.0 * cc) * f[6] + kSqrt3Over2 * ss * f[7] + kSqrt3Over2 * s_sq * f[8];
    g[7] = -kSqrt3Over2 * ss * f[6] + cc * f[7] + 0.5 * ss * f[8];
    g[8] = kSqrt3Over2 * s_sq * f[6] - 0.5 * ss * f[7] + 0.25 * (3.0 + cc) * f[8];
  }
  return out;
}

Status rotate(const ShL2& sh, const Matrix3& rotation, ShL2& out) noexcept {
  const Matrix3& r = rotation;
  // Orthogonality: max |R^T R - I| <= 1e-6, which also rejects NaN and Inf (comparisons
  // with NaN are false).
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double dot = r[0][i] * r[0][j] + r[1][i] * r[1][j] + r[2][i] * r[2][j];
      if (!(std::fabs(dot - (i == j ? 1.0 : 0.0)) <= 1e-6))
        return Status::error(Errc::InvalidArgument, "rotation matrix is not orthogonal");
    }
  }
  // Band 1: Y(axis i)(R v) = (R v)_i = sum_j R_ij v_j.
  double band1[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) band1[i][j] = r[i][j];
  // Band 2: P_i(R v) = v^T (R^T A_i R) v and R^T A_i R is traceless and symmetric, so
  // P_i(R v) = sum_j [tr(R^T A_i R A_j) / <A_j, A_j>] P_j(v); in Y: times k_i / k_j.
  double band2[5][5];
  for (int i = 0; i < 5; ++i) {
    double rotated[3][3];  // R^T A_i R
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) {
        double sum = 0.0;
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) sum += r[k][p] * kBand2Poly[i][k][l] * r[l][q];
        rotated[p][q] = sum;
      }
    }
    for (int j = 0; j < 5; ++j) {
      double dot = 0.0;
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) dot += rotated[p][q] * kBand2Poly[j][p][q];
      band2[i][j] = dot / kBand2Norm[j] * (kBasisScale[4 + i] / kBasisScale[4 + j]);
    }
  }
  ShL2 result;
  for (int ch = 0; ch < kChannelCount; ++ch) {
    const std::array<double, kShCount>& f = sh.c[ch];
    std::array<double, kShCount>& g = result.c[ch];
    g[0] = f[0];
    for (int i = 0; i < 3; ++i) {
      double sum = 0.0;
      for (int j = 0; j < 3; ++j) sum += band1[i][j] * f[kAxisIndex[j]];
      g[kAxisIndex[i]] = sum;
    }
    for (int i = 0; i < 5; ++i) {
      double sum = 0.0;
      for (int j = 0; j < 5; ++j) sum += band2[i][j] * f[4 + j];
      g[4 + i] = sum;
    }
  }
  out = result;
  return Status::success();
}

}  // namespace shpack
