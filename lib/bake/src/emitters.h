// emitters.h (private) - next-event estimation toward emissive geometry: a point of an
// emissive shape chosen by power, as a direction from a given point with its density per
// steradian (pbrt-v4, 12.6 "Light sampling" and 13.4 "Direct lighting").
//
// A shape is chosen with probability proportional to its power (the mean of its emitted
// radiance's channels times its area: the emission is uniform and on both sides); inside it
// a triangle by area and a point uniform on the triangle, so the density on a mesh is
// P(shape) / A(shape) per unit area anywhere on it. A sphere seen from outside is sampled
// uniformly in the cone it subtends (density P / Omega, which never wastes a sample on its
// far side); from inside, uniformly by area. pdf() gives the same densities for a direction
// that found the shape by itself, which multiple importance sampling needs to weigh the two
// (sampling.h, mis_weight).
#pragma once

#include <cstdint>
#include <vector>

#include "shpack/scene/scene.h"
#include "tracer.h"

namespace shpack::bake {

struct EmitterSample {
  Vec3d dir;              // unit, from the point toward the emitter
  double distance = 0;    // to the sampled point
  double pdf = 0;         // per steradian at the point; 0: no sample (seen edge-on)
  std::uint32_t shape = 0;
};

class EmitterSampler {
 public:
  explicit EmitterSampler(const std::vector<scene::SceneShape>& geometry);

  bool empty() const noexcept { return shapes_.empty(); }
  // (u1, u2) uniform in [0, 1)^2.
  EmitterSample sample(const Vec3d& from, double u1, double u2) const noexcept;
  // The density per steradian with which sample() gives direction `dir` (unit) from `from`,
  // when `hit` (a hit of the ray from `from` along `dir`) is that direction's first surface.
  double pdf(const Vec3d& from, const Vec3d& dir, const Hit& hit) const noexcept;

 private:
  struct Emitter {
    std::uint32_t shape = 0;
    double area = 0;
    std::vector<double> triangle_cdf;  // meshes: cumulative area, normalised
  };
  double shape_pdf(std::uint32_t shape) const noexcept;  // P(shape), 0 for a non-emitter
  const std::vector<scene::SceneShape>& geometry_;
  std::vector<Emitter> shapes_;
  std::vector<double> shape_cdf_;            // cumulative power, normalised
  std::vector<std::int32_t> emitter_of_;     // shape index -> index in shapes_, or -1
};

}  // namespace shpack::bake
