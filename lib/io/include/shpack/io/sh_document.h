// sh_document.h - the content of one output document, before it becomes JSON.
//
// docs/json-format.md describes every key. sphericalHarmonicsL2 and the shader vectors are
// not stored here: the writer derives them from unity_form (unity_pack.h), the only
// place where doubles become float32.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/io/layout.h"
#include "shpack/rotate.h"
#include "shpack/sampling_methods.h"
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

// The sun taken out of the map (convert --extract-sun, sun.h), in the document's frame, with
// its intensity applied.
struct SunLight {
  Dir3 direction;                      // unit, towards the sun
  std::array<double, 3> irradiance{};  // E per channel at normal incidence (radiance x sr)
  std::array<double, 3> sky{};         // the sky level its texels were set to
  double radius_deg = 0;               // angular radius of the removed disc
  double solid_angle = 0;              // of the removed texels, sr
  std::uint64_t texels = 0;            // how many were removed
};

// How the source was read, beyond its layout (docs/json-format.md, "source").
struct ShReading {
  std::string layer;                        // the part or layer chosen (--layer); "" for the default
  CubeFrame cube_frame = CubeFrame::Unity;  // the world its cube faces were made in (cube layouts)
  std::string colorspace = "linear-rec709"; // its RGB primaries (colorspace.h), or "file" for
                                            // chromaticities that match no named space
};

struct ShDocument {
  ShSource source;
  ShReading reading;
  MethodSpec method;       // the projection method (sampling_methods.h)
  double intensity = 1.0;  // linear factor applied to the radiance (intensity * 2^exposure)
  double rotate_deg = 0.0; // yaw applied (rotate.h)
  Window window;           // deringing applied (window.h)
  ShL2 radiance;           // L_c,i in Unity's frame, intensity, rotation and window applied
  ShL2 unity_form;         // (A_l / pi) k_i L_c,i (convolution.h)
  ShDiagnostics diagnostics;
  std::optional<Matrix3> colour_matrix;  // applied to the input's RGB, if it was not Rec. 709 (colorspace.h)
  bool l1 = false;         // band 2 removed for Light Probe Proxy Volumes (output_format.h)
  bool sun_extraction = false;  // --extract-sun was asked for (sun.h)
  std::optional<SunLight> sun;   // the sun it found, if any
};

}  // namespace shpack::io
