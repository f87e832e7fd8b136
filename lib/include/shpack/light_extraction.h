// light_extraction.h - the sun of an equirect map taken out as a light, the image transform
// of `convert --extract-sun` (pipeline.h, stage 3: image in, image + light out), so that a
// shadow-casting light and the soft rest can be lit separately with the sun counted once.
//
// Finding it, on an equirect map held as float texels, with luminance Y = w . rgb for the
// caller's weights w (Rec. 709 luminance of the output primaries: kRec709Luminance when the
// file is Rec. 709, M^T kRec709Luminance for a colour matrix M, colorspace.h):
//  1. the peak: the texel of largest Y (none if Y <= 0 everywhere);
//  2. the disc: every texel within kSunMaxRadiusDeg of the peak's direction whose Y is at
//     least kSunThreshold times the peak's. Angles are measured on the sphere, so the disc
//     wraps around the left and right edges and over the poles like the sky does;
//  3. it must be compact: no texel between kSunMaxRadiusDeg and kSunMaxRadiusDeg +
//     kSunGuardDeg from the peak reaches the threshold (else the bright region is larger than
//     a sun: an overcast sky, a window, a lamp-lit wall);
//  4. the surrounding sky level L_sky (per channel) is the solid-angle-weighted mean of the
//     ring from r + kSunRingGapDeg to r + kSunRingGapDeg + kSunRingWidthDeg, r being the
//     disc's radius (its farthest texel centre from the peak plus half a texel diagonal);
//  5. it must stand out: peak Y >= kSunMinContrast * Y(L_sky).
// Otherwise there is no sun and the map is used whole.
//
// Values are read as the projector reads them (project.h): a NaN/Inf channel counts as 0
// (the projector then fails or zeroes it, by its policy), a negative one as 0 under
// Negative::Clamp.
//
// Removing it: each disc texel is set to L_sky. What was removed, e_t = L_t - L_sky per
// channel, carries the flux vector m_c = sum_t e_t,c int_t w dw (exact texel integrals). The
// sun's direction d is the unit vector along the luminance-weighted m, and its irradiance at
// normal incidence E_c = d . m_c: the irradiance the removed texels give a plane facing d
// (for a disc of angular radius a this differs from the flux sum_t e Omega by a factor
// within cos a of 1). The light is in the map's frame and colours, unscaled: the finish stage
// (pipeline.h) applies the colour matrix, the intensity and the rotation to it as to the SH.
//
// Several compact sources of a map (a sun and lamps, softboxes, windows), each found with the
// same texel reading, ring level and flux vector, are light_candidates.h's.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/status.h"

namespace shpack {

inline constexpr double kSunThreshold = 0.05;     // of the peak's luminance
inline constexpr double kSunMaxRadiusDeg = 5.0;   // the sun (0.27 degrees) blurred by the camera
inline constexpr double kSunGuardDeg = 1.0;       // step 3
inline constexpr double kSunRingGapDeg = 0.5;     // step 4
inline constexpr double kSunRingWidthDeg = 2.0;
inline constexpr double kSunMinContrast = 20.0;   // step 5

// Unity's LinearRgbToLuminance (UnityCG.cginc): Rec. 709 luminance of linear RGB.
inline constexpr std::array<double, 3> kRec709Luminance = {0.2126729, 0.7151522, 0.0721750};

// The sun taken out of a map.
struct SunLight {
  Dir3 direction;                      // unit, towards the sun
  std::array<double, 3> irradiance{};  // E per channel at normal incidence (radiance x sr)
  std::array<double, 3> sky{};         // the sky level its texels were set to
  double radius_deg = 0;               // angular radius of the removed disc
  double solid_angle = 0;              // of the removed texels, sr
  std::uint64_t texels = 0;            // how many were removed
  double offset_deg = 0;               // --extract-lights: the angle from its source's centre (light_fit.h)

  friend bool operator==(const SunLight&, const SunLight&) = default;
};

struct SunSearch {
  std::array<double, 3> luminance = kRec709Luminance;  // w of Y = w . rgb (above)
  Negative negative = Negative::Keep;                  // as the projector will read the texels
};

// Finds the sun of an equirect view (resolve_view is applied) of F32 texels (1 channel grey, or R, G, B first,
// packed as make_view makes them) and, if there is one, sets its texels to the sky level in
// `pixels`, the writable memory the view points into. `sun` is empty when the map has none.
// Errors: BadView (resolve_view), InvalidArgument for a view that is not F32 or no pixels,
// OutOfMemory.
Status extract_sun(const ImageView& image, float* pixels, const SunSearch& search,
                   std::optional<SunLight>& sun) noexcept;

}  // namespace shpack
