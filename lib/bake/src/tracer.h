// tracer.h (private) - rays against the scene's geometry, through Embree 3.
//
// One Embree scene holds every shape: triangle meshes (planes, boxes and meshes are
// triangles) and exact spheres (Embree's sphere points). Rays are single precision inside
// Embree; origins and directions are rounded to float once, here. Each call is thread-safe
// (rtcIntersect1 and rtcOccluded1 on a committed scene).
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <limits>
#include <vector>

#include "shpack/scene/scene.h"
#include "shpack/vec3.h"

namespace shpack::bake {

using Vec3d = Vec3;  // vec3.h

struct Hit {
  bool hit = false;
  std::uint32_t shape = 0;  // index into Scene::geometry
  double t = 0;             // distance along the unit direction
  Vec3d normal;             // unit geometric normal, facing the ray's origin
  // The ray met the shape's back: Embree's raw geometric normal Ng points along the ray.
  // Ng is (v1 - v0) x (v2 - v0) for a triangle (counter-clockwise front, Embree's
  // RTC_GEOMETRY_TYPE_TRIANGLE) and outward for a sphere; the loader winds boxes outward,
  // planes towards right x up and meshes as their files do (scene_loader.cpp).
  bool backface = false;
};

class Tracer {
 public:
  // Builds the acceleration structure over `geometry` (which must outlive the tracer).
  // `ok()` is false, with `error()` set, if Embree could not be started.
  explicit Tracer(const std::vector<scene::SceneShape>& geometry);
  ~Tracer();
  Tracer(const Tracer&) = delete;
  Tracer& operator=(const Tracer&) = delete;

  bool ok() const noexcept { return scene_ != nullptr; }
  const char* error() const noexcept { return error_; }

  // First hit along origin + t dir, t in (t_min, t_max); dir is a unit vector.
  Hit intersect(const Vec3d& origin, const Vec3d& dir, double t_min,
                double t_max = std::numeric_limits<double>::infinity()) const noexcept;
  // Whether anything lies along origin + t dir for t in (t_min, t_max).
  bool occluded(const Vec3d& origin, const Vec3d& dir, double t_min,
                double t_max = std::numeric_limits<double>::infinity()) const noexcept;

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<std::uint32_t> shape_of_geometry_;  // Embree geometry id -> shape index
  const char* error_ = "";
};

}  // namespace shpack::bake
