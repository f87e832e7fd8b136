// scene_lights.h (private) - the scene's lights for the engine: closed forms, the planner's
// question "can this shape hide this light from this point?", light samples for shadow rays,
// and the irradiance a surface point receives (bounce).
#pragma once

#include <vector>

#include "sampling.h"
#include "shpack/scene/scene.h"
#include "shpack/status.h"
#include "tracer.h"

namespace shpack::bake {

// The closed form of one light at a probe (lights.h).
Status add_light(const scene::SceneLight& light, Point3 probe, ShL2& radiance) noexcept;

// Hemisphere and ambient lights are distant and uniform over whole hemispheres: never
// shadowed, and seen by bounce paths when they escape (docs/scenes.md).
bool is_distant(const scene::SceneLight& light) noexcept;
// Radiance of a distant light arriving from d.
Rgb distant_radiance(const scene::SceneLight& light, Vec3d d) noexcept;

// An axis-aligned bounding box of a shape.
struct Bounds {
  Vec3d lo, hi;
};
Bounds shape_bounds(const scene::SceneShape& shape) noexcept;

// Whether a shape within `bounds` can lie between `probe` and some point of the light
// (conservative: false means no ray to the light can hit the shape). Every ray from the probe
// to a light of bounding radius R lies within distance R of the segment probe -> light
// centre (R = 0 for point and spot lights), and every ray to a directional light of
// half-angle a within the cone about its direction; the test is a slab test of that segment
// or ray against the box grown by R (or by the cone's widest radius over the box).
bool can_shadow(const scene::SceneLight& light, Vec3d probe, const Bounds& bounds) noexcept;

// A light as seen from `from`, for shadow rays: a delta light's one direction (weight 0: its
// closed form carries the value), or the point of an extended light that (u1, u2), uniform
// in [0, 1)^2, picks: uniform in solid angle over the cap of a sphere light or a sun, uniform
// by area over a rect or disk. `weight` is 1 / pdf per steradian (0 for a point seen from
// behind), `distance` the distance to the light along `dir` (inf for a sun).
struct LightSample {
  Vec3d dir;
  double distance = 0;
  double weight = 0;
};
bool is_delta(const scene::SceneLight& light) noexcept;
LightSample light_point(const scene::SceneLight& light, Vec3d from, double u1, double u2) noexcept;
// The uniform radiance of an extended light (lights.h's normalisations).
Rgb light_radiance(const scene::SceneLight& light) noexcept;

// Irradiance at a surface point x with unit normal n from one light, by the sample (u1, u2)
// and one shadow ray (delta lights exactly, with their ray); distant lights give 0 (paths find
// them on escape). `rays` counts the rays traced.
Rgb light_irradiance(const scene::SceneLight& light, Vec3d x, Vec3d n, double epsilon, const Tracer& tracer,
                     double u1, double u2, std::uint64_t& rays);

}  // namespace shpack::bake
