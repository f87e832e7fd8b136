#include "shpack/sh_basis.h"

namespace shpack {

double eval_unity_form(const ShL2& unity_form, int channel, double x, double y,
                       double z) noexcept {
  const std::array<double, kShCount> p = basis_polynomials(x, y, z);
  double sum = 0.0;
  for (int i = 0; i < kShCount; ++i) sum += unity_form.c[channel][i] * p[i];
  return sum;
}

}  // namespace shpack
