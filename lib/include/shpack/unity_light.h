// unity_light.h - a light taken out of a map (light_extraction.h) as a Unity directional light.
//
// A directional light shines along its transform's forward, +Z (Unity Manual, "Directional
// Light"): forward = -d. Rotation: Euler angles as Unity's Transform.eulerAngles (degrees,
// applied Z, then X, then Y, all about world axes; roll 0): pitch x = asin(-forward.y)
// (positive looks down), yaw y = atan2(forward.x, forward.z); the same rotation as a
// quaternion (x, y, z, w) = (cos(y/2) sin(x/2), sin(y/2) cos(x/2), -sin(y/2) sin(x/2),
// cos(y/2) cos(x/2)), which turns +Z into forward. Colour and intensity: Unity's diffuse term
// for a light is albedo * colour * intensity * max(0, n.l), with no 1/pi, while a white
// Lambertian surface under the sun leaves E max(0, n.l) / pi; so colour * intensity = E / pi
// (linear). intensity is the largest channel of E / pi and colour the rest (its largest
// channel is 1), linear; color_srgb is the same colour sRGB-encoded (srgb.h), for an
// Inspector colour field in a gamma-space colour picker. Whether a project multiplies colour
// and intensity in linear or in gamma space (GraphicsSettings.lightsUseLinearIntensity) is
// Unity's setting: colour * intensity = E / pi holds as stated only for linear intensity.
#pragma once

#include <array>

#include "shpack/conventions.h"
#include "shpack/light_extraction.h"

namespace shpack {

struct UnitySunLight {
  Dir3 forward;                        // -direction
  std::array<double, 3> euler_deg{};   // (pitch, yaw, 0)
  std::array<double, 4> quaternion{};  // (x, y, z, w)
  std::array<double, 3> colour{};      // linear, largest channel 1 (0, 0, 0 if E = 0)
  std::array<double, 3> colour_srgb{};
  double intensity = 0;                // colour * intensity = E / pi
};

UnitySunLight unity_sun_light(const SunLight& sun) noexcept;

}  // namespace shpack
