// The rectangular area light in closed form (lights.h: Arvo's boundary integrals [2],
// van Oosterom-Strackee solid angles [3]).
#include <array>
#include <cmath>

#include "lights/light_geometry.h"
#include "shpack/lights.h"

namespace shpack {
namespace {

// Solid angle of the spherical triangle (a, b, c), given by unnormalised vectors from the
// probe with lengths la, lb, lc, positive for a counterclockwise (left-hand-region) order [3]:
//   tan(Omega/2) = [a b c] / (la lb lc + (a.b) lc + (a.c) lb + (b.c) la).
// The triple product is taken as a.((b - a) x (c - a)) with the exact edge vectors eb, ec, so
// a small, distant triangle keeps its relative accuracy.
double triangle_solid_angle(Vec3 a, Vec3 b, Vec3 c, Vec3 eb, Vec3 ec) noexcept {
  const double la = detail::length(a), lb = detail::length(b), lc = detail::length(c);
  const double triple = dot(a, cross(eb, ec));
  const double denom = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2.0 * std::atan2(triple, denom);
}

}  // namespace

Status add_rect_light(const RectLight& rect, const Rgb& radiance, Point3 probe,
                      ShL2& radiance_sh) noexcept {
  Vec3 u, v;
  if (!detail::normalised(to_vec3(rect.right), u) || !detail::normalised(to_vec3(rect.up), v))
    return Status::error(Errc::InvalidArgument, "rect light: right and up must be finite and non-zero");
  if (!(std::fabs(dot(u, v)) <= 1e-6))
    return Status::error(Errc::InvalidArgument, "rect light: right and up must be orthogonal");
  if (!(rect.width > 0 && std::isfinite(rect.width) && rect.height > 0 && std::isfinite(rect.height)))
    return Status::error(Errc::InvalidArgument, "rect light: width and height must be finite and > 0");
  if (!detail::valid_colour(radiance))
    return Status::error(Errc::InvalidArgument, "rect light: radiance must be finite and >= 0");
  const Vec3 to_centre = detail::vec(rect.centre) - detail::vec(probe);
  if (!detail::finite(to_centre))
    return Status::error(Errc::InvalidArgument, "rect light: centre and probe must be finite");
  const Vec3 normal = cross(u, v);
  if (!(dot(to_centre, normal) < 0)) return Status::success();  // behind or in its plane

  // Corners seen from the probe, ordered so that the rectangle is on the left of each edge
  // as the probe sees it: clockwise about the normal (the normal points at the probe).
  const Vec3 hu = (0.5 * rect.width) * u, hv = (0.5 * rect.height) * v;
  const std::array<Vec3, 4> corner = {to_centre - hu - hv, to_centre - hu + hv, to_centre + hu + hv,
                                      to_centre + hu - hv};
  const std::array<Vec3, 4> edge = {rect.height * v, rect.width * u, -rect.height * v, -rect.width * u};

  detail::SphereMoments m;
  m.solid_angle = triangle_solid_angle(corner[0], corner[1], corner[2], edge[0], edge[0] + edge[1]) +
                  triangle_solid_angle(corner[0], corner[2], corner[3], edge[0] + edge[1], -1.0 * edge[3]);
  for (int k = 0; k < 4; ++k) {
    const Vec3 a = corner[k], b = corner[(k + 1) % 4];
    const double la = detail::length(a), lb = detail::length(b);
    const Vec3 axb = cross(a, edge[k]);  // = a x b, from the exact edge vector
    const double sin_len = detail::length(axb);  // |a x b| = la lb sin T
    const double theta = std::atan2(sin_len, dot(a, b));
    m.first = m.first + (0.5 * theta / sin_len) * axb;
    // sym((a^ x b^)(a^ + b^)^T) / (1 + a^.b^) with unit a^, b^ and 1 + a^.b^ = |a^ + b^|^2 / 2.
    const Vec3 ua = (1.0 / la) * a, ub = (1.0 / lb) * b;
    const Vec3 n = (1.0 / (la * lb)) * axb, s = ua + ub;
    const double f = 2.0 / dot(s, s);
    const double nn[3] = {n.x, n.y, n.z}, ss[3] = {s.x, s.y, s.z};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m.second[r][c] += 0.5 * f * (nn[r] * ss[c] + ss[r] * nn[c]);
  }
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m.second[r][c] /= 3.0;
    m.second[r][r] += m.solid_angle / 3.0;
  }
  detail::add_moments(m, radiance, radiance_sh);
  return Status::success();
}

}  // namespace shpack
