#include "shpack/unity_pack.h"

#include <cmath>

namespace shpack {

UnitySphericalHarmonicsL2 to_unity_sh(const ShL2& unity_form) noexcept {
  UnitySphericalHarmonicsL2 out{};
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) out[c][i] = static_cast<float>(unity_form.c[c][i]);
  return out;
}

UnityShaderVectors to_shader_vectors(const ShL2& unity_form) noexcept {
  auto a = [&](int c) -> UnityShaderVectors::Float4 {
    const auto& s = unity_form.c[c];
    return {float(s[3]), float(s[1]), float(s[2]), float(s[0] - s[6])};
  };
  auto b = [&](int c) -> UnityShaderVectors::Float4 {
    const auto& s = unity_form.c[c];
    return {float(s[4]), float(s[5]), float(3.0 * s[6]), float(s[7])};
  };
  const auto& s = unity_form.c;
  return {a(0), a(1), a(2), b(0), b(1), b(2), {float(s[0][8]), float(s[1][8]), float(s[2][8]), 1.0f}};
}

bool fits_unity_float32(const ShL2& unity_form) noexcept {
  for (const auto& channel : to_unity_sh(unity_form))
    for (const float v : channel)
      if (!std::isfinite(v)) return false;
  const UnityShaderVectors v = to_shader_vectors(unity_form);
  for (const auto* vector : {&v.SHAr, &v.SHAg, &v.SHAb, &v.SHBr, &v.SHBg, &v.SHBb, &v.SHC})
    for (const float x : *vector)
      if (!std::isfinite(x)) return false;
  return true;
}

float shade_sh9(const UnityShaderVectors& v, int channel, float x, float y, float z) noexcept {
  const UnityShaderVectors::Float4& sha = channel == 0 ? v.SHAr : channel == 1 ? v.SHAg : v.SHAb;
  const UnityShaderVectors::Float4& shb = channel == 0 ? v.SHBr : channel == 1 ? v.SHBg : v.SHBb;
  // SHEvalLinearL0L1: dot(SHA, (n, 1)).
  const float l0l1 = sha[0] * x + sha[1] * y + sha[2] * z + sha[3];
  // SHEvalLinearL2: dot(SHB, n.xyzz * n.yzzx) + SHC * (x^2 - y^2).
  const float l2 = shb[0] * (x * y) + shb[1] * (y * z) + shb[2] * (z * z) + shb[3] * (z * x) +
                   v.SHC[channel] * (x * x - y * y);
  return l0l1 + l2;
}

}  // namespace shpack
