// The disk area light by the periodic trapezoid rule on its rim (lights.h, [2], [5]).
#include <algorithm>
#include <array>
#include <cmath>

#include "common/angles.h"
#include "lights/light_geometry.h"
#include "shpack/lights.h"

namespace shpack {
namespace {

// Two unit vectors completing n to a right-handed orthonormal basis (e1 x e2 = n), without
// a branch on a threshold: Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017.
void basis_of(Vec3 n, Vec3& e1, Vec3& e2) noexcept {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
  e1 = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
  e2 = {b, sign + n.y * n.y * a, -n.y};
}

// Sums of the integrands of lights.h's three rim integrals.
struct RimSums {
  double omega = 0;
  Vec3 first;
  std::array<std::array<double, 3>, 3> second{};
};

// Nodes used: lights.h (add_disk_light) derives N from the analyticity strip s.
int disk_nodes(double h, double q_len, double radius) noexcept {
  if (!(q_len > 0)) return 16;  // on the axis the integrands are trigonometric polynomials
  const double s = std::acosh((h * h + q_len * q_len + radius * radius) / (2.0 * radius * q_len));
  const double wanted = std::min(kDiskStripProduct / s, static_cast<double>(kDiskMaxNodes));
  return std::max(16, 8 * static_cast<int>(std::ceil(wanted / 8.0)));
}

}  // namespace

Status add_disk_light(const DiskLight& disk, const Rgb& radiance, Point3 probe, ShL2& radiance_sh,
                      DiskQuadrature* quadrature) noexcept {
  Vec3 n;
  if (!detail::normalised(to_vec3(disk.normal), n))
    return Status::error(Errc::InvalidArgument, "disk light: normal must be finite and non-zero");
  if (!(disk.radius > 0 && std::isfinite(disk.radius)))
    return Status::error(Errc::InvalidArgument, "disk light: radius must be finite and > 0");
  if (!detail::valid_colour(radiance))
    return Status::error(Errc::InvalidArgument, "disk light: radiance must be finite and >= 0");
  const Vec3 to_centre = detail::vec(disk.centre) - detail::vec(probe);
  if (!detail::finite(to_centre))
    return Status::error(Errc::InvalidArgument, "disk light: centre and probe must be finite");
  const double h = -dot(to_centre, n);  // probe's height over the plane
  if (quadrature) *quadrature = {};
  if (!(h > 0)) return Status::success();  // behind or in its plane
  Vec3 e1, e2;
  basis_of(n, e1, e2);
  const Vec3 q = to_centre + h * n;  // disk centre minus the probe's foot point, in the plane
  const double radius = disk.radius;
  const int count = disk_nodes(h, detail::length(q), radius);

  // Trapezoid sums over all nodes and over the even ones (the N/2 rule, for the estimate).
  RimSums all, even;
  // cos t_j, sin t_j by rotating with (cos dt, sin dt), recomputed exactly every 32 nodes so
  // the recurrence's rounding (about j u after j steps) stays below 32 u.
  const double dt = 2.0 * kPi / count, cd = std::cos(dt), sd = std::sin(dt);
  double ct = 1.0, st = 0.0;
  for (int j = 0; j < count; ++j) {
    if (j % 32 == 0) {
      ct = std::cos(dt * j);
      st = std::sin(dt * j);
    } else {
      const double c_next = ct * cd - st * sd;
      st = st * cd + ct * sd;
      ct = c_next;
    }
    const Vec3 e = ct * e1 + st * e2;
    const Vec3 x = to_centre + radius * e;       // X(t) = B(t) - probe
    const Vec3 dx = radius * (ct * e2 - st * e1);  // X'(t)
    const double len2 = dot(x, x), len = std::sqrt(len2);
    const Vec3 xdx = cross(x, dx);
    const double omega = (radius * radius + radius * dot(q, e)) / (len * (len + h));
    const Vec3 first = (-0.5 / len2) * xdx;
    const double xx[3] = {x.x, x.y, x.z}, cc[3] = {xdx.x, xdx.y, xdx.z};
    const double inv_len3 = 1.0 / (len2 * len);
    for (RimSums* sums : {&all, &even}) {
      if (sums == &even && j % 2 != 0) continue;
      sums->omega += omega;
      sums->first = sums->first + first;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) sums->second[r][c] -= 0.5 * (xx[r] * cc[c] + cc[r] * xx[c]) * inv_len3;
    }
  }
  // Weights 2 pi / N (and 2 pi / (N/2)); int w w^T = (Omega I + rim term) / 3.
  const auto moments = [](const RimSums& sums, double weight) {
    detail::SphereMoments m;
    m.solid_angle = weight * sums.omega;
    m.first = weight * sums.first;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m.second[r][c] = weight * sums.second[r][c] / 3.0;
      m.second[r][r] += m.solid_angle / 3.0;
    }
    return m;
  };
  const detail::SphereMoments m = moments(all, 2.0 * kPi / count);
  if (quadrature) {
    const detail::SphereMoments half = moments(even, 4.0 * kPi / count);
    double diff = std::fabs(m.solid_angle - half.solid_angle);
    diff = std::max({diff, std::fabs(m.first.x - half.first.x), std::fabs(m.first.y - half.first.y),
                     std::fabs(m.first.z - half.first.z)});
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) diff = std::max(diff, std::fabs(m.second[r][c] - half.second[r][c]));
    *quadrature = {count, m.solid_angle > 0 ? diff / m.solid_angle : 0.0};
  }
  detail::add_moments(m, radiance, radiance_sh);
  return Status::success();
}

}  // namespace shpack
