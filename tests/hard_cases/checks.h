// checks.h - comparisons shared by the hard-case tests: double results against long-double
// oracles under a stated tolerance, and the packed float outputs against float rounding.
// Each check is also a gtest EXPECT; the functions return the worst ratio for the
// "[ measure  ]" lines that docs/hard-cases.md quotes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "hard_cases/hard_case_support.h"
#include "shpack/convolution.h"
#include "shpack/sh_basis.h"
#include "shpack/unity_pack.h"
#include "support/test_util.h"

namespace shpack_hard {

using shpack::ShL2;
using shpack_test::kU;

// Tolerances per coefficient, same shape as ShL2.
using Tol = std::array<std::array<double, 9>, 3>;

inline ShL2 to_double(const ShLd& sh) {
  ShL2 out;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) out.c[c][i] = static_cast<double>(sh[c][i]);
  return out;
}

inline double norm(const ShLd& sh, int c) {
  long double s = 0;
  for (long double v : sh[c]) s += v * v;
  return static_cast<double>(std::sqrt(s));
}

inline Tol relative_to_norm(const ShLd& want, double rel) {
  Tol t{};
  for (int c = 0; c < 3; ++c) t[c].fill(rel * norm(want, c));
  return t;
}

// Largest |got - want| / tol over all coefficients; every coefficient is also an EXPECT.
inline double expect_within(const ShL2& got, const ShLd& want, const Tol& tol, const std::string& what) {
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) {
      const double err = static_cast<double>(std::fabs(got.c[c][i] - want[c][i]));
      EXPECT_LE(err, tol[c][i]) << what << " c=" << c << " i=" << i << " got=" << got.c[c][i]
                                << " want=" << static_cast<double>(want[c][i]);
      worst = std::max(worst, err / tol[c][i]);
    }
  return worst;
}

// Largest error / norm over channels (what the closing table reports).
inline double rel_error(const ShL2& got, const ShLd& want) {
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i)
      worst = std::max(worst, static_cast<double>(std::fabs(got.c[c][i] - want[c][i])) / norm(want, c));
  return worst;
}

// The 27 floats and the 7 shader vectors of `got` against the oracle `want` (radiance), given
// |got - want| <= tol per radiance coefficient. Unity form multiplies by C_i (one more
// rounding, u |value|); SHA.w = s0 - s6 and SHB.z = 3 s6 are formed in double (one more u).
// Returns the largest |float - exact| / tolerance (<= 1 required).
inline double expect_packed(const ShL2& got, const ShLd& want, const Tol& tol, const std::string& what) {
  const ShL2 unity = shpack::radiance_to_unity_form(got);
  const shpack::UnitySphericalHarmonicsL2 floats = shpack::to_unity_sh(unity);
  const shpack::UnityShaderVectors vectors = shpack::to_shader_vectors(unity);
  ShLd want_u{};
  Tol err_u{};
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) {
      want_u[c][i] = static_cast<long double>(shpack::kUnityScale[i]) * want[c][i];
      err_u[c][i] = shpack::kUnityScale[i] * tol[c][i] + 2 * kU * static_cast<double>(std::fabs(want_u[c][i]));
    }
  double worst = 0;
  auto check = [&](float value, long double exact, double err, const std::string& name) {
    const double e = static_cast<double>(exact);
    const double diff = std::fabs(static_cast<double>(value) - e), tol = float_rounding_tol(e, err);
    EXPECT_LE(diff, tol) << what << " " << name << " float=" << value << " exact=" << e;
    if (tol > 0) worst = std::max(worst, diff / tol);
  };
  for (int c = 0; c < 3; ++c) {
    const std::string ch = "c=" + std::to_string(c);
    for (int i = 0; i < 9; ++i) check(floats[c][i], want_u[c][i], err_u[c][i], "sh[" + ch + "][" + std::to_string(i) + "]");
    const auto& sha = c == 0 ? vectors.SHAr : c == 1 ? vectors.SHAg : vectors.SHAb;
    const auto& shb = c == 0 ? vectors.SHBr : c == 1 ? vectors.SHBg : vectors.SHBb;
    const auto& w = want_u[c];
    const auto& e = err_u[c];
    check(sha[0], w[3], e[3], "SHA.x " + ch);
    check(sha[1], w[1], e[1], "SHA.y " + ch);
    check(sha[2], w[2], e[2], "SHA.z " + ch);
    check(sha[3], w[0] - w[6], e[0] + e[6] + kU * static_cast<double>(std::fabs(w[0] - w[6])), "SHA.w " + ch);
    check(shb[0], w[4], e[4], "SHB.x " + ch);
    check(shb[1], w[5], e[5], "SHB.y " + ch);
    check(shb[2], 3 * w[6], 3 * e[6] + kU * static_cast<double>(std::fabs(3 * w[6])), "SHB.z " + ch);
    check(shb[3], w[7], e[7], "SHB.w " + ch);
    check(vectors.SHC[c], w[8], e[8], "SHC " + ch);
  }
  return worst;
}

// Derived rounding bound of a whole equirect projection of coefficient i of channel c
// (project.h, equirect_weights.h, row_kernel.h): per texel one product by a longitude table
// (tables within ~3u: a correctly rounded cos/sin and the double-angle products), 8-lane
// row sums (each lane ceil(W/8) terms, pairwise total: <= (ceil(W/8) + 3) u of the sum of
// |terms|), the row weights (within 16u; their parts sum in absolute value to <= 4 Omega of
// the texel: e.g. |k6_s0| + |k6_c2| <= (2.5 + 1.5) Omega), Neumaier over rows (2u of the
// result + O(H u^2)) and the final k_i (1u):
//   |err| <= (ceil(W/8) + 26) u * 4 k_i * sum_t |v_t| Omega_t + 2u |L|.
// The long-double oracle adds < 1e-17 of sum_t |v_t| Omega_t, counted as 1u.
inline Tol equirect_sum_tol(const EquirectOracle& oracle, std::uint32_t w, std::uint32_t h,
                            const std::vector<float>& rgb, const ShLd& want) {
  std::array<long double, 3> abs_integral{};
  for (std::uint32_t j = 0; j < h; ++j) {
    const long double omega = oracle.texel(0, j)[9];
    for (std::uint32_t i = 0; i < w; ++i)
      for (int c = 0; c < 3; ++c) abs_integral[c] += std::fabs(rgb[(std::size_t{j} * w + i) * 3 + c]) * omega;
  }
  Tol t{};
  const double lanes = std::ceil(w / 8.0);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i)
      t[c][i] = ((lanes + 26) * 4 + 1) * kU * shpack::kBasisScale[i] * static_cast<double>(abs_integral[c]) +
                2 * kU * static_cast<double>(std::fabs(want[c][i]));
  return t;
}

}  // namespace shpack_hard
