// unity_pack.h - Unity's SphericalHarmonicsL2 and the seven shader vectors.
//
// The only place where doubles become float32 ([5] sections 5 and 6, no constants added):
//
//   unity_SHA{r,g,b} = ( sh[c][3], sh[c][1], sh[c][2], sh[c][0] - sh[c][6] )
//   unity_SHB{r,g,b} = ( sh[c][4], sh[c][5], 3 * sh[c][6], sh[c][7] )
//   unity_SHC        = ( sh[0][8], sh[1][8], sh[2][8], 1 )
//
// so that dot(SHA, (n,1)) + dot(SHB, (xy, yz, zz, zx)) + SHC.c (x^2 - y^2) = sum_i sh P_i(n).
// A widely copied packing swaps indices 5 and 6 in SHB and green and blue in SHC: this
// one does not (tests/sh/unity_pack_test.cpp).
#pragma once

#include <array>

#include "shpack/sh_basis.h"

namespace shpack {

// Unity's SphericalHarmonicsL2: sh[channel][coefficient], serialized as sh[ 0]..sh[26].
using UnitySphericalHarmonicsL2 = std::array<std::array<float, kShCount>, kChannelCount>;

struct UnityShaderVectors {
  using Float4 = std::array<float, 4>;
  Float4 SHAr, SHAg, SHAb, SHBr, SHBg, SHBb, SHC;
};

// Rounds Unity-form coefficients (convolution.h) to the 27 floats Unity stores.
UnitySphericalHarmonicsL2 to_unity_sh(const ShL2& unity_form) noexcept;

// Packs the seven vectors. The arithmetic (sh0 - sh6, 3 sh6) is done in double from the
// Unity-form coefficients and rounded once, which is also how Unity's own packing rounds
// when it starts from the 27 floats up to one float rounding.
UnityShaderVectors to_shader_vectors(const ShL2& unity_form) noexcept;

// Whether every float of to_unity_sh and of to_shader_vectors is finite: both must be, since
// SHA.w = s0 - s6 and SHB.z = 3 s6 can overflow float32 while the 27 floats fit.
bool fits_unity_float32(const ShL2& unity_form) noexcept;

// Unity's ShadeSH9 in float: SHEvalLinearL0L1(n) + SHEvalLinearL2(n) for one channel [3],
// evaluated from the packed vectors exactly as the shader does.
float shade_sh9(const UnityShaderVectors& v, int channel, float x, float y, float z) noexcept;

}  // namespace shpack
