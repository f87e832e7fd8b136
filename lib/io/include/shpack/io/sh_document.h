// sh_document.h - the content of one output document, before it becomes JSON.
//
// docs/json-format.md describes every key. sphericalHarmonicsL2 and the shader vectors are
// not stored here: the writer derives them from unity_form (unity_pack.h), the only
// place where doubles become float32.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "shpack/io/layout.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"
#include "shpack/sh_minimum.h"
#include "shpack/window.h"

namespace shpack::io {

struct ShSource {
  std::vector<std::string> files;   // file names, without folders
  std::vector<std::string> sha256;  // lower-case hex digest of each file
  Layout layout = Layout::Equirect;
  std::uint32_t width = 0, height = 0;
};

struct ShDiagnostics {
  std::uint64_t nonfinite_texels = 0;  // NaN/Inf texels replaced by 0 (NonFinite::Zero)
  std::uint64_t negative_texels = 0;   // texels with a negative channel (kept or clamped)
  std::uint32_t ignored_channels = 0;  // channels of the file that were not projected
  // Per channel, the exact minimum over the sphere of E/pi of unity_form (sh_minimum.h):
  // negative where L2 ringing would make Unity's shader return negative light.
  std::array<SphereMinimum, kChannelCount> min_e_over_pi{};
  // Per channel, the factors (w_0, w_1, w_2) the window applied to each band (window.h),
  // and whether the sloan window could not make that channel non-negative (L00 < 0).
  std::array<std::array<double, 3>, kChannelCount> window_factors{{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}};
  std::array<bool, kChannelCount> window_impossible{};
};

struct ShDocument {
  ShSource source;
  Method method = Method::Exact;
  double intensity = 1.0;  // linear factor applied to the radiance (intensity * 2^exposure)
  double rotate_deg = 0.0; // yaw applied (rotate.h)
  Window window;           // deringing applied (window.h)
  ShL2 radiance;           // L_c,i in Unity's frame, intensity, rotation and window applied
  ShL2 unity_form;         // (A_l / pi) k_i L_c,i (convolution.h)
  ShDiagnostics diagnostics;
};

// "exact" or "center", as in the CLI and the JSON output.
const char* method_name(Method method) noexcept;

}  // namespace shpack::io
