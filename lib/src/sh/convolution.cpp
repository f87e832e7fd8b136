#include "shpack/convolution.h"

namespace shpack {

ShL2 radiance_to_unity_form(const ShL2& radiance) noexcept {
  ShL2 out;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) out.c[c][i] = kUnityScale[i] * radiance.c[c][i];
  return out;
}

ShL2 scaled(const ShL2& sh, double factor) noexcept {
  ShL2 out;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) out.c[c][i] = factor * sh.c[c][i];
  return out;
}

}  // namespace shpack
