// Lights that cover a cap of the sphere: the directional light with an angular diameter,
// the uniform cone and the sphere light (lights.h states the formulas and cites them).
#include <cmath>

#include "common/angles.h"
#include "lights/light_geometry.h"
#include "shpack/lights.h"

namespace shpack {
namespace {

// A cap about d with irradiance E at normal incidence and cos a = cos_a: the delta's
// coefficients times g = (2/(1 + cos a), 1, cos a) (lights.h, add_directional_light).
void add_cap(Vec3 d, double cos_a, const Rgb& irradiance, ShL2& out) noexcept {
  detail::add_zonal(d, irradiance, {2.0 / (1.0 + cos_a), 1.0, cos_a}, out);
}

}  // namespace

Status add_directional_light(Dir3 towards_light, double angular_diameter, const Rgb& irradiance,
                             ShL2& radiance) noexcept {
  Vec3 d;
  if (!detail::normalised(to_vec3(towards_light), d))
    return Status::error(Errc::InvalidArgument, "directional light: direction must be finite and non-zero");
  if (!(angular_diameter >= 0 && angular_diameter < kPi))
    return Status::error(Errc::InvalidArgument, "directional light: angular diameter must be in [0, pi)");
  if (!detail::valid_colour(irradiance))
    return Status::error(Errc::InvalidArgument, "directional light: irradiance must be finite and >= 0");
  add_cap(d, std::cos(0.5 * angular_diameter), irradiance, radiance);
  return Status::success();
}

Status add_cone_light(Dir3 axis, double half_angle, const Rgb& radiance, ShL2& out) noexcept {
  Vec3 d;
  if (!detail::normalised(to_vec3(axis), d))
    return Status::error(Errc::InvalidArgument, "cone light: axis must be finite and non-zero");
  if (!(half_angle >= 0 && half_angle <= kPi))
    return Status::error(Errc::InvalidArgument, "cone light: half-angle must be in [0, pi]");
  if (!detail::valid_colour(radiance))
    return Status::error(Errc::InvalidArgument, "cone light: radiance must be finite and >= 0");
  // Zonal integrals 2 pi int_{cos a}^1 P_l(t) dt [1] of lights.h, with 1 - cos a = 2 sin^2(a/2).
  const double s_half = std::sin(0.5 * half_angle), s = std::sin(half_angle);
  const double g1 = kPi * s * s;
  detail::add_zonal(d, radiance, {4.0 * kPi * s_half * s_half, g1, std::cos(half_angle) * g1}, out);
  return Status::success();
}

Status add_sphere_light(Point3 centre, double radius, const Rgb& intensity, Point3 probe,
                        ShL2& radiance) noexcept {
  const Vec3 to_light = detail::vec(centre) - detail::vec(probe);
  if (!detail::finite(to_light))
    return Status::error(Errc::InvalidArgument, "sphere light: position and probe must be finite");
  if (!(radius >= 0 && std::isfinite(radius)))
    return Status::error(Errc::InvalidArgument, "sphere light: radius must be finite and >= 0");
  if (!detail::valid_colour(intensity))
    return Status::error(Errc::InvalidArgument, "sphere light: intensity must be finite and >= 0");
  const double r = detail::length(to_light);
  if (!(r > radius)) return Status::error(Errc::ProbeInsideLight, "probe inside the sphere light");
  // sin a = R/r; cos a = sqrt(1 - R^2/r^2) = sqrt((r - R)(r + R))/r without cancellation.
  const double cos_a = std::sqrt((r - radius) * (r + radius)) / r;
  const double inv_r2 = 1.0 / (r * r);
  add_cap((1.0 / r) * to_light, cos_a,
          {intensity[0] * inv_r2, intensity[1] * inv_r2, intensity[2] * inv_r2}, radiance);
  return Status::success();
}

}  // namespace shpack
