#include "support/unity_shader.h"

#include <cmath>
#include <numbers>

#include "support/sh_oracle.h"

namespace shpack_test {
namespace {

struct float4 {
  float x, y, z, w;
};
float dot(const float4& a, const float4& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
float4 as_float4(const shpack::UnityShaderVectors::Float4& v) { return {v[0], v[1], v[2], v[3]}; }

}  // namespace

std::array<float, 3> unity_shade_sh9(const shpack::UnityShaderVectors& v, const shpack::Dir3& n) {
  const float4 normal{static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z), 1.0f};
  // SHEvalLinearL0L1
  const float x1[3] = {dot(as_float4(v.SHAr), normal), dot(as_float4(v.SHAg), normal),
                       dot(as_float4(v.SHAb), normal)};
  // SHEvalLinearL2
  const float4 vB{normal.x * normal.y, normal.y * normal.z, normal.z * normal.z, normal.z * normal.x};
  const float x2[3] = {dot(as_float4(v.SHBr), vB), dot(as_float4(v.SHBg), vB), dot(as_float4(v.SHBb), vB)};
  const float vC = normal.x * normal.x - normal.y * normal.y;
  const float x3[3] = {v.SHC[0] * vC, v.SHC[1] * vC, v.SHC[2] * vC};
  std::array<float, 3> res{};
  for (int c = 0; c < 3; ++c) {
    const float l2 = x2[c] + x3[c];
    res[c] = x1[c];
    res[c] += l2;
  }
  return res;
}

double shade_sh9_rounding_bound(const shpack::ShL2& unity_form, int channel, const shpack::Dir3& n) {
  const auto& s = unity_form.c[channel];
  const double x = n.x, y = n.y, z = n.z;
  const double terms = std::fabs(s[3] * x) + std::fabs(s[1] * y) + std::fabs(s[2] * z) +
                       std::fabs(s[0] - s[6]) + std::fabs(s[4] * x * y) + std::fabs(s[5] * y * z) +
                       std::fabs(3.0 * s[6] * z * z) + std::fabs(s[7] * z * x) +
                       std::fabs(s[8]) * (x * x + y * y);
  return (11.0 * 0x1p-24 + 16.0 * 0x1p-53) * terms;
}

double reconstruct_unity_form(const shpack::ShL2& unity_form, int channel, const shpack::Dir3& n) {
  const auto& s = unity_form.c[channel];
  const double x = n.x, y = n.y, z = n.z;
  return s[0] + s[1] * y + s[2] * z + s[3] * x + s[4] * x * y + s[5] * y * z +
         s[6] * (3.0 * z * z - 1.0) + s[7] * x * z + s[8] * (x * x - y * y);
}

double reconstruct_irradiance_over_pi(const shpack::ShL2& radiance, int channel, const shpack::Dir3& n) {
  const std::array<double, 9> y = unity_basis_slow(n.x, n.y, n.z);
  double sum = 0.0;
  for (int l = 0; l <= 2; ++l)
    for (int m = -l; m <= l; ++m) {
      const int i = l * (l + 1) + m;
      sum += cosine_lobe(l) / std::numbers::pi * radiance.c[channel][i] * y[i];
    }
  return sum;
}

}  // namespace shpack_test
