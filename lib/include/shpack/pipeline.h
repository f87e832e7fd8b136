// pipeline.h - from projected radiance coefficients to what a Unity user gets: the steps of
// `shpack convert` after the projection, in its order, for callers that hold the pixels
// themselves (the C ABI, shpack_c.h).
//
//   radiance  = rotate_about_y(scaled(projected, intensity), rotate_deg)   (rotate.h)
//   unity     = apply_window(radiance_to_unity_form(radiance), window)      (convolution.h, window.h)
//   radiance  = apply_band_factors(radiance, the window's factors)          (both describe one function)
//   minimum   = minimum_on_sphere(unity, c) per channel                     (sh_minimum.h)
//
// lib/io's convert_env_map (convert.cpp) calls it too, so a map projected through the C ABI
// and one converted by the CLI give bit-identical numbers (pinned by tests/io/c_api_test.cpp
// against the CLI's JSON).
#pragma once

#include <array>

#include "shpack/sh_basis.h"
#include "shpack/sh_minimum.h"
#include "shpack/status.h"
#include "shpack/window.h"

namespace shpack {

struct FinishOptions {
  double intensity = 1.0;   // linear factor on the radiance; finite and >= 0
  double rotate_deg = 0.0;  // yaw about +Y, as Skybox/Panoramic's _Rotation (rotate.h); finite
  Window window;            // deringing (window.h)
};

struct FinishedSh {
  ShL2 radiance;      // L_c,i with intensity, rotation and window applied
  ShL2 unity_form;    // (A_l / pi) k_i L_c,i, windowed (convolution.h)
  WindowResult window;                           // the factors the window applied
  std::array<SphereMinimum, kChannelCount> min_e_over_pi{};  // per channel, of unity_form
};

// Errors: Errc::InvalidArgument for an intensity or rotation out of its domain or a window
// that apply_window rejects; Errc::OutOfRange for a result too bright for Unity's float32
// coefficients (a float of to_unity_sh or to_shader_vectors would be infinite). `out` is
// left as it was.
Status finish_projection(const ShL2& projected_radiance, const FinishOptions& options, FinishedSh& out) noexcept;

// The option checks of finish_projection alone (intensity and rotation), for callers that
// want to refuse bad options before they read an image.
Status check_finish_options(const FinishOptions& options) noexcept;

}  // namespace shpack
