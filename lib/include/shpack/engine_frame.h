// engine_frame.h - the world frames and SH basis signs of other engines, and what they do to
// a direction and to L2 coefficients made in Unity's frame (conventions.h).
//
// docs/conventions.md ("Frames of other engines") derives every entry below; in short, each
// engine's axes are Unity's axes, permuted and signed:
//
//   frame      handed  up   axes in terms of Unity's (x right, y up, z forward)   basis
//   unity      left    +Y   (x, y, z)                                            Unity's
//   threejs    right   +Y   (x, y, -z)   the same equirect file in equirectUv    Unity's
//   gltf       right   +Y   (-x, y, z)   glTF 2.0: +Z forward, -X right          Unity's
//   unreal     left    +Z   (z, x, y)    X forward, Y right, Z up                Condon-Shortley
//   blender    right   +Z   (x, z, y)    the same equirect file in Blender       Unity's
//   filament   right   +Y   (z, y, x)    what cmgen's default (mirrored) output  Unity's
//                                        holds for the same equirect file
//
// "Unity's basis" is sh_basis.h's: Y_i = k_i P_i, no Condon-Shortley phase. Unreal's shaders
// (SHCommon.ush, SHBasisFunction3) use Y_i = s_i k_i P_i with s = (+,-,+,-,+,-,+,-,+), the
// Condon-Shortley phase (-1)^m on m > 0 and the same sign on m < 0.
//
// Coefficients. With engine axis X_k = a_k * u_{p(k)} (u = Unity's x, y, z, a_k = +-1), the
// function f(d) = sum_i c_i Y_i(d) of Unity's frame is g(D) = sum_i c'_i Y_i(D) of the engine's:
//  - bands 0 and 1 and the products xy, yz, xz (indices 0..5, 7) move as their polynomials:
//    c'_{index(X_k)} = a_k c_{index(u_p(k))}, c'_{index(X_j X_k)} = a_j a_k c_{index(u_p(j) u_p(k))};
//  - the zonal pair (6: 3z^2-1, 8: x^2-y^2) is a signed permutation only when Unity's z is
//    the engine's Z; otherwise (unreal, blender, filament) it mixes: writing their part of f as
//    sum_k w_k X_k^2 - c6 k3 with w = (c8 k4, -c8 k4, 3 c6 k3) carried to the engine's axes,
//    and d_k = w_k - mean(w) its trace-free part, c'_6 = d_Z / (2 k3), c'_8 = (d_X - d_Y) / (2 k4).
// Then c'_i *= s_i for the engine's basis signs. Every map is orthogonal per band, so band
// energies and the mean are kept. It maps coefficients of the orthonormal Y_i (radiance L_i,
// irradiance A_l L_i), not Unity-form ones (k_i folded in): those go through unity_form_to_engine_frame.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"

