// rotate.h - rotations of L2 SH, and the yaw of Unity's Skybox/Panoramic `_Rotation`.
//
// What `--rotate DEG` means. The vertex shaders of Unity's Skybox/Panoramic and
// Skybox/Cubemap draw each vertex v of the skybox mesh at RotateAroundYInDegrees(v,
// _Rotation) and sample the texture with the unrotated v (`o.texcoord = v.vertex.xyz`)
// [Unity built-in shaders, DefaultResourcesExtra/Skybox-Panoramic.shader and
// Skybox-Cubed.shader, read in the Lex-DRL/unity-builtin_shaders mirror]. That function is
//
//   alpha = degrees * pi / 180;  m = float2x2(cos, -sin, sin, cos);
//   return float3(mul(m, v.xz), v.y).xzy;
//
// HLSL's float2x2(a, b, c, d) has rows (a, b) and (c, d), and mul(m, v) is m times the
// column v, so with c = cos alpha, s = sin alpha:
//
//   R_y(alpha):  x' = c x - s z,   y' = y,   z' = s x + c z      (rotation_about_y below)
//
// The texel that the unrotated sky shows in direction v is shown in direction R v: the
// environment is turned by R, L'(w) = L(R^-1 w). For alpha = +90 degrees, +X -> +Z ->
// -X -> -Z: the view straight ahead (+Z) then shows what was on the right (+X), i.e. the
// sky turns from right to left, counterclockwise seen from above (Unity's top view: +X
// right, +Z up the screen). On an equirect image (conventions.h: lon = (0.5 - u) 2 pi and
// R_y adds alpha to lon) the rotated image is I'(u) = I(u + alpha / 2pi): for a width W,
// turning by 360 k / W degrees moves every column k columns to the LEFT (column i shows
// old column i + k, mod W); +90 degrees is a shift of W/4 to the left.
//
// The SH of the turned environment are L'_i = int L(R^-1 w) Y_i(w) dw
// = int L(v) Y_i(R v) dv = sum_j M_ij L_j, where Y_i(R v) = sum_j M_ij Y_j(v): bands do not
// mix, band 0 is unchanged, and M is orthogonal within each band (so band energies
// sum_m L_lm^2 are preserved). Rotation commutes with the cosine convolution, so these
// functions apply equally to radiance, irradiance or Unity-form coefficients.
#pragma once

#include <array>

#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

// A 3x3 matrix, m[row][column], acting on column vectors (x, y, z): w = m v.
using Matrix3 = std::array<std::array<double, 3>, 3>;

// Unity's RotateAroundYInDegrees as a matrix: R_y above. Exact at multiples of 90 degrees
// (the angle is reduced exactly in degrees before any rounding to radians).
Matrix3 rotation_about_y(double degrees) noexcept;

// The coefficients of the environment as Skybox/Panoramic shows it with
// _Rotation = `degrees`: rotate(radiance, rotation_about_y(degrees)), in closed form.
// Exact identity at multiples of 360 degrees. `degrees` must be finite (NaN or Inf give NaN
// coefficients).
ShL2 rotate_about_y(const ShL2& sh, double degrees) noexcept;

// The coefficients of L'(w) = L(R^T w) (the environment turned by R, content at v moving
// to R v) for an orthogonal R; a reflection (det R = -1) is allowed too, e.g. the z mirror
// diag(1, 1, -1) gives kMirrorZSign. Errc::InvalidArgument if R is not orthogonal to
// 1e-6 (max |R^T R - I|; the result's error then grows in proportion) or not finite.
Status rotate(const ShL2& sh, const Matrix3& rotation, ShL2& out) noexcept;

}  // namespace shpack
