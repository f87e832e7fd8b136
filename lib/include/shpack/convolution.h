// convolution.h - from radiance coefficients to what Unity's shader wants.
//
// Irradiance E_c,i = A_l L_c,i with the clamped-cosine zonal factors A_l [1]; Unity wants
// E/pi, with the basis constant k_i folded in as well, so that sum_i sh[c][i] P_i(n) is
// E_c(n)/pi (sh_basis.h [5] section 5). This is the one place where A_l and 1/pi are applied.
#pragma once

#include "shpack/sh_basis.h"

namespace shpack {

// Unity form: sh[c][i] = (A_l / pi) k_i L_c,i = kUnityScale[i] * radiance.c[c][i].
ShL2 radiance_to_unity_form(const ShL2& radiance) noexcept;

// Scales every coefficient (linear in the radiance: --intensity, --exposure).
ShL2 scaled(const ShL2& sh, double factor) noexcept;

}  // namespace shpack
