#include "scene_lights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "shpack/lights.h"

namespace shpack::bake {
namespace {

using std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
using scene::LightType;

// Whether origin + t d, t in [0, t_max], meets the box [lo - grow, hi + grow] (slab test;
// a zero component of d is an infinite slope, handled by the comparisons with infinities).
bool segment_meets_box(Vec3d origin, Vec3d d, double t_max, const Bounds& b, double grow) noexcept {
  double t0 = 0, t1 = t_max;
  const double o[3] = {origin.x, origin.y, origin.z}, dir[3] = {d.x, d.y, d.z};
  const double lo[3] = {b.lo.x - grow, b.lo.y - grow, b.lo.z - grow}, hi[3] = {b.hi.x + grow, b.hi.y + grow, b.hi.z + grow};
  for (int k = 0; k < 3; ++k) {
    if (dir[k] == 0) {
      if (o[k] < lo[k] || o[k] > hi[k]) return false;
      continue;
    }
    double near = (lo[k] - o[k]) / dir[k], far = (hi[k] - o[k]) / dir[k];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return false;
  }
  return true;
}

// Distance along unit w from p to the sphere (c, R) seen from outside, by the root without
// cancellation: t = (|c-p|^2 - R^2) / (b + sqrt(b^2 - |c-p|^2 + R^2)), b = w.(c - p).
double sphere_distance(Vec3d p, Vec3d w, Vec3d c, double radius) noexcept {
  const Vec3d pc = c - p;
  const double b = dot(w, pc), k = (norm(pc) - radius) * (norm(pc) + radius);
  return k / (b + std::sqrt(std::fmax(0.0, b * b - k)));
}

// Uniform radiance of an extended light (lights.h's normalisations).
Rgb extended_radiance(const scene::SceneLight& light) noexcept {
  Rgb out = light.colour;
  double scale = 1.0;
  if (light.type == LightType::Directional) {
    const double s = std::sin(0.5 * light.angular_diameter);
    scale = 1.0 / (pi * s * s);  // E = L pi sin^2 a
  } else if (light.type == LightType::Sphere) {
    scale = 1.0 / (pi * light.radius * light.radius);  // I = pi R^2 L
  }
  for (double& v : out) v *= scale;
  return out;
}

// 1 - cos a of the cap a sphere light or a sun subtends from `from` (0 if `from` is inside
// the sphere), and its axis: 1 - cos a = (R/r)^2 / (1 + cos a) for a sphere, without
// cancellation; 2 sin^2(a/2) for a sun of angular diameter 2a.
double cap_of(const scene::SceneLight& light, Vec3d from, Vec3d& axis) noexcept {
  if (light.type == LightType::Directional) {
    axis = -1.0 * vec(light.direction);
    const double s = std::sin(0.25 * light.angular_diameter);
    return 2.0 * s * s;
  }
  const Vec3d pc = vec(light.position) - from;
  const double r = norm(pc);
  if (r <= light.radius) return 0;
  axis = (1.0 / r) * pc;
  const double cos_a = std::sqrt((r - light.radius) * (r + light.radius)) / r;
  return (light.radius / r) * (light.radius / r) / (1.0 + cos_a);
}

}  // namespace

Status add_light(const scene::SceneLight& light, Point3 probe, ShL2& radiance) noexcept {
  switch (light.type) {
    case LightType::Directional:
      return add_directional_light({-light.direction.x, -light.direction.y, -light.direction.z},
                                   light.angular_diameter, light.colour, radiance);
    case LightType::Point: return add_point_light(light.position, light.colour, probe, radiance);
    case LightType::Sphere: return add_sphere_light(light.position, light.radius, light.colour, probe, radiance);
    case LightType::Spot:
      return add_spot_light({light.position, light.direction, light.inner_angle, light.outer_angle}, light.colour,
                            probe, radiance);
    case LightType::Rect:
      return add_rect_light({light.position, light.right, light.up, light.width, light.height}, light.colour, probe,
                            radiance);
    case LightType::Disk:
      return add_disk_light({light.position, light.direction, light.radius}, light.colour, probe, radiance);
    case LightType::Hemisphere: return add_hemisphere_light(light.colour, light.ground, radiance);
    case LightType::Ambient: return add_ambient_light(light.colour, radiance);
  }
  return Status::error(Errc::InvalidArgument, "unknown light type");
}

bool is_distant(const scene::SceneLight& light) noexcept {
  return light.type == LightType::Hemisphere || light.type == LightType::Ambient;
}

Rgb distant_radiance(const scene::SceneLight& light, Vec3d d) noexcept {
  if (light.type == LightType::Ambient) return light.colour;
  if (light.type == LightType::Hemisphere) return d.y > 0 ? light.colour : light.ground;
  return {0, 0, 0};
}

Bounds shape_bounds(const scene::SceneShape& shape) noexcept {
  Vec3d lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
  if (shape.type == scene::ShapeType::Sphere) {
    const Vec3d c = vec(shape.centre), r{shape.radius, shape.radius, shape.radius};
    lo = c - r;
    hi = c + r;
  } else {
    const std::vector<float>& v = shape.vertices;
    for (std::size_t k = 0; k + 2 < v.size(); k += 3) {
      lo = {std::fmin(lo.x, v[k]), std::fmin(lo.y, v[k + 1]), std::fmin(lo.z, v[k + 2])};
      hi = {std::fmax(hi.x, v[k]), std::fmax(hi.y, v[k + 1]), std::fmax(hi.z, v[k + 2])};
    }
  }
  // Widened by what float rounding (Embree's, and of float vertices) can move a surface.
  const double pad = 1e-6 * (1.0 + std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(lo.z), std::fabs(hi.x),
                                             std::fabs(hi.y), std::fabs(hi.z)}));
  return {lo - Vec3d{pad, pad, pad}, hi + Vec3d{pad, pad, pad}};
}

