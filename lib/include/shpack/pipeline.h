// pipeline.h - the one conversion pipeline: from an environment map to what a Unity user
// gets, in five stages. Every command and the C ABI go through it (docs/architecture.md
// draws it), and each option is applied at exactly one stage:
//
//   1. source      which pixels: file or faces, part/layer, data window, colour space and
//                  layout, resolved once (lib/io's map source for files; the caller's views
//                  here). Result: a MapImage and FinishOptions::colour_matrix.
//   2. transforms  --extract-sun: image in, image + light out (light_extraction.h);
//                  --extract-lights N: image in, lights + the SH they take out of the
//                  projection (light_candidates.h, light_choice.h and light_fit.h, the choice
//                  measured by stage 4 and view_error.h). Needs the whole image, writable.
//   3. projector   one, chosen by ConvertOptions::method: the closed-form rules of every
//                  layout (project.h, project_cube.h, project_sphere_map.h) or the sampling
//                  rules of other tools on equirect maps (sampling_methods.h). The value
//                  policies (--nonfinite, --negative) are applied here and nowhere else.
//                  When no transform needs the whole image, exact and center stream an
//                  equirect file in bands through EquirectProjector (streams_rows).
//   4. finish      finish_projection, on the SH and on every extracted light alike:
//                    radiance = rotate_about_y(intensity M L, rotate_deg)  (colorspace.h, rotate.h)
//                    L1:        band 2 of the radiance set to 0 (document.h says why)
//                    unity    = apply_window(radiance_to_unity_form(radiance), window, L1)
//                    radiance = apply_band_factors(radiance, the window's factors), or
//                               for --window optimal (no band factors) the radiance whose
//                               Unity form the fit returned
//                    float32 check, minimum of E/pi per channel (sh_minimum.h), packing
//                  (unity_pack.h: the only place where doubles become float32).
//   5. document    make_document (document.h): what was read, the options applied, the
//                  result; lib/io's writers only format it.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "shpack/colorspace.h"
#include "shpack/conventions.h"
#include "shpack/cube_layout.h"
#include "shpack/image_view.h"
#include "shpack/layout.h"
#include "shpack/light_choice.h"
#include "shpack/light_extraction.h"
#include "shpack/project.h"
#include "shpack/rotate.h"
#include "shpack/sampling_methods.h"
#include "shpack/sh_basis.h"
#include "shpack/sh_minimum.h"
#include "shpack/status.h"
#include "shpack/unity_light.h"
#include "shpack/unity_pack.h"
#include "shpack/view_error.h"
#include "shpack/view_reference.h"
#include "shpack/window.h"

