// vec3.h - a 3-vector of doubles with the five operations the light and bake code share, and
// a direction as one. Directions on the sphere are Dir3 (conventions.h) and positions Point3
// (lights.h); this is the arithmetic type between them, kept out of the projection API.
#pragma once

#include "shpack/conventions.h"

namespace shpack {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};

constexpr Vec3 operator+(Vec3 a, Vec3 b) noexcept { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(Vec3 a, Vec3 b) noexcept { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator*(double s, Vec3 a) noexcept { return {s * a.x, s * a.y, s * a.z}; }
constexpr double dot(Vec3 a, Vec3 b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr Vec3 to_vec3(Dir3 d) noexcept { return {d.x, d.y, d.z}; }

}  // namespace shpack
