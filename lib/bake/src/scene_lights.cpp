#include "scene_lights.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "shpack/lights.h"

namespace shpack::bake {
namespace {

constexpr double kPi = std::numbers::pi;
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
    scale = 1.0 / (kPi * s * s);  // E = L pi sin^2 a
  } else if (light.type == LightType::Sphere) {
    scale = 1.0 / (kPi * light.radius * light.radius);  // I = pi R^2 L
  }
  for (double& v : out) v *= scale;
  return out;
}

bool is_delta(const scene::SceneLight& light) noexcept {
  return light.type == LightType::Point || light.type == LightType::Spot ||
         (light.type == LightType::Directional && light.angular_diameter == 0) ||
         (light.type == LightType::Sphere && light.radius == 0);
}

// Cap about unit d with 1 - cos a = one_minus_cos: n_u strata in u = cos theta', each with the
// 2-point Gauss rule, times n_phi equally spaced azimuths with a random offset: exact for
// every polynomial of degree <= 2 in the direction over each stratum (bake.h).
void sample_cap(Vec3d d, double one_minus_cos, int wanted, Rng& rng, std::vector<LightSample>& out,
                const std::function<double(Vec3d)>& distance) {
  const int n_u = std::max(1, static_cast<int>(std::ceil(std::sqrt(wanted / 2.0))));
  const int n_phi = std::max(3, (wanted + 2 * n_u - 1) / (2 * n_u));
  Vec3d e1, e2;
  basis_of(d, e1, e2);
  const double offset = rng.uniform();
  const double g = 0.5 / std::sqrt(3.0);  // Gauss nodes at 1/2 -+ g of each stratum
  for (int k = 0; k < n_u; ++k) {
    for (const double node : {0.5 - g, 0.5 + g}) {
      // v = 1 - u, measured from the pole, so sin theta' = sqrt(v (2 - v)) keeps its digits.
      const double v = one_minus_cos * (k + node) / n_u;
      const double s = std::sqrt(v * (2.0 - v)), u = 1.0 - v;
      for (int j = 0; j < n_phi; ++j) {
        const double phi = 2.0 * kPi * (j + offset) / n_phi;
        const Vec3d w = u * d + (s * std::cos(phi)) * e1 + (s * std::sin(phi)) * e2;
        out.push_back({w, distance(w), 0.5 * (one_minus_cos / n_u) * (2.0 * kPi / n_phi)});
      }
    }
  }
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

void sample_light(const scene::SceneLight& light, Vec3d from, int wanted, Rng& rng, LightSamples& out) {
  out.samples.clear();
  out.radiance = extended_radiance(light);
  if (is_delta(light)) {
    const bool directional = light.type == LightType::Directional;
    const Vec3d to = directional ? -1.0 * vec(light.direction) : vec(light.position) - from;
    const double dist = directional ? kInf : norm(to);
    out.samples.push_back({directional ? to : (1.0 / dist) * to, dist, 0.0});
    return;
  }
  switch (light.type) {
    case LightType::Directional: {
      const double s = std::sin(0.25 * light.angular_diameter);  // 1 - cos a = 2 sin^2(a/2)
      sample_cap(-1.0 * vec(light.direction), 2.0 * s * s, wanted, rng, out.samples,
                 [](Vec3d) { return kInf; });
      return;
    }
    case LightType::Sphere: {
      const Vec3d c = vec(light.position), pc = c - from;
      const double r = norm(pc), radius = light.radius;
      // 1 - cos a = (R/r)^2 / (1 + cos a), cos a = sqrt((r - R)(r + R)) / r.
      const double cos_a = std::sqrt((r - radius) * (r + radius)) / r;
      sample_cap((1.0 / r) * pc, (radius / r) * (radius / r) / (1.0 + cos_a), wanted, rng, out.samples,
                 [&](Vec3d w) { return sphere_distance(from, w, c, radius); });
      return;
    }
    case LightType::Rect:
    case LightType::Disk: {
      // Stratified points over the area (a grid in (s, t), or in (r^2, phi) for the disk,
      // both area-preserving), weight dA cos(theta_x) / d^2. Points the probe sees from
      // behind get weight 0.
      const int n1 = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(wanted)))));
      const int n2 = std::max(1, (wanted + n1 - 1) / n1);
      const bool rect = light.type == LightType::Rect;
      const Vec3d c = vec(light.position);
      Vec3d e1 = vec(light.right), e2 = vec(light.up), n = cross(e1, e2);
      if (!rect) {
        n = vec(light.direction);
        basis_of(n, e1, e2);
      }
      const double area = rect ? light.width * light.height : kPi * light.radius * light.radius;
      for (int a = 0; a < n1; ++a)
        for (int b = 0; b < n2; ++b) {
          const double s = (a + rng.uniform()) / n1, t = (b + rng.uniform()) / n2;
          Vec3d x;
          if (rect) {
            x = c + ((s - 0.5) * light.width) * e1 + ((t - 0.5) * light.height) * e2;
          } else {
            const double rho = light.radius * std::sqrt(s), phi = 2.0 * kPi * t;
            x = c + (rho * std::cos(phi)) * e1 + (rho * std::sin(phi)) * e2;
          }
          const Vec3d to = x - from;
          const double dist = norm(to);
          const Vec3d w = (1.0 / dist) * to;
          const double cos_x = -dot(n, w);
          out.samples.push_back({w, dist, cos_x > 0 ? area / (n1 * n2) * cos_x / (dist * dist) : 0.0});
        }
      return;
    }
    default: return;  // distant lights are never sampled
  }
}

