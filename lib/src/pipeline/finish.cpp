// finish.cpp - stage 4 of the pipeline (pipeline.h): the same colour matrix, intensity and
// rotation for the SH and the lights, then the SH's convolution, window, L1, float32 check,
// minimum and packing.
#include <cmath>

#include "shpack/convolution.h"
#include "shpack/pipeline.h"

namespace shpack {
namespace {

// Band 2 (indices 4..8) set to 0. Why this is what a Light Probe Proxy Volume of quality Low
// evaluates: document.h.
void remove_band_2(ShL2& sh) noexcept {
  for (auto& channel : sh.c)
    for (int i = 0; i < kShCount; ++i)
      if (kBand[i] == 2) channel[i] = 0.0;
}

// The radiance whose Unity form is `fitted` (convolution.h: unity_i = kUnityScale[i]
// radiance_i), for a window that scales no band (window.h, Optimal). A channel the fit left
// unchanged keeps its radiance bit for bit.
ShL2 radiance_of_fit(const ShL2& radiance, const ShL2& unity_form, const ShL2& fitted) noexcept {
  ShL2 out = radiance;
  for (int c = 0; c < kChannelCount; ++c)
    if (fitted.c[c] != unity_form.c[c])
      for (int i = 0; i < kShCount; ++i) out.c[c][i] = fitted.c[c][i] / kUnityScale[i];
  return out;
}

std::array<double, 3> mixed_and_scaled(const std::array<double, 3>& rgb, const FinishOptions& options) noexcept {
  std::array<double, 3> out = rgb;
  if (options.colour_matrix) {
    const Matrix3& m = *options.colour_matrix;
    for (int c = 0; c < 3; ++c) out[c] = m[c][0] * rgb[0] + m[c][1] * rgb[1] + m[c][2] * rgb[2];
  }
  for (double& v : out) v *= options.intensity;
  return out;
}

}  // namespace

Status check_finish_options(const FinishOptions& options) noexcept {
  if (!std::isfinite(options.intensity) || options.intensity < 0)
    return Status::error(Errc::InvalidArgument, "intensity must be finite and >= 0");
  if (!std::isfinite(options.rotate_deg))
    return Status::error(Errc::InvalidArgument, "rotation must be a finite number of degrees");
  return Status::success();
}

Status finish_projection(const ShL2& projected_radiance, const FinishOptions& options, FinishedSh& out) noexcept {
  if (Status st = check_finish_options(options); !st.ok()) return st;
  FinishedSh result;
  const ShL2 linear = options.colour_matrix ? mix_channels(projected_radiance, *options.colour_matrix)
                                            : projected_radiance;
  ShL2 radiance = rotate_about_y(scaled(linear, options.intensity), options.rotate_deg);
  // L1 before the window, so that sloan and optimal make the L1 function non-negative (the
  // L1 part of a non-negative L2 function need not be).
  if (options.l1) remove_band_2(radiance);
  const ShL2 unity_form = radiance_to_unity_form(radiance);
  if (Status st = apply_window(unity_form, options.window, result.unity_form, &result.window, options.l1); !st.ok())
    return st;
  result.radiance = scales_bands(options.window.kind) ? apply_band_factors(radiance, result.window.factors)
                                                      : radiance_of_fit(radiance, unity_form, result.unity_form);
  if (!fits_unity_float32(result.unity_form))
    return Status::error(Errc::OutOfRange, "the lighting is too bright for Unity's float32 coefficients");
  for (int c = 0; c < kChannelCount; ++c) result.min_e_over_pi[c] = minimum_on_sphere(result.unity_form, c);
  result.unity_sh = to_unity_sh(result.unity_form);
  result.shader = to_shader_vectors(result.unity_form);
  out = result;
  return Status::success();
}

FinishedLight finish_light(const SunLight& light, const FinishOptions& options) noexcept {
  FinishedLight out{light, {}};
  // The map's environment is turned by R (rotate.h): the light's direction too.
  const Matrix3 r = rotation_about_y(options.rotate_deg);
  const Dir3 d = light.direction;
  out.light.direction = {r[0][0] * d.x + r[0][1] * d.y + r[0][2] * d.z, r[1][0] * d.x + r[1][1] * d.y + r[1][2] * d.z,
                         r[2][0] * d.x + r[2][1] * d.y + r[2][2] * d.z};
  out.light.irradiance = mixed_and_scaled(light.irradiance, options);
  out.light.sky = mixed_and_scaled(light.sky, options);
  out.unity = unity_sun_light(out.light);
  return out;
}

}  // namespace shpack