bool can_shadow(const scene::SceneLight& light, Vec3d probe, const Bounds& b) noexcept {
  switch (light.type) {
    case LightType::Directional: {
      // The cone of half-angle a about d: within the box, no wider than tan(a) times the
      // distance to the box's farthest corner.
      const Vec3d d = -1.0 * vec(light.direction);
      const Vec3d far{std::max(std::fabs(b.lo.x - probe.x), std::fabs(b.hi.x - probe.x)),
                      std::max(std::fabs(b.lo.y - probe.y), std::fabs(b.hi.y - probe.y)),
                      std::max(std::fabs(b.lo.z - probe.z), std::fabs(b.hi.z - probe.z))};
      return segment_meets_box(probe, d, kInf, b, std::tan(0.5 * light.angular_diameter) * norm(far));
    }
    case LightType::Point:
    case LightType::Spot:
    case LightType::Sphere:
    case LightType::Disk:
    case LightType::Rect: {
      const double grow = light.type == LightType::Rect ? 0.5 * std::hypot(light.width, light.height)
                          : light.type == LightType::Sphere || light.type == LightType::Disk ? light.radius
                                                                                            : 0.0;
      return segment_meets_box(probe, vec(light.position) - probe, 1.0, b, grow);
    }
    case LightType::Hemisphere:
    case LightType::Ambient: return false;
  }
  return true;
}

bool is_delta(const scene::SceneLight& light) noexcept {
  return light.type == LightType::Point || light.type == LightType::Spot ||
         (light.type == LightType::Directional && light.angular_diameter == 0) ||
         (light.type == LightType::Sphere && light.radius == 0);
}

Rgb light_radiance(const scene::SceneLight& light) noexcept { return extended_radiance(light); }

