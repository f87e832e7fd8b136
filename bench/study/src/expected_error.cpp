#include "shpack/study/expected_error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shpack::study {

double expected_rms_pct(const ShL2& variance, double n, const ShL2& reference) {
  double worst = std::numeric_limits<double>::quiet_NaN();
  for (int c = 0; c < kChannelCount; ++c) {
    const double mean = kUnityScale[0] * reference.c[c][0];
    if (!(mean > 0)) continue;
    double mean_square = 0;  // (1/4 pi) sum_i a_i^2 Var_i / N (header)
    for (int i = 0; i < kShCount; ++i) {
      const double a = kCosineLobeOverPi[kBand[i]];
      mean_square += a * a * variance.c[c][i];
    }
    mean_square /= 4.0 * std::numbers::pi * n;
    const double pct = 100.0 * std::sqrt(mean_square) / mean;
    if (!(pct <= worst)) worst = pct;
  }
  return worst;
}

std::string_view error_kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Exact: return "exact";
    case ErrorKind::Bound: return "bound";
    case ErrorKind::Sampled: return "sampled";
  }
  return "sampled";
}

}  // namespace shpack::study
