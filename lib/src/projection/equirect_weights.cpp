#include "projection/equirect_weights.h"

#include <cmath>
#include "common/angles.h"

namespace shpack::detail {
namespace {

double square(double v) noexcept { return v * v; }

// Longitude integrals over a column of width dlon centred on lon_m, written as factors
// of the centre functions (ColumnTrig), with a = 2 sin(dlon/2), b = sin(dlon)/2:
//   int cos = a cos lon_m,   int sin = a sin lon_m,        int sin cos = b sin 2lon_m,
//   int cos^2 = dlon/2 + b cos 2lon_m,   int sin^2 = dlon/2 - b cos 2lon_m.
struct ColumnFactors {
  double dlon, a, b;
};
ColumnFactors column_factors(std::uint32_t width) noexcept {
  const double dlon = 2.0 * kPi / width;
  return {dlon, 2.0 * std::sin(0.5 * dlon), 0.5 * std::sin(dlon)};
}

// Row j of the southern half is the mirror image of row H - 1 - j (theta -> pi - theta:
// sin theta even, cos theta odd), so its weights are taken from the northern row with the
// odd-in-cos ones (k1 ~ int cos sin, kxy ~ int sin^2 cos) negated. This is not a shortcut
// but the precision fix: theta ~ pi rounds with an absolute error ~u pi, which makes
// sin(theta) near the south pole off by ~2 H u relative (1.8e-12 at H = 8192), while the
// northern angles are small and exact to a few u.
template <class Weights>
RowWeights mirrored_south(Weights weights, std::uint32_t j, std::uint32_t height, std::uint32_t width) noexcept {
  const std::uint32_t north = height - 1 - j;
  if (north >= j) return weights(j, height, width);
  RowWeights w = weights(north, height, width);
  w.k1 = -w.k1;
  w.kxy = -w.kxy;
  return w;
}

}  // namespace

double x_minus_sin(double x) noexcept {
  // x - sin x = sum_{k>=1} (-1)^(k+1) x^(2k+1) / (2k+1)!; for |x| <= pi the 16th term is
  // below pi^33/33! < 1e-20, and no term is more than 2x the sum, so no cancellation.
  const double x2 = x * x;
  double term = x * x2 / 6.0, sum = 0.0;
  for (int k = 1; k <= 16; ++k) {
    sum += term;
    term *= -x2 / ((2.0 * k + 2.0) * (2.0 * k + 3.0));
  }
  return sum;
}

namespace {

RowWeights exact_northern_row_weights(std::uint32_t j, std::uint32_t height, std::uint32_t width) noexcept {
  // Row j spans theta0 = pi j/H .. theta1 = pi (j+1)/H, half-width h = pi/(2H), centre
  // theta_c. Each theta integral (of f(theta) sin theta dtheta) is written in a form free
  // of cancellation at the poles, from cos a - cos b = 2 sin((a+b)/2) sin((b-a)/2):
  //   A0   = int sin           = mu0 - mu1 = 2 sin(theta_c) sin(h)
  //   A1   = int mu sin        = (mu0^2 - mu1^2)/2 = A0 cos(theta_c) cos(h)
  //   As   = int sin^2         = (D - sin D)/2 + sin^2(theta_c) sin D,   D = 2h
  //   Asmu = int sin^2 mu      = (s1^3 - s0^3)/3 = (s1 - s0)(s1^2 + s1 s0 + s0^2)/3,
  //                              s1 - s0 = 2 cos(theta_c) sin(h)
  //   As2  = int sin^3         = A0 (3 - mu0^2 - mu0 mu1 - mu1^2)/3
  //                            = A0 (s0^2 + s1^2 + sin^2 h + sin^2 theta_c)/3
  //   Amu2 = int mu^2 sin      = A0 (mu0^2 + mu0 mu1 + mu1^2)/3
  const double h = 0.5 * kPi / height;
  const double theta_c = kPi * (j + 0.5) / height;
  const double theta0 = kPi * j / height, theta1 = kPi * (j + 1.0) / height;
  const double sin_c = std::sin(theta_c), cos_c = std::cos(theta_c);
  const double sin_h = std::sin(h), cos_h = std::cos(h);
  const double s0 = std::sin(theta0), s1 = std::sin(theta1);
  const double mu0 = std::cos(theta0), mu1 = std::cos(theta1);

  const double a0 = 2.0 * sin_c * sin_h;
  const double a1 = a0 * cos_c * cos_h;
  const double as = 0.5 * x_minus_sin(2.0 * h) + square(sin_c) * std::sin(2.0 * h);
  const double asmu = 2.0 * cos_c * sin_h * (s1 * s1 + s1 * s0 + s0 * s0) / 3.0;
  const double as2 = a0 * (s0 * s0 + s1 * s1 + square(sin_h) + square(sin_c)) / 3.0;
  const double amu2 = a0 * (mu0 * mu0 + mu0 * mu1 + mu1 * mu1) / 3.0;

  const ColumnFactors col = column_factors(width);
  // I6 = int (3 z^2 - 1) = 3 As2 int sin^2 lon - A0 dlon per column;
  // I8 = int (x^2 - y^2) = As2 int cos^2 lon - Amu2 dlon per column.
  return {
      .k0 = a0 * col.dlon,
      .k1 = a1 * col.dlon,
      .kx = as * col.a,
      .kxy = asmu * col.a,
      .k6_s0 = 1.5 * as2 * col.dlon - a0 * col.dlon,
      .k6_c2 = -3.0 * as2 * col.b,
      .k7 = as2 * col.b,
      .k8_s0 = 0.5 * as2 * col.dlon - amu2 * col.dlon,
      .k8_c2 = as2 * col.b,
  };
}

RowWeights center_northern_row_weights(std::uint32_t j, std::uint32_t height, std::uint32_t width) noexcept {
  // P_i(d_centre) * Omega, Omega = A0 dlon the exact texel solid angle, with
  // sin^2 lon = (1 - cos 2lon)/2, cos^2 lon = (1 + cos 2lon)/2, sin cos = sin 2lon / 2.
  const double h = 0.5 * kPi / height;
  const double theta_c = kPi * (j + 0.5) / height;
  const double s = std::sin(theta_c), mu = std::cos(theta_c);
  const double omega = 2.0 * s * std::sin(h) * column_factors(width).dlon;
  return {
      .k0 = omega,
      .k1 = omega * mu,
      .kx = omega * s,
      .kxy = omega * s * mu,
      .k6_s0 = omega * (1.5 * s * s - 1.0),
      .k6_c2 = -1.5 * omega * s * s,
      .k7 = 0.5 * omega * s * s,
      .k8_s0 = omega * (0.5 * s * s - mu * mu),
      .k8_c2 = 0.5 * omega * s * s,
  };
}

}  // namespace

RowWeights exact_row_weights(std::uint32_t j, std::uint32_t height, std::uint32_t width) noexcept {
  return mirrored_south(exact_northern_row_weights, j, height, width);
}

RowWeights center_row_weights(std::uint32_t j, std::uint32_t height, std::uint32_t width) noexcept {
  return mirrored_south(center_northern_row_weights, j, height, width);
}

ColumnTrig column_trig(std::uint32_t i, std::uint32_t width) noexcept {
  // Double angles from one sine and cosine: cos 2a = (c - s)(c + s), sin 2a = 2 s c, each
  // within a few ulps of 1 (absolute), which is all the column sums need.
  const double lon = (0.5 - (i + 0.5) / width) * 2.0 * kPi;
  const double c = std::cos(lon), s = std::sin(lon);
  return {c, s, (c - s) * (c + s), 2.0 * s * c};
}

}  // namespace shpack::detail
