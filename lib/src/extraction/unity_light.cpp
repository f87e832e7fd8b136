#include "shpack/unity_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "shpack/srgb.h"

namespace shpack {

UnitySunLight unity_sun_light(const SunLight& sun) noexcept {
  UnitySunLight light;
  light.forward = {-sun.direction.x, -sun.direction.y, -sun.direction.z};
  const double pitch = std::asin(std::clamp(-light.forward.y, -1.0, 1.0));
  const double yaw = std::atan2(light.forward.x, light.forward.z);
  light.euler_deg = {pitch / kDegree, yaw / kDegree, 0.0};
  const double sx = std::sin(0.5 * pitch), cx = std::cos(0.5 * pitch);
  const double sy = std::sin(0.5 * yaw), cy = std::cos(0.5 * yaw);
  light.quaternion = {cy * sx, sy * cx, -sy * sx, cy * cx};
  std::array<double, 3> e_over_pi;
  for (int c = 0; c < 3; ++c) e_over_pi[c] = std::max(0.0, sun.irradiance[c]) / std::numbers::pi;
  light.intensity = std::max({e_over_pi[0], e_over_pi[1], e_over_pi[2]});
  for (int c = 0; c < 3; ++c) {
    light.colour[c] = light.intensity > 0 ? e_over_pi[c] / light.intensity : 0.0;
    light.colour_srgb[c] = linear_to_srgb(light.colour[c]);
  }
  return light;
}

}  // namespace shpack
