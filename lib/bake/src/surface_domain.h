// surface_domain.h (private) - the directions a receiver gathers light from: the whole sphere
// for a probe, the hemisphere about its normal for a point of a lightmapped surface (the
// surface itself hides everything below its tangent plane).
//
// A surface point's SH is that of its incoming radiance over the hemisphere,
// c_i = int_{n.w > 0} L(w) Y_i(w) dw, stored on the whole sphere (zero below the horizon), so
// that the shader evaluates it with the probes' own formula (docs/lightmaps.md).
#pragma once

#include <array>
#include <cmath>
#include <numbers>

#include "sampling.h"
#include "shpack/scene/scene.h"

namespace shpack::bake {

struct Domain {
  bool hemisphere = false;  // false: the sphere
  Vec3d normal;             // unit, when hemisphere

  bool contains(const Vec3d& w) const noexcept { return !hemisphere || dot(w, normal) > 0; }
  // Uniform over the domain: a uniform sphere direction, reflected through the tangent plane
  // when it lies below it (a measure-preserving fold, so Sobol nets stay stratified).
  Vec3d sample(double u1, double u2) const noexcept {
    Vec3d w = uniform_sphere(u1, u2);
    if (hemisphere) {
      const double d = dot(w, normal);
      if (d < 0) w = w - (2.0 * d) * normal;
    }
    return w;
  }
  // Density of sample(): 1 / (4 pi) on the sphere, 1 / (2 pi) on the hemisphere, 0 outside.
  double pdf(const Vec3d& w) const noexcept {
    if (!hemisphere) return kUniformPdf;
    return dot(w, normal) > 0 ? 2.0 * kUniformPdf : 0.0;
  }
};

// Where a light lies against a surface point's horizon.
enum class Horizon : unsigned char { Above, Below, Straddles };

// The cone a (non-distant) light fills seen from p: axis towards it and sin of its
// half-angle (0 for a delta light); an extended light's bounding sphere (rect: half its
// diagonal, disk: its radius) bounds its cone. The cone lies above the tangent plane iff
// angle(axis, n) + alpha <= 90 degrees, i.e. axis.n >= sin(alpha); below iff axis.n <= -sin(alpha).
Horizon horizon_of(const scene::SceneLight& light, const Vec3d& p, const Vec3d& n) noexcept;

// M(n): the hemisphere's Gram matrix of the basis, M_ij = int_{n.w > 0} Y_i Y_j dw, so that
// the hemisphere part of a band-limited radiance with SH c has SH M c exactly. Y_i Y_j is a
// polynomial of degree <= 4 in w: in the frame (e1, e2, n), integrating over phi leaves a
// polynomial of degree <= 4 in z = n.w, which 3-point Gauss-Legendre on [0, 1] integrates
// exactly (degree <= 5), and the phi integrand is a trigonometric polynomial of degree <= 4,
// which the 8-point trapezoid rule integrates exactly (degree <= 7): 24 points, no error.
using ShMatrix = std::array<std::array<double, kShCount>, kShCount>;
ShMatrix hemisphere_gram(const Vec3d& n) noexcept;

// M c, per channel.
ShL2 hemisphere_part(const ShMatrix& m, const ShL2& sh) noexcept;

// The radiance of an SH at w: sum_i c_i Y_i(w), per channel.
Rgb eval_radiance(const ShL2& sh, const Vec3d& w) noexcept;

}  // namespace shpack::bake
