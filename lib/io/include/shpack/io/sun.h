// sun.h - the sun of an HDRI as a Unity directional light, and the map without it
// (`shpack convert --extract-sun`): a shadow-casting sun plus soft ambient SH, with the sun's
// light counted once.
//
// Finding it, on an equirect map held as float texels (luminance Y with Unity's weights, as
// preview.h):
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
// Removing it: each disc texel is set to L_sky. What was removed, e_t = L_t - L_sky per channel,
// carries the flux vector m_c = sum_t e_t,c int_t w dw (exact texel integrals). The sun's
// direction d is the unit vector along the luminance-weighted m, and its irradiance at normal
// incidence E_c = d . m_c: the irradiance the removed texels give a plane facing d (for a disc of
// angular radius a this differs from the flux sum_t e Omega by a factor within cos a of 1).
//
// As a Unity directional light. A directional light shines along its transform's forward, +Z
// (Unity Manual, "Directional Light"): forward = -d. Rotation: Euler angles as Unity's
// Transform.eulerAngles (degrees, applied Z, then X, then Y, all about world axes; roll 0):
// pitch x = asin(-forward.y) (positive looks down), yaw y = atan2(forward.x, forward.z); the
// same rotation as a quaternion (x, y, z, w) = (cos(y/2) sin(x/2), sin(y/2) cos(x/2),
// -sin(y/2) sin(x/2), cos(y/2) cos(x/2)), which turns +Z into forward. Colour and intensity: Unity's
// diffuse term for a light is albedo * colour * intensity * max(0, n.l), with no 1/pi, while a
// white Lambertian surface under the sun leaves E max(0, n.l) / pi; so colour * intensity =
// E / pi (linear). intensity is the largest channel of E / pi and colour the rest (its largest
// channel is 1), linear; color_srgb is the same colour sRGB-encoded, for an Inspector colour
// field in a gamma-space colour picker. Whether a project multiplies colour and intensity in
// linear or in gamma space (GraphicsSettings.lightsUseLinearIntensity) is Unity's setting:
// colour * intensity = E / pi holds as stated only for linear intensity.
#pragma once

#include <array>
#include <filesystem>
#include <optional>

#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/io/convert.h"
#include "shpack/io/io_status.h"
#include "shpack/io/sh_document.h"

namespace shpack::io {

inline constexpr double kSunThreshold = 0.05;     // of the peak's luminance
inline constexpr double kSunMaxRadiusDeg = 5.0;   // the sun (0.27 degrees) blurred by the camera
inline constexpr double kSunGuardDeg = 1.0;       // step 3
inline constexpr double kSunRingGapDeg = 0.5;     // step 4
inline constexpr double kSunRingWidthDeg = 2.0;
inline constexpr double kSunMinContrast = 20.0;   // step 5

// Finds the sun of a resolved equirect view of finite F32 texels (1 channel grey, or R, G, B
// first, packed as make_view makes them) and, if there is one, sets its texels to the sky
// level in `pixels`, the writable memory the view points into. The result is in the map's
// frame, unscaled.
std::optional<SunLight> extract_sun(const ImageView& image, float* pixels);

// convert_env_map (convert.h) with the sun taken out first: reads the whole map, extracts the
// sun, projects the rest with settings.method and finishes it as convert does
// (pipeline.h); doc.sun_extraction is set, and doc.sun holds the sun (scaled by the
// intensity and turned with the map) if one was found. Errors as convert_env_map, plus
// Unsupported for a layout other than equirect.
IoStatus convert_env_map_extracting_sun(const std::filesystem::path& path, const ConvertSettings& settings,
                                        ShDocument& out);

// The sun as Unity's light: forward, Euler angles, quaternion, linear colour and intensity.
struct UnitySunLight {
  Dir3 forward;                      // -direction
  std::array<double, 3> euler_deg{};  // (pitch, yaw, 0)
  std::array<double, 4> quaternion{};  // (x, y, z, w)
  std::array<double, 3> colour{};     // linear, largest channel 1 (0, 0, 0 if E = 0)
  std::array<double, 3> colour_srgb{};
  double intensity = 0;               // colour * intensity = E / pi
};
UnitySunLight unity_sun_light(const SunLight& sun);

}  // namespace shpack::io
