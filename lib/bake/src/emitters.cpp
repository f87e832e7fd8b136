#include "emitters.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sampling.h"

namespace shpack::bake {
namespace {

using std::numbers::pi;

Vec3d vertex(const scene::SceneShape& s, std::uint32_t index) noexcept {
  const std::size_t k = 3 * static_cast<std::size_t>(s.indices[index]);
  return {s.vertices[k], s.vertices[k + 1], s.vertices[k + 2]};
}

double triangle_area(const scene::SceneShape& s, std::size_t t) noexcept {
  const auto k = static_cast<std::uint32_t>(3 * t);
  const Vec3d a = vertex(s, k), b = vertex(s, k + 1), c = vertex(s, k + 2);
  return 0.5 * norm(cross(b - a, c - a));
}

// The interval of a normalised cdf that u falls in, u rescaled to [0, 1) inside it (one
// uniform number for the choice and for what follows, keeping its strata).
std::size_t pick(const std::vector<double>& cdf, double& u) noexcept {
  const std::size_t n = cdf.size() - 1;
  std::size_t k = static_cast<std::size_t>(std::upper_bound(cdf.begin() + 1, cdf.end(), u) - cdf.begin()) - 1;
  k = std::min(k, n - 1);
  while (k > 0 && cdf[k + 1] == cdf[k]) --k;
  const double width = cdf[k + 1] - cdf[k];
  u = width > 0 ? std::clamp((u - cdf[k]) / width, 0.0, 1.0) : 0.5;
  return k;
}

// Whether `from` is outside the sphere, and its cone's 1 - cos(alpha) (bake's rule,
// 1 - cos a = (R/r)^2 / (1 + cos a), without cancellation).
bool cone_of(const scene::SceneShape& s, const Vec3d& from, Vec3d& axis, double& distance,
             double& one_minus_cos) noexcept {
  const Vec3d pc = vec(s.centre) - from;
  distance = norm(pc);
  if (!(distance > s.radius * (1 + 1e-9))) return false;
  axis = (1.0 / distance) * pc;
  const double cos_a = std::sqrt((distance - s.radius) * (distance + s.radius)) / distance;
  one_minus_cos = (s.radius / distance) * (s.radius / distance) / (1.0 + cos_a);
  return true;
}

}  // namespace

EmitterSampler::EmitterSampler(const std::vector<scene::SceneShape>& geometry)
    : geometry_(geometry), emitter_of_(geometry.size(), -1) {
  std::vector<double> power;
  for (std::uint32_t s = 0; s < geometry.size(); ++s) {
    const scene::SceneShape& shape = geometry[s];
    const double radiance = (shape.emission[0] + shape.emission[1] + shape.emission[2]) / 3.0;
    if (!(radiance > 0)) continue;
    Emitter e;
    e.shape = s;
    if (shape.type == scene::ShapeType::Sphere) {
      e.area = 4.0 * pi * shape.radius * shape.radius;
    } else {
      const std::size_t n = shape.indices.size() / 3;
      e.triangle_cdf.assign(n + 1, 0.0);
      for (std::size_t t = 0; t < n; ++t) e.triangle_cdf[t + 1] = e.triangle_cdf[t] + triangle_area(shape, t);
      e.area = e.triangle_cdf[n];
      if (!(e.area > 0)) continue;
      for (double& v : e.triangle_cdf) v /= e.area;
    }
    emitter_of_[s] = static_cast<std::int32_t>(shapes_.size());
    shapes_.push_back(std::move(e));
    power.push_back(radiance * shapes_.back().area);
  }
  shape_cdf_.assign(power.size() + 1, 0.0);
  for (std::size_t k = 0; k < power.size(); ++k) shape_cdf_[k + 1] = shape_cdf_[k] + power[k];
  for (double& v : shape_cdf_) v /= shape_cdf_.back();
}

double EmitterSampler::shape_pdf(std::uint32_t shape) const noexcept {
  const std::int32_t k = shape < emitter_of_.size() ? emitter_of_[shape] : -1;
  return k < 0 ? 0.0 : shape_cdf_[k + 1] - shape_cdf_[k];
}

EmitterSample EmitterSampler::sample(const Vec3d& from, double u1, double u2) const noexcept {
  EmitterSample out;
  if (empty()) return out;
  const Emitter& e = shapes_[pick(shape_cdf_, u1)];
  const scene::SceneShape& shape = geometry_[e.shape];
  const double p_shape = shape_pdf(e.shape);
  out.shape = e.shape;
  Vec3d x, n;
  if (shape.type == scene::ShapeType::Sphere) {
    Vec3d axis;
    double r, one_minus_cos;
    if (cone_of(shape, from, axis, r, one_minus_cos)) {
      // Uniform in the cone: 1 - cos theta' = v uniform in [0, 1 - cos a].
      Vec3d e1, e2;
      basis_of(axis, e1, e2);
      const double v = one_minus_cos * u1, s = std::sqrt(v * (2.0 - v)), phi = 2.0 * pi * u2;
      out.dir = (1.0 - v) * axis + (s * std::cos(phi)) * e1 + (s * std::sin(phi)) * e2;
      // Distance to the near side: t = (r^2 - R^2) / (b + sqrt(b^2 - r^2 + R^2)), b = w.(c - p).
      const double b = dot(out.dir, vec(shape.centre) - from), k = (r - shape.radius) * (r + shape.radius);
      out.distance = k / (b + std::sqrt(std::fmax(0.0, b * b - k)));
      out.pdf = p_shape / (2.0 * pi * one_minus_cos);
      return out;
    }
    // Inside: uniform on the sphere, z = 1 - 2 u1.
    const double z = 1.0 - 2.0 * u1, s = std::sqrt(std::fmax(0.0, 1.0 - z * z)), phi = 2.0 * pi * u2;
    n = {s * std::cos(phi), s * std::sin(phi), z};
    x = vec(shape.centre) + shape.radius * n;
  } else {
    const auto t = static_cast<std::uint32_t>(pick(e.triangle_cdf, u1));
    const Vec3d a = vertex(shape, 3 * t), b = vertex(shape, 3 * t + 1), c = vertex(shape, 3 * t + 2);
    // Uniform on the triangle (Osada et al. 2002): sqrt(u1) splits the area evenly.
    const double r = std::sqrt(u1);
    x = (1.0 - r) * a + (r * (1.0 - u2)) * b + (r * u2) * c;
    n = cross(b - a, c - a);
    n = (1.0 / norm(n)) * n;
  }
  const Vec3d to = x - from;
  out.distance = norm(to);
  if (!(out.distance > 0)) return out;
  out.dir = (1.0 / out.distance) * to;
  const double cos_x = std::fabs(dot(n, out.dir));
  if (!(cos_x > 0)) return out;
  out.pdf = p_shape / e.area * out.distance * out.distance / cos_x;  // area density to solid angle
  return out;
}

double EmitterSampler::pdf(const Vec3d& from, const Vec3d& dir, const Hit& hit) const noexcept {
  if (!hit.hit) return 0;
  const double p_shape = shape_pdf(hit.shape);
  if (p_shape == 0) return 0;
  const scene::SceneShape& shape = geometry_[hit.shape];
  const Emitter& e = shapes_[static_cast<std::size_t>(emitter_of_[hit.shape])];
  if (shape.type == scene::ShapeType::Sphere) {
    Vec3d axis;
    double r, one_minus_cos;
    if (cone_of(shape, from, axis, r, one_minus_cos)) return p_shape / (2.0 * pi * one_minus_cos);
  }
  const double cos_x = std::fabs(dot(hit.normal, dir));
  return cos_x > 0 ? p_shape / e.area * hit.t * hit.t / cos_x : 0.0;
}

}  // namespace shpack::bake
