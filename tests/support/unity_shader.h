// unity_shader.h - Unity's ShadeSH9 transcribed to C++ float (the test oracle), and the
// float rounding bound used to compare it with a double reconstruction.
//
// UnityCG.cginc (docs/conventions.md section 1), for half4 normal = (n, 1) with half = float:
//   x1.r = dot(unity_SHAr, normal)  ...                      SHEvalLinearL0L1
//   vB   = normal.xyzz * normal.yzzx
//   x2.r = dot(unity_SHBr, vB)      ...
//   vC   = normal.x*normal.x - normal.y*normal.y
//   x3   = unity_SHC.rgb * vC
//   return x2 + x3                                            SHEvalLinearL2
//   ShadeSH9: res = SHEvalLinearL0L1(normal); res += SHEvalLinearL2(normal)
// (the Standard shader's optional clamp at 0 is not applied). dot() is evaluated left to
// right, each product rounded (the build uses -ffp-contract=off).
#pragma once

#include <array>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"
#include "shpack/unity_pack.h"

namespace shpack_test {

// Per channel r, g, b, for a normal given in double and rounded to float as a shader
// input would be.
std::array<float, 3> unity_shade_sh9(const shpack::UnityShaderVectors& v, const shpack::Dir3& n);

// Bound on |unity_shade_sh9(to_shader_vectors(sh), n)[c] - sum_i sh.c[c][i] P_i(n)| for
// Unity-form coefficients sh and a unit n, from rounding alone.
//
// The shader sums nine terms a_k b_k: a = (SHA, SHB, SHC.c) are the exact packed values
// (sh3, sh1, sh2, sh0 - sh6, sh4, sh5, 3 sh6, sh7, sh8) each rounded once to float, and
// b = (x, y, z, 1, xy, yz, zz, zx, x^2 - y^2) are formed in float from the rounded normal.
// Following one term through: 1 rounding of a_k, <= 3 of b_k (two rounded inputs and the
// product), 1 of the product a_k b_k, <= 3 additions inside its dot() and 2 more
// (x2 + x3, then x1 + that): at most 10 relative perturbations of size u = 2^-24, so
// |error| <= gamma_10 sum_k |a_k| |b_k| with gamma_10 = 10u/(1 - 10u) < 11u. For the last
// term the subtraction x^2 - y^2 is exact to within rounding of each square, so its |b|
// is x^2 + y^2. The double reference adds 16 * 2^-53 sum_k |a_k||b_k| (negligible). So
//   bound = 11 * 2^-24 * sum_k |a_k| |b_k|  (+ the double term).
double shade_sh9_rounding_bound(const shpack::ShL2& unity_form, int channel, const shpack::Dir3& n);

// sum_i sh.c[c][i] P_i(n) with the polynomials of docs/conventions.md written out here
// (not shpack::eval_unity_form).
double reconstruct_unity_form(const shpack::ShL2& unity_form, int channel, const shpack::Dir3& n);

// E(n)/pi = sum_l (A_l/pi) sum_m L_lm Y_lm(n) from radiance coefficients, with A_l from
// sh_oracle.h's general formula and Y from the Legendre route: independent of shpack's
// constants, convolution and packing.
double reconstruct_irradiance_over_pi(const shpack::ShL2& radiance, int channel, const shpack::Dir3& n);

}  // namespace shpack_test