LightSample light_point(const scene::SceneLight& light, Vec3d from, double u1, double u2) noexcept {
  if (is_delta(light)) {
    const bool directional = light.type == LightType::Directional;
    const Vec3d to = directional ? -1.0 * vec(light.direction) : vec(light.position) - from;
    const double dist = directional ? kInf : norm(to);
    return {directional ? to : (1.0 / dist) * to, dist, 0.0};
  }
  switch (light.type) {
    case LightType::Directional:
    case LightType::Sphere: {
      // Uniform in the cap: v = 1 - cos theta' uniform in [0, 1 - cos a], measured from the
      // pole so that sin theta' = sqrt(v (2 - v)) keeps its digits; weight Omega = 2 pi (1 - cos a).
      Vec3d axis, e1, e2;
      const double one_minus_cos = cap_of(light, from, axis);
      if (one_minus_cos == 0) return {};
      basis_of(axis, e1, e2);
      const double v = one_minus_cos * u1, s = std::sqrt(v * (2.0 - v)), phi = 2.0 * pi * u2;
      const Vec3d w = (1.0 - v) * axis + (s * std::cos(phi)) * e1 + (s * std::sin(phi)) * e2;
      const double dist =
          light.type == LightType::Sphere ? sphere_distance(from, w, vec(light.position), light.radius) : kInf;
      return {w, dist, 2.0 * pi * one_minus_cos};
    }
    case LightType::Rect:
    case LightType::Disk: {
      // Uniform by area ((s, t), or (r^2, phi) for the disk: both area-preserving), weight
      // A cos(theta_x) / d^2; a point the probe sees from behind weighs 0.
      const bool rect = light.type == LightType::Rect;
      const Vec3d c = vec(light.position);
      Vec3d e1 = vec(light.right), e2 = vec(light.up), n = cross(e1, e2);
      if (!rect) {
        n = vec(light.direction);
        basis_of(n, e1, e2);
      }
      const double area = rect ? light.width * light.height : pi * light.radius * light.radius;
      Vec3d x;
      if (rect) {
        x = c + ((u1 - 0.5) * light.width) * e1 + ((u2 - 0.5) * light.height) * e2;
      } else {
        const double rho = light.radius * std::sqrt(u1), phi = 2.0 * pi * u2;
        x = c + (rho * std::cos(phi)) * e1 + (rho * std::sin(phi)) * e2;
      }
      const Vec3d to = x - from;
      const double dist = norm(to);
      const Vec3d w = (1.0 / dist) * to;
      const double cos_x = -dot(n, w);
      return {w, dist, cos_x > 0 ? area * cos_x / (dist * dist) : 0.0};
    }
    default: return {};  // distant lights are never sampled
  }
}

Rgb light_irradiance(const scene::SceneLight& light, Vec3d x, Vec3d n, double epsilon, const Tracer& tracer,
                     double u1, double u2, std::uint64_t& rays) {
  Rgb out{0, 0, 0};
  if (is_distant(light)) return out;
  const LightSample s = light_point(light, x, u1, u2);
  Rgb radiance = extended_radiance(light);
  double weight = s.weight;  // 1 / pdf in solid angle; for a delta light, its E below
  if (is_delta(light)) {
    // E = I f / r^2 (point, spot) or E (directional), times the cosine below.
    radiance = light.colour;
    weight = 1.0;
    if (light.type != LightType::Directional) {
      weight = 1.0 / (s.distance * s.distance);
      if (light.type == LightType::Spot)
        weight *= spot_falloff({light.position, light.direction, light.inner_angle, light.outer_angle},
                               -dot(vec(light.direction), s.dir));
    }
  }
  const double scale = weight * dot(n, s.dir);
  if (!(scale > 0)) return out;
  ++rays;
  if (tracer.occluded(x, s.dir, epsilon, s.distance * (1.0 - 1e-7))) return out;
  for (int c = 0; c < 3; ++c) out[c] = radiance[c] * scale;
  return out;
}

}  // namespace shpack::bake
