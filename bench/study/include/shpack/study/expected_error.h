// expected_error.h - the expected error of E/pi of a random method from its variance, and
// which kind each error of `shpack bench` is.
//
// Derivation. E_c/pi(n) = sum_i (A_l/pi) L_c,i Y_i(n) (sh_basis.h: A_l/pi = 1, 2/3, 1/4), so
// an estimate L' errs by dE_c(n)/pi = sum_i a_i d_i Y_i(n), a_i = A_l(i)/pi, d_i = L'_c,i - L_c,i.
// Over the sphere, orthonormality (int Y_i Y_j dw = delta_ij) removes every cross term:
//   (1/4 pi) int (dE_c/pi)^2 dw = (1/4 pi) sum_i a_i^2 d_i^2,
// whatever the correlations of the d_i; the expectation over draws of an unbiased estimate
// (E[d_i^2] = Var(L'_c,i) = Var(X)_c,i / N, sampling_variance.h) is then
//   E[mean-square error] = (1/4 pi) sum_i a_i^2 Var(X)_c,i / N.
// Its square root, in % of the mean of E_c/pi over the sphere (C_0 L_c,0, accuracy.h), the
// worst channel, is the method's expected RMS error: err_rms_pct's expectation up to the
// meter's 1024 normals standing for the sphere (a quadrature of a degree-4 polynomial) and
// the max over channels taken after the expectation rather than before.
//
// The max over the sphere has no such form; Cauchy-Schwarz bounds it draw by draw:
// |sum_i a_i d_i Y_i(n)|^2 <= (sum_i a_i^2 d_i^2) (sum_i Y_i(n)^2) and sum_i Y_i(n)^2 = 9/(4 pi)
// (the addition theorem: (2l + 1)/(4 pi) per band), so max_n (dE/pi)^2 <= 9 x the mean
// square above, and sqrt(E[max^2]) <= 3 x the expected RMS error: a bound.
#pragma once

#include <string_view>

#include "shpack/sh_basis.h"

namespace shpack::study {

// Expected RMS error of E/pi, in % of the mean (above), of an estimate of `n` i.i.d. terms
// with per-term variance `variance` (sampling_variance.h), for the exact `reference`: the
// worst channel with a positive mean; NaN if none has one.
double expected_rms_pct(const ShL2& variance, double n, const ShL2& reference);

// sqrt(E[max^2]) <= kMaxOverRmsBound x the expected RMS error (above).
inline constexpr double kMaxOverRmsBound = 3.0;

// How an error of `shpack bench` was obtained: "exact" (a deterministic rule's one error,
// or the closed form of a random one), "bound" (an upper bound from the closed form),
// "sampled" (the RMS over draws, with its confidence interval).
enum class ErrorKind { Exact, Bound, Sampled };
std::string_view error_kind_name(ErrorKind kind);

}  // namespace shpack::study
