#include "surface_domain.h"

#include "scene_lights.h"

namespace shpack::bake {

using scene::LightType;

Horizon horizon_of(const scene::SceneLight& light, const Vec3d& p, const Vec3d& n) noexcept {
  Vec3d axis;
  double sin_alpha = 0;
  if (light.type == LightType::Directional) {
    axis = -1.0 * vec(light.direction);
    sin_alpha = std::sin(0.5 * light.angular_diameter);
  } else {
    const Vec3d to = vec(light.position) - p;
    const double d = norm(to);
    const double r = light.type == LightType::Rect                                   ? 0.5 * std::hypot(light.width, light.height)
                     : light.type == LightType::Sphere || light.type == LightType::Disk ? light.radius
                                                                                      : 0.0;
    if (!(d > r)) return Horizon::Straddles;  // the point is within the light's bounding sphere
    axis = (1.0 / d) * to;
    sin_alpha = r / d;
  }
  const double c = dot(axis, n);
  if (sin_alpha == 0) return c > 0 ? Horizon::Above : Horizon::Below;
  if (c >= sin_alpha) return Horizon::Above;
  if (c <= -sin_alpha) return Horizon::Below;
  return Horizon::Straddles;
}

ShMatrix hemisphere_gram(const Vec3d& n) noexcept {
  // Gauss-Legendre, 3 nodes, mapped to [0, 1]: z = (1 + x) / 2, weights halved (5/18, 8/18, 5/18).
  const double r = 0.5 * std::sqrt(0.6);
  const std::array<double, 3> z{0.5 - r, 0.5, 0.5 + r}, wz{5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  constexpr int kPhi = 8;
  Vec3d e1, e2;
  basis_of(n, e1, e2);
  ShMatrix m{};
  for (int j = 0; j < 3; ++j) {
    const double s = std::sqrt((1.0 - z[j]) * (1.0 + z[j]));
    for (int k = 0; k < kPhi; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / kPhi;
      const Vec3d w = (s * std::cos(phi)) * e1 + (s * std::sin(phi)) * e2 + z[j] * n;
      const double weight = wz[j] * 2.0 * std::numbers::pi / kPhi;
      const std::array<double, kShCount> y = eval_basis(w.x, w.y, w.z);
      for (int a = 0; a < kShCount; ++a)
        for (int b = 0; b < kShCount; ++b) m[a][b] += weight * y[a] * y[b];
    }
  }
  return m;
}

ShL2 hemisphere_part(const ShMatrix& m, const ShL2& sh) noexcept {
  ShL2 out;
  for (int c = 0; c < kChannelCount; ++c)
    for (int a = 0; a < kShCount; ++a) {
      double sum = 0;
      for (int b = 0; b < kShCount; ++b) sum += m[a][b] * sh.c[c][b];
      out.c[c][a] = sum;
    }
  return out;
}

Rgb eval_radiance(const ShL2& sh, const Vec3d& w) noexcept {
  const std::array<double, kShCount> y = eval_basis(w.x, w.y, w.z);
  Rgb out{0, 0, 0};
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) out[c] += sh.c[c][i] * y[i];
  return out;
}

}  // namespace shpack::bake
