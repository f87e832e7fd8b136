// sampling_variance.h - the exact variance of the random methods mc:N and is:N of
// sampling_methods.h, on the piecewise-constant image they sample.
//
// Both estimates are means of N i.i.d. terms X_k, so Var(L'_c,i) = Var(X)_c,i / N with
//
//   Var(X)_c,i = E[X^2] - L_c,i^2,   E[X^2] = sum_t w_t L_c,t^2 int_t Y_i^2 dw,
//
// t running over the texels, L_c,i the exact projection (project.h) and w_t = Omega_t / P_t
// the ratio of a texel's solid angle to its probability:
//  - mc:N draws w uniformly (density 1/(4 pi)), X = 4 pi L(w) Y_i(w), so
//    E[X^2] = 4 pi int L^2 Y_i^2 dw: w_t = 4 pi.
//  - is:N draws texel t with P_t, then w uniform in solid angle inside t (density
//    P_t / Omega_t), X = L_t Y_i(w) Omega_t / P_t, so E[X^2] = sum_t P_t int_t
//    (L_t Y_i Omega_t / P_t)^2 dw / Omega_t: w_t = Omega_t / P_t = Q / d_t with the
//    sampler's density d_t = max(lum_t, 0) + eps mean and Q = sum_t d_t Omega_t
//    = (1 + eps) 4 pi mean; w_t = 4 pi for an image sampled uniformly (mean <= 0).
// (A direction on a texel edge is looked up by equirect_texel's rounding, a set of measure
// zero.) The texel integrals of Y_i^2, polynomials of degree <= 4 in (x, y, z), are taken in
// closed form: with mu = cos(theta), s^2 = 1 - mu^2 and dw = dmu dlon, each is a product of
// an integral of a polynomial in mu of degree <= 4 over the row and one of
// 1, cos^2, sin^2, cos^4, sin^4, cos^2 sin^2 of lon over the column.
//
// The variance does not depend on N or on the seed: one pass over the texels (two for is,
// whose mean comes first) and one exact projection per image give Var for every N.
#pragma once

#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

// Var(X)_c,i of one term of `method` (MonteCarlo or Importance) on `image`, read with the
// value policies of `options` as project_with_method reads it (options.threads goes to the
// exact projection): Var(L'_c,i) of mc:N or is:N is this over N. Never negative (a
// difference that rounds below 0 is 0). Errors: InvalidArgument for another method, BadView,
// NonFiniteTexel (NonFinite::Error), OutOfMemory (one row and the exact projection's tables).
Status sample_variance(const ImageView& image, SamplingMethod method, const ProjectOptions& options,
                       ShL2& variance) noexcept;

}  // namespace shpack
