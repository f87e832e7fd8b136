#include "tracer.h"

#include <cmath>
#include <cstring>

namespace shpack::bake {

Tracer::Tracer(const std::vector<scene::SceneShape>& geometry) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) {
    error_ = "cannot start Embree";
    return;
  }
  RTCScene scene = rtcNewScene(device_);
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);  // no cracks between shared triangle edges
  for (std::uint32_t s = 0; s < geometry.size(); ++s) {
    const scene::SceneShape& shape = geometry[s];
    RTCGeometry geom;
    if (shape.type == scene::ShapeType::Sphere) {
      geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
      auto* v = static_cast<float*>(
          rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
      v[0] = static_cast<float>(shape.centre.x);
      v[1] = static_cast<float>(shape.centre.y);
      v[2] = static_cast<float>(shape.centre.z);
      v[3] = static_cast<float>(shape.radius);
    } else {
      geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      const std::size_t nv = shape.vertices.size() / 3, nt = shape.indices.size() / 3;
      auto* v = static_cast<float*>(
          rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
      auto* i = static_cast<unsigned*>(
          rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
      if (nv) std::memcpy(v, shape.vertices.data(), shape.vertices.size() * sizeof(float));
      if (nt) std::memcpy(i, shape.indices.data(), shape.indices.size() * sizeof(unsigned));
    }
    rtcCommitGeometry(geom);
    const unsigned id = rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    if (shape_of_geometry_.size() <= id) shape_of_geometry_.resize(id + 1);
    shape_of_geometry_[id] = s;
  }
  rtcCommitScene(scene);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
    rtcReleaseScene(scene);
    error_ = "Embree could not build the scene (out of memory or invalid geometry)";
    return;
  }
  scene_ = scene;
}

Tracer::~Tracer() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

namespace {

void set_ray(RTCRay& ray, const Vec3d& o, const Vec3d& d, double t_min, double t_max) {
  ray.org_x = static_cast<float>(o.x);
  ray.org_y = static_cast<float>(o.y);
  ray.org_z = static_cast<float>(o.z);
  ray.dir_x = static_cast<float>(d.x);
  ray.dir_y = static_cast<float>(d.y);
  ray.dir_z = static_cast<float>(d.z);
  ray.tnear = static_cast<float>(t_min);
  ray.tfar = std::isinf(t_max) ? std::numeric_limits<float>::infinity() : static_cast<float>(t_max);
  ray.time = 0;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
}

}  // namespace

Hit Tracer::intersect(const Vec3d& origin, const Vec3d& dir, double t_min, double t_max) const noexcept {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  set_ray(rh.ray, origin, dir, t_min, t_max);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  Hit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.hit = true;
  hit.shape = shape_of_geometry_[rh.hit.geomID];
  hit.t = rh.ray.tfar;
  Vec3d n{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
  const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  hit.backface = (n.x * dir.x + n.y * dir.y + n.z * dir.z) > 0;
  const double sign = hit.backface ? -1.0 : 1.0;  // face the origin
  hit.normal = {sign * n.x / len, sign * n.y / len, sign * n.z / len};
  return hit;
}

bool Tracer::occluded(const Vec3d& origin, const Vec3d& dir, double t_min, double t_max) const noexcept {
  // An empty interval holds nothing (and a negative tfar would read as Embree's "hit" below).
  if (!(t_max > t_min)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  set_ray(ray, origin, dir, t_min, t_max);
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar < 0;  // Embree sets tfar to -inf on a hit
}

}  // namespace shpack::bake
