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

// Points of a light as seen from `from`: direction, distance to the light along it (inf for
// a directional light) and solid-angle weight (sr); the light's radiance is `radiance`.
// Delta lights give one sample of weight 0 (their closed form carries the value). `wanted`
// is the scene's shadow_samples; the rules are in bake.h and docs/scenes.md.
struct LightSample {
  Vec3d dir;
  double distance = 0;
  double weight = 0;
};
struct LightSamples {
  Rgb radiance{};
  std::vector<LightSample> samples;
};
void sample_light(const scene::SceneLight& light, Vec3d from, int wanted, Rng& rng, LightSamples& out);

// Irradiance at a surface point x with unit normal n from one light, by one sample and one
// shadow ray (delta lights exactly, with their ray); distant lights give 0 (paths find them
// on escape). `rays` counts the rays traced.
Rgb light_irradiance(const scene::SceneLight& light, Vec3d x, Vec3d n, double epsilon, const Tracer& tracer,
                     Rng& rng, std::uint64_t& rays);

}  // namespace shpack::bake
