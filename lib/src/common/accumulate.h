// accumulate.h (private) - compensated summation.
//
// Neumaier's variant of Kahan summation (A. Neumaier, "Rundungsfehleranalyse einiger
// Verfahren zur Summation endlicher Summen", ZAMM 54, 1974): unlike Kahan's it keeps the
// correction when the new term is larger than the running sum, which is exactly what
// happens when a 1e6 sun row follows rows of 0.1 sky. Error bound of the compensated sum:
// |s - sum| <= 2u |sum| + O(n u^2) sum |t_i|, u = 2^-53.
// Needs strict IEEE evaluation: the build uses -ffp-contract=off and never -ffast-math.
#pragma once

#include <cmath>

namespace shpack::detail {

struct NeumaierSum {
  double sum = 0.0;
  double compensation = 0.0;

  void add(double term) noexcept {
    const double t = sum + term;
    if (std::fabs(sum) >= std::fabs(term)) {
      compensation += (sum - t) + term;
    } else {
      compensation += (term - t) + sum;
    }
    sum = t;
  }
  void add(const NeumaierSum& other) noexcept {
    add(other.sum);
    add(other.compensation);
  }
  double value() const noexcept { return sum + compensation; }
};

}  // namespace shpack::detail