namespace shpack {

// ---- Stage 1: what the source stage hands on ------------------------------------------

struct MapImage {
  Layout layout = Layout::Equirect;  // resolved: never Auto
  ImageView image;                   // every layout but Faces
  std::array<ImageView, kCubeFaceCount> faces{};  // Layout::Faces, Unity's face order
  CubeFrame cube_frame = CubeFrame::Unity;        // cube layouts only
  // The memory `image` views, packed F32 (make_view): the transforms write into it. Only
  // needed when a transform runs.
  float* writable = nullptr;
};

// Makes an equirect map writable for the transforms: a packed F32 copy of map.image in
// `storage` (F16 values widened exactly), which map.image then views and map.writable points
// at, so that the caller's own pixels are never written. Other layouts are left as they are
// (no transform reads them). Errors: BadView for a view resolve_view refuses, OutOfMemory
// when the copy cannot be allocated; `map` is then unchanged.
Status make_writable(MapImage& map, std::vector<float>& storage) noexcept;

// ---- Stage 4 --------------------------------------------------------------------------

struct FinishOptions {
  std::optional<Matrix3> colour_matrix;  // file RGB -> linear Rec. 709 (colorspace.h); none: identity
  double intensity = 1.0;   // linear factor on the radiance; finite and >= 0
  double rotate_deg = 0.0;  // yaw about +Y, as Skybox/Panoramic's _Rotation (rotate.h); finite
  Window window;            // deringing (window.h)
  bool l1 = false;          // band 2 removed, for Light Probe Proxy Volumes (document.h)
};

struct FinishedSh {
  ShL2 radiance;      // L_c,i with colour, intensity, rotation, window and L1 applied
  ShL2 unity_form;    // (A_l / pi) k_i L_c,i, windowed (convolution.h)
  WindowResult window;                                       // the factors the window applied
  std::array<SphereMinimum, kChannelCount> min_e_over_pi{};  // per channel, of unity_form
  UnitySphericalHarmonicsL2 unity_sh{};  // the 27 floats (unity_pack.h)
  UnityShaderVectors shader{};           // the seven float4 vectors
};

// An extracted light after the finish stage: in the output's colours and frame, scaled.
struct FinishedLight {
  SunLight light;
  UnitySunLight unity;  // unity_light.h
};

// Errors: Errc::InvalidArgument for an intensity or rotation out of its domain or a window
// that apply_window rejects; Errc::OutOfRange for a result too bright for Unity's float32
// coefficients (a float of to_unity_sh or to_shader_vectors would be infinite). `out` is
// left as it was.
Status finish_projection(const ShL2& projected_radiance, const FinishOptions& options, FinishedSh& out) noexcept;

// The same colour matrix, intensity and rotation applied to a light (its direction turned,
// its irradiance and sky level mixed and scaled), and its Unity form.
FinishedLight finish_light(const SunLight& light, const FinishOptions& options) noexcept;

// The option checks of finish_projection alone (intensity and rotation), for callers that
// want to refuse bad options before they read an image.
Status check_finish_options(const FinishOptions& options) noexcept;

// ---- The whole pipeline ---------------------------------------------------------------

inline constexpr unsigned kMaxExtractedLights = 8;  // --extract-lights N: 0 <= N <= this

struct ConvertOptions {
  MethodSpec method;                      // stage 3 (validate_method)
  NonFinite nonfinite = NonFinite::Error; // stage 3
  Negative negative = Negative::Keep;     // stage 3
  unsigned threads = 1;                   // stage 3; 0 = all cores
  bool extract_sun = false;               // stage 2
  unsigned extract_lights = 0;            // stage 2: at most this many lights (light_choice.h)
  FinishOptions finish;                   // stage 4
};

// What stage 2 took out of the map, in the map's frame and colours (unfinished).
struct Extraction {
  std::optional<SunLight> sun;     // --extract-sun found one
  std::vector<SunLight> lights;    // --extract-lights: the lights chosen, in the order chosen,
                                   // their irradiance fitted (light_fit.h)
  ShL2 removed;                    // --extract-lights: the radiance SH the lights take out of
                                   // the projection (their texels are left as they are)
  LightChoice choice;              // and how each lowered the error (light_choice.h)
  std::size_t candidates = 0;      // how many candidates were found (light_candidates.h)
};

// A light of --extract-lights, finished, with the max error of what Unity shows (view_error.h)
// with the lights chosen before it, and with it too.
struct ExtractedLight {
  FinishedLight light;
  double error_before_pct = 0, error_after_pct = 0;
};

struct Conversion {
  ProjectStats stats;                 // what the projector saw (sampling methods: their reads)
  FinishedSh sh;
  std::optional<FinishedLight> sun;   // extract_sun found one
  std::vector<ExtractedLight> lights; // extract_lights: those chosen, in the order chosen
  std::size_t light_candidates = 0;   // extract_lights: how many were found to choose from
  // What Unity shows against the exact E/pi of the input (view_error.h); absent only when
  // finish_conversion was given no reference.
  std::optional<ViewError> view_error;
};

// The checks that need no pixels: the method's parameter (validate_method), the finish
// options, a sampling method, --extract-sun or --extract-lights on a layout other than
// equirect, both extractions at once, more than kMaxExtractedLights lights, a cube frame
// other than Unity on a layout that is not a cube. InvalidArgument, naming the option.
Status check_convert_options(const ConvertOptions& options, Layout layout, CubeFrame cube_frame) noexcept;

// True when stage 2 runs: it needs the whole image, writable (MapImage::writable).
bool needs_transform(const ConvertOptions& options) noexcept;

// True when stage 3 can take the map in bands of rows (EquirectProjector), so that the
// source never holds the whole image: exact or center on an equirect map, no transform.
bool streams_rows(const ConvertOptions& options, Layout layout) noexcept;

// The value policy for NaN/Inf applied to what the projector counted: the projectors always
// run with NonFinite::Zero so that the whole image is seen, and then, under NonFinite::Error
// with nonfinite_texels > 0, this is Errc::NonFiniteTexel with the first texel's x, y (and
// face). Success otherwise.
Status apply_nonfinite_policy(const ProjectStats& stats, NonFinite policy) noexcept;

// Stages 2 to 4 on a whole image. On success `out` holds the result. On failure `out` is
// left as it was, except that under NonFiniteTexel `seen` (if given) receives the counts,
// with the first bad texel in image coordinates (in face coordinates and its face for
// Layout::Faces), so the caller can say how many there are and where.
Status convert_map(const MapImage& map, const ConvertOptions& options, Conversion& out,
                   ProjectStats* seen = nullptr) noexcept;

// Stage 2 on a whole equirect map. extract_sun: the sun is found and its texels set to their
// fill level in map.writable. extract_lights: the lights are chosen by choose_lights
// (light_choice.h) among the candidates of a search at each of kLightChoiceScales (up to
// kLightCandidateCount each, light_candidates.h), each set of lights tried with its colours
// fitted (light_fit.h), the measure being the max error (view_error.h, against `reference`,
// the input before any transform) of stage 4 on the exact projection of the map less the
// lights' SH, with their finished lights; the map is left as it is and
// Extraction::removed holds the SH to take out of its projection. Nothing is written when it
// fails.
Status extract_from_map(const MapImage& map, const ConvertOptions& options, const ViewSamples& reference,
                        Extraction& out) noexcept;

// Stage 4 on a projection made elsewhere (the streamed path, with no extraction) or by
// convert_map: the SH and the lights, and the view error against `reference`
// (view_error.h), sampled from the input before any transform.
Status finish_conversion(const ShL2& projected, const ProjectStats& stats, const Extraction& extraction,
                         const FinishOptions& options, const ViewSamples* reference, Conversion& out) noexcept;

// The reference E/pi (view_reference.h) of a whole map of any layout, under the projector's
// value policies (NaN/Inf read as 0), sampled at view_error.h's directions. Errors: BadView,
// InvalidArgument (faces of unequal sizes, a cube image of the wrong shape), OutOfMemory.
Status build_view_reference(const MapImage& map, const ProjectOptions& options, ViewReference& out) noexcept;
Status sample_map_reference(const MapImage& map, const ConvertOptions& options, ViewSamples& out) noexcept;

}  // namespace shpack
