// Delta lights at a position: the point light and the spot light (lights.h).
#include <cmath>
#include <numbers>

#include "lights/light_geometry.h"
#include "shpack/lights.h"

namespace shpack {

Status add_point_light(Point3 position, const Rgb& intensity, Point3 probe, ShL2& radiance) noexcept {
  const Vec3 to_light = detail::vec(position) - detail::vec(probe);
  if (!detail::finite(to_light))
    return Status::error(Errc::InvalidArgument, "point light: position and probe must be finite");
  if (!detail::valid_colour(intensity))
    return Status::error(Errc::InvalidArgument, "point light: intensity must be finite and >= 0");
  const double r = detail::length(to_light);
  if (!(r > 0)) return Status::error(Errc::ProbeInsideLight, "probe at the point light's position");
  // Irradiance I / r^2 from d: the delta L_i = E Y_i(d).
  const double inv_r2 = 1.0 / (r * r);
  detail::add_zonal((1.0 / r) * to_light, {intensity[0] * inv_r2, intensity[1] * inv_r2, intensity[2] * inv_r2},
                    {1.0, 1.0, 1.0}, radiance);
  return Status::success();
}

double spot_falloff(const SpotLight& spot, double cos_t) noexcept {
  // KHR_lights_punctual [6] of lights.h: a smooth square of the linear ramp in cos t. The
  // comparisons come first, so a hard edge (inner == outer) never divides by zero.
  const double cos_inner = std::cos(spot.inner_angle), cos_outer = std::cos(spot.outer_angle);
  if (cos_t >= cos_inner) return 1.0;
  if (cos_t <= cos_outer) return 0.0;
  const double s = (cos_t - cos_outer) / (cos_inner - cos_outer);
  return s * s;
}

Status add_spot_light(const SpotLight& spot, const Rgb& intensity, Point3 probe,
                      ShL2& radiance) noexcept {
  Vec3 axis;
  if (!detail::normalised(to_vec3(spot.axis), axis))
    return Status::error(Errc::InvalidArgument, "spot light: axis must be finite and non-zero");
  if (!(spot.inner_angle >= 0 && spot.inner_angle <= spot.outer_angle &&
        spot.outer_angle <= std::numbers::pi))
    return Status::error(Errc::InvalidArgument, "spot light: need 0 <= inner angle <= outer angle <= pi");
  if (!detail::valid_colour(intensity))
    return Status::error(Errc::InvalidArgument, "spot light: intensity must be finite and >= 0");
  const Vec3 to_light = detail::vec(spot.position) - detail::vec(probe);
  if (!detail::finite(to_light))
    return Status::error(Errc::InvalidArgument, "spot light: position and probe must be finite");
  const double r = detail::length(to_light);
  if (!(r > 0)) return Status::error(Errc::ProbeInsideLight, "probe at the spot light's position");
  const Vec3 d = (1.0 / r) * to_light;
  // t is the angle between the axis and the direction from the light to the probe, -d.
  const double e = spot_falloff(spot, -dot(axis, d)) / (r * r);
  detail::add_zonal(d, {intensity[0] * e, intensity[1] * e, intensity[2] * e}, {1.0, 1.0, 1.0}, radiance);
  return Status::success();
}

}  // namespace shpack