namespace shpack {

enum class EngineFrame : std::uint8_t { Unity, ThreeJs, Gltf, Unreal, Blender, Filament };

// Engine axis k (0 = X, 1 = Y, 2 = Z) is sign[k] times Unity's axis from[k].
struct EngineAxes {
  std::array<int, 3> from;
  std::array<double, 3> sign;
};

struct EngineFrameSpec {
  const char* name;         // the value of --frame: "unity", "threejs", ...
  const char* description;  // "threejs: right-handed, +Y up, ..." for the documents
  EngineAxes axes;
  std::array<double, kShCount> basis_sign;  // s_i of the engine's basis against Y_i = k_i P_i
};

inline constexpr std::array<double, kShCount> kNoBasisSign = {1, 1, 1, 1, 1, 1, 1, 1, 1};
// (-1)^m for m > 0 and the same sign for -m: Unreal's SHBasisFunction3, Babylon.js's
// SH3ylmBasisConstants.
inline constexpr std::array<double, kShCount> kCondonShortleySign = {1, -1, 1, -1, 1, -1, 1, -1, 1};

inline constexpr std::array<EngineFrameSpec, 6> kEngineFrames = {{
    {"unity", "unity: left-handed, +Y up, +Z forward", {{0, 1, 2}, {1, 1, 1}}, kNoBasisSign},
    {"threejs", "threejs: right-handed, +Y up, +X = Unity +X, +Z = Unity -Z",
     {{0, 1, 2}, {1, 1, -1}}, kNoBasisSign},
    {"gltf", "gltf: right-handed, +Y up, +Z forward, +X = Unity -X (left)", {{0, 1, 2}, {-1, 1, 1}},
     kNoBasisSign},
    {"unreal", "unreal: left-handed, +Z up, +X forward, +Y right; Condon-Shortley basis signs",
     {{2, 0, 1}, {1, 1, 1}}, kCondonShortleySign},
    {"blender", "blender: right-handed, +Z up, +X = Unity +X, +Y = Unity +Z", {{0, 2, 1}, {1, 1, 1}},
     kNoBasisSign},
    {"filament", "filament: right-handed, +Y up, +X = Unity +Z, +Z = Unity +X (cmgen, mirrored)",
     {{2, 1, 0}, {1, 1, 1}}, kNoBasisSign},
}};

constexpr const EngineFrameSpec& engine_frame_spec(EngineFrame frame) noexcept {
  return kEngineFrames[static_cast<std::size_t>(frame)];
}

// A direction of Unity's frame in the engine's frame.
constexpr Dir3 to_engine_frame(EngineFrame frame, Dir3 unity) noexcept {
  const EngineAxes& axes = engine_frame_spec(frame).axes;
  const std::array<double, 3> u = {unity.x, unity.y, unity.z};
  return {axes.sign[0] * u[axes.from[0]], axes.sign[1] * u[axes.from[1]], axes.sign[2] * u[axes.from[2]]};
}

// The 9 coefficients (of Y_i = k_i P_i, e.g. radiance L_i or irradiance A_l L_i) of one
// channel, made in Unity's frame, as coefficients of the engine's basis in its frame (above).
constexpr std::array<double, kShCount> sh_to_engine_frame(EngineFrame frame,
                                                          const std::array<double, kShCount>& c) noexcept {
  const EngineFrameSpec& spec = engine_frame_spec(frame);
  const EngineAxes& axes = spec.axes;
  constexpr std::array<int, 3> kLinear = {3, 1, 2};  // index of x, y, z
  // Index of the product u_a u_b (a != b): xy 4, yz 5, xz 7.
  constexpr auto product = [](int a, int b) { return a + b == 1 ? 4 : a + b == 3 ? 5 : 7; };
  std::array<double, kShCount> out{};
  out[0] = c[0];
  for (int k = 0; k < 3; ++k) out[kLinear[k]] = axes.sign[k] * c[kLinear[axes.from[k]]];
  for (int j = 0; j < 3; ++j)
    for (int k = j + 1; k < 3; ++k)
      out[product(j, k)] = axes.sign[j] * axes.sign[k] * c[product(axes.from[j], axes.from[k])];
  if (axes.from[2] == 2) {  // z stays: 3z^2 - 1 is kept, x^2 - y^2 flips if x and y swap; exact
    out[6] = c[6];
    out[8] = axes.from[0] == 0 ? c[8] : -c[8];
  } else {
    const std::array<double, 3> w = {c[8] * kY22, -c[8] * kY22, 3.0 * c[6] * kY20};  // of x^2, y^2, z^2
    const double mean = (w[0] + w[1] + w[2]) / 3.0;
    const std::array<double, 3> d = {w[axes.from[0]] - mean, w[axes.from[1]] - mean, w[axes.from[2]] - mean};
    out[6] = d[2] / (2.0 * kY20);
    out[8] = (d[0] - d[1]) / (2.0 * kY22);
  }
  for (int i = 0; i < kShCount; ++i) out[i] *= spec.basis_sign[i];
  return out;
}

// All three channels.
constexpr ShL2 sh_to_engine_frame(EngineFrame frame, const ShL2& unity) noexcept {
  ShL2 out;
  for (int ch = 0; ch < kChannelCount; ++ch) out.c[ch] = sh_to_engine_frame(frame, unity.c[ch]);
  return out;
}

// Unity-form coefficients (convolution.h: u_i = (A_l/pi) k_i L_i, so sum_i u_i P_i = E/pi)
// in the engine's frame, such that sum_i u'_i s_i P_i(D) = E(D)/pi with the engine's signs
// s_i: u_i / k_i is a per-band multiple of L_i, mapped as above, then k_i folded back in.
constexpr ShL2 unity_form_to_engine_frame(EngineFrame frame, const ShL2& unity_form) noexcept {
  ShL2 out;
  for (int ch = 0; ch < kChannelCount; ++ch) {
    std::array<double, kShCount> orthonormal{};
    for (int i = 0; i < kShCount; ++i) orthonormal[i] = unity_form.c[ch][i] / kBasisScale[i];
    out.c[ch] = sh_to_engine_frame(frame, orthonormal);
    for (int i = 0; i < kShCount; ++i) out.c[ch][i] *= kBasisScale[i];
  }
  return out;
}

}  // namespace shpack
