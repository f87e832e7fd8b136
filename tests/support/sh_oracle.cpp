#include "support/sh_oracle.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace shpack_test {
namespace {

constexpr double kPi = std::numbers::pi;

double factorial_ratio(int l, int m) {  // (l - m)! / (l + m)!
  double r = 1.0;
  for (int k = l - m + 1; k <= l + m; ++k) r /= k;
  return r;
}

}  // namespace

double assoc_legendre(int l, int m, double x) {
  if (m < 0 || m > l) throw std::out_of_range("assoc_legendre: m");
  // P_m^m = (2m - 1)!! (1 - x^2)^(m/2)   (no (-1)^m)
  double pmm = 1.0;
  if (m > 0) {
    const double somx2 = std::sqrt((1.0 - x) * (1.0 + x));
    double odd = 1.0;
    for (int i = 1; i <= m; ++i) {
      pmm *= odd * somx2;
      odd += 2.0;
    }
  }
  if (l == m) return pmm;
  // P_{m+1}^m = x (2m + 1) P_m^m
  double pmm1 = x * (2.0 * m + 1.0) * pmm;
  if (l == m + 1) return pmm1;
  // (l - m) P_l^m = x (2l - 1) P_{l-1}^m - (l + m - 1) P_{l-2}^m
  double pll = 0.0;
  for (int ll = m + 2; ll <= l; ++ll) {
    pll = (x * (2.0 * ll - 1.0) * pmm1 - (ll + m - 1.0) * pmm) / (ll - m);
    pmm = pmm1;
    pmm1 = pll;
  }
  return pll;
}

double sh_slow(int l, int m, double theta, double phi) {
  const int am = std::abs(m);
  const double k = std::sqrt((2.0 * l + 1.0) / (4.0 * kPi) * factorial_ratio(l, am));
  const double p = assoc_legendre(l, am, std::cos(theta));
  if (m > 0) return std::numbers::sqrt2 * k * std::cos(m * phi) * p;
  if (m < 0) return std::numbers::sqrt2 * k * std::sin(am * phi) * p;
  return k * p;
}

std::array<double, 9> unity_basis_slow(double x, double y, double z) {
  const double theta = std::acos(std::clamp(z, -1.0, 1.0));
  const double phi = std::atan2(y, x);
  std::array<double, 9> out{};
  for (int l = 0; l <= 2; ++l)
    for (int m = -l; m <= l; ++m) out[l * (l + 1) + m] = sh_slow(l, m, theta, phi);
  return out;
}

std::vector<double> sh_slow_all(int lmax, double x, double y, double z) {
  const double theta = std::acos(std::clamp(z, -1.0, 1.0));
  const double phi = std::atan2(y, x);
  std::vector<double> out((lmax + 1) * (lmax + 1));
  for (int l = 0; l <= lmax; ++l)
    for (int m = -l; m <= l; ++m) out[l * (l + 1) + m] = sh_slow(l, m, theta, phi);
  return out;
}

double cosine_lobe(int l) {
  if (l < 0) throw std::out_of_range("cosine_lobe: l");
  if (l == 0) return kPi;
  if (l == 1) return 2.0 * kPi / 3.0;
  if (l % 2 == 1) return 0.0;
  const double sign = (l / 2 - 1) % 2 == 0 ? 1.0 : -1.0;
  // l! / (2^l ((l/2)!)^2) = C(l, l/2) / 2^l, in logarithms for large l.
  const double central = std::exp(std::lgamma(l + 1.0) - 2.0 * std::lgamma(l / 2 + 1.0) -
                                  l * std::log(2.0));
  return 2.0 * kPi * sign / ((l + 2.0) * (l - 1.0)) * central;
}

double truncation_kernel_norm() {
  // Explicit sum to l = 20000, then the tail: C(l, l/2)/2^l <= sqrt(2/(pi l)) gives term_l
  // <= 4/((l+2)^2 (l-1)^2) * 2/(pi l) * (2l+1)/(4 pi) <= 0.43/(l-1)^4 for l >= 4, and the
  // even l >= L sum to at most 0.43/(6 (L-3)^3) (integral test).
  constexpr int kLast = 20000;
  double sum = 0.0;
  for (int l = kLast; l >= 3; --l) {  // small terms first
    const double a = cosine_lobe(l) / kPi;
    sum += a * a * (2.0 * l + 1.0) / (4.0 * kPi);
  }
  const double tail = 0.43 / (6.0 * std::pow(kLast + 2.0 - 3.0, 3));
  return std::sqrt(sum + tail) * (1.0 + 1e-12);
}

}  // namespace shpack_test
