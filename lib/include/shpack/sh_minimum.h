// sh_minimum.h - the exact minimum over the sphere of an L2 function.
//
// On the unit sphere an L2 function in Unity form (sum_i s_i P_i(n), sh_basis.h) is a
// quadratic c + b.n + n^T A n, with
//   c = s0 - s6,   b = (s3, s1, s2) for (x, y, z),
//   A = [[ s8,   s4/2, s7/2 ],
//        [ s4/2, -s8,  s5/2 ],
//        [ s7/2, s5/2, 3 s6 ]].
// Its minimum on |n| = 1 is the trust-region subproblem: the global minimiser satisfies
// (A - lambda I) n = -b/2 with A - lambda I positive semidefinite (J. J. More, D. C.
// Sorensen, "Computing a Trust Region Step", SIAM J. Sci. Stat. Comput. 4(3), 1983). In the
// eigenbasis of A (alpha_1 <= alpha_2 <= alpha_3, beta = V^T b) the multiplier solves
// sum_k beta_k^2 / (4 (alpha_k - lambda)^2) = 1 for lambda <= alpha_1, a monotone equation
// solved here by bisection to full double precision; the "hard case" (beta_1 = 0) is
// handled in closed form. The result is exact up to rounding, not a sampled estimate.
#pragma once

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"

namespace shpack {

struct SphereMinimum {
  double value = 0;  // min over unit n of sum_i s_i P_i(n)
  Dir3 direction;    // a unit direction where it is attained (one of them, if several)
};

// Minimum of channel `channel` of Unity-form coefficients: the minimum of E/pi that
// Unity's ShadeSH9 would return before any clamp.
SphereMinimum minimum_on_sphere(const ShL2& unity_form, int channel) noexcept;

}  // namespace shpack