Rgb light_irradiance(const scene::SceneLight& light, Vec3d x, Vec3d n, double epsilon, const Tracer& tracer,
                     Rng& rng, std::uint64_t& rays) {
  Rgb out{0, 0, 0};
  if (is_distant(light)) return out;
  Rgb radiance = extended_radiance(light);
  Vec3d dir;
  double distance = kInf, weight = 0;  // weight: 1 / pdf in solid angle (or the delta's E)
  if (is_delta(light)) {
    LightSamples s;
    sample_light(light, x, 1, rng, s);
    dir = s.samples.front().dir;
    distance = s.samples.front().distance;
    // E = I f / r^2 (point, spot) or E (directional), times the cosine below.
    weight = 1.0;
    radiance = light.colour;
    if (light.type != LightType::Directional) {
      weight = 1.0 / (distance * distance);
      if (light.type == LightType::Spot)
        weight *= spot_falloff({light.position, light.direction, light.inner_angle, light.outer_angle},
                               -dot(vec(light.direction), dir));
    }
  } else if (light.type == LightType::Directional || light.type == LightType::Sphere) {
    // One direction uniform in the cap: v = 1 - cos theta' uniform in [0, 1 - cos a].
    Vec3d axis = -1.0 * vec(light.direction);
    double one_minus_cos;
    if (light.type == LightType::Directional) {
      const double s = std::sin(0.25 * light.angular_diameter);
      one_minus_cos = 2.0 * s * s;
    } else {
      const Vec3d pc = vec(light.position) - x;
      const double r = norm(pc);
      if (r <= light.radius) return out;  // a surface inside the light: not lit by it
      const double cos_a = std::sqrt((r - light.radius) * (r + light.radius)) / r;
      one_minus_cos = (light.radius / r) * (light.radius / r) / (1.0 + cos_a);
      axis = (1.0 / r) * pc;
    }
    Vec3d e1, e2;
    basis_of(axis, e1, e2);
    const double v = one_minus_cos * rng.uniform(), phi = 2.0 * kPi * rng.uniform();
    const double s = std::sqrt(v * (2.0 - v));
    dir = (1.0 - v) * axis + (s * std::cos(phi)) * e1 + (s * std::sin(phi)) * e2;
    weight = 2.0 * kPi * one_minus_cos;
    if (light.type == LightType::Sphere) distance = sphere_distance(x, dir, vec(light.position), light.radius);
  } else {
    LightSamples s;  // rect or disk: one uniform point of the area, weight A cos_x / d^2
    sample_light(light, x, 1, rng, s);
    dir = s.samples.front().dir;
    distance = s.samples.front().distance;
    weight = s.samples.front().weight;
  }
  const double scale = weight * dot(n, dir);
  if (!(scale > 0)) return out;
  ++rays;
  if (tracer.occluded(x, dir, epsilon, distance * (1.0 - 1e-7))) return out;
  for (int c = 0; c < 3; ++c) out[c] = radiance[c] * scale;
  return out;
}

}  // namespace shpack::bake
