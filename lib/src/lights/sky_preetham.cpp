// The Preetham clear sky (sky.h): radiance by the published formulas [1], projection by
// quadrature.
#include <algorithm>
#include <array>
#include <cmath>

#include "common/angles.h"
#include "lights/light_geometry.h"
#include "shpack/sky.h"

namespace shpack {
namespace {

struct Perez {
  double a, b, c, d, e;
  // F(theta, gamma) with cos theta > 0 (above the horizon), or cos theta = 0 where
  // e^(B / cos theta) -> 0 for B < 0.
  double operator()(double cos_theta, double gamma, double cos_gamma) const noexcept {
    const double horizon = cos_theta > 0 ? std::exp(b / cos_theta) : 0.0;
    return (1.0 + a * horizon) * (1.0 + c * std::exp(d * gamma) + e * cos_gamma * cos_gamma);
  }
};

// Everything that depends on the sun and the turbidity only [1], Appendix A.2.
struct SkyModel {
  Perez y, x, yc;          // luminance Y and chromaticities x, y
  double zenith[3];        // Y_z / F_Y(0, theta_s), x_z / F_x(0, theta_s), y_z / F_y(0, theta_s)
  Vec3 sun;
};

Status make_model(const PreethamSky& sky, SkyModel& m) noexcept {
  if (!detail::normalised(to_vec3(sky.sun), m.sun))
    return Status::error(Errc::InvalidArgument, "preetham sky: sun direction must be finite and non-zero");
  if (!(m.sun.y >= 0)) return Status::error(Errc::InvalidArgument, "preetham sky: the sun must be above the horizon");
  const double t = sky.turbidity;
  if (!(t >= 1.7 && t <= 10)) return Status::error(Errc::InvalidArgument, "preetham sky: turbidity must be in [1.7, 10]");
  if (!detail::valid_colour(sky.ground) || !(sky.intensity >= 0 && std::isfinite(sky.intensity)))
    return Status::error(Errc::InvalidArgument, "preetham sky: ground and intensity must be finite and >= 0");
  m.y = {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703};
  m.x = {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989, -0.0033 * t + 0.0452};
  m.yc = {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537, -0.0109 * t + 0.0529};
  const double theta_s = std::acos(std::clamp(m.sun.y, -1.0, 1.0));
  const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * theta_s);
  const double y_zenith = (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;  // kcd/m^2
  const double th = theta_s, th2 = th * th, th3 = th2 * th, t2 = t * t;
  const double x_zenith = t2 * (0.00166 * th3 - 0.00375 * th2 + 0.00209 * th) +
                          t * (-0.02903 * th3 + 0.06377 * th2 - 0.03202 * th + 0.00394) +
                          (0.11693 * th3 - 0.21196 * th2 + 0.06052 * th + 0.25886);
  const double yc_zenith = t2 * (0.00275 * th3 - 0.00610 * th2 + 0.00317 * th) +
                           t * (-0.04214 * th3 + 0.08970 * th2 - 0.04153 * th + 0.00516) +
                           (0.15346 * th3 - 0.26756 * th2 + 0.06670 * th + 0.26688);
  // At the zenith, theta = 0 and gamma = theta_s.
  m.zenith[0] = y_zenith / m.y(1.0, theta_s, m.sun.y);
  m.zenith[1] = x_zenith / m.x(1.0, theta_s, m.sun.y);
  m.zenith[2] = yc_zenith / m.yc(1.0, theta_s, m.sun.y);
  return Status::success();
}

// Sky radiance above the horizon (cos_theta = d.y >= 0), linear Rec. 709 RGB.
Rgb sky_rgb(const SkyModel& m, Vec3 d, double intensity) noexcept {
  const double cos_gamma = std::clamp(dot(d, m.sun), -1.0, 1.0);
  // gamma by atan2 of |d x s| and d.s: accurate near the sun, where acos is not.
  const double gamma = std::atan2(detail::length(cross(d, m.sun)), cos_gamma);
  const double lum = m.zenith[0] * m.y(d.y, gamma, cos_gamma);
  const double x = m.zenith[1] * m.x(d.y, gamma, cos_gamma), y = m.zenith[2] * m.yc(d.y, gamma, cos_gamma);
  // xyY -> XYZ -> linear sRGB (IEC 61966-2-1) [2].
  const double cx = x * lum / y, cz = (1.0 - x - y) * lum / y;
  return {intensity * (3.2404542 * cx - 1.5371385 * lum - 0.4985314 * cz),
          intensity * (-0.9692660 * cx + 1.8760108 * lum + 0.0415560 * cz),
          intensity * (0.0556434 * cx - 0.2040259 * lum + 1.0572252 * cz)};
}

// Gauss-Legendre nodes and weights on [0, 1] by Newton's method on P_n (Golub-Welsch would do
// as well; n <= 64 here), computed once per call: no static state.
void gauss_legendre_01(int n, double* nodes, double* weights) noexcept {
  for (int k = 0; k < n; ++k) {
    double t = std::cos(kPi * (k + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = t;
      for (int j = 2; j <= n; ++j) {
        const double p2 = ((2.0 * j - 1.0) * t * p1 - (j - 1.0) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double step = p1 / dp;
      t -= step;
      if (std::fabs(step) <= 1e-16) break;
    }
    nodes[k] = 0.5 * (t + 1.0);
    weights[k] = 1.0 / ((1.0 - t * t) * dp * dp);  // 2 / ((1 - t^2) P'^2), halved for [0, 1]
  }
}

// The product rule over the upper hemisphere with n_theta x n_phi nodes.
ShL2 project_upper(const SkyModel& m, double intensity, int n_theta, int n_phi) noexcept {
  std::array<double, 64> nodes{}, weights{};
  gauss_legendre_01(n_theta, nodes.data(), weights.data());
  ShL2 out;
  for (int k = 0; k < n_theta; ++k) {
    const double y = nodes[k], s = std::sqrt((1.0 - y) * (1.0 + y));
    for (int j = 0; j < n_phi; ++j) {
      const double phi = 2.0 * kPi * (j + 0.5) / n_phi;
      const Vec3 d{s * std::cos(phi), y, s * std::sin(phi)};
      const Rgb l = sky_rgb(m, d, intensity);
      const double w = weights[k] * 2.0 * kPi / n_phi;
      detail::add_zonal(d, {w * l[0], w * l[1], w * l[2]}, {1.0, 1.0, 1.0}, out);
    }
  }
  return out;
}

}  // namespace

Status preetham_radiance(const PreethamSky& sky, Dir3 d, Rgb& radiance) noexcept {
  SkyModel m;
  if (Status st = make_model(sky, m); !st.ok()) return st;
  Vec3 u;
  if (!detail::normalised(to_vec3(d), u))
    return Status::error(Errc::InvalidArgument, "preetham sky: direction must be finite and non-zero");
  radiance = u.y < 0 ? sky.ground : sky_rgb(m, u, sky.intensity);
  return Status::success();
}

Status add_preetham_sky(const PreethamSky& sky, ShL2& radiance, double* error_estimate) noexcept {
  SkyModel m;
  if (Status st = make_model(sky, m); !st.ok()) return st;
  static_assert(kPreethamThetaNodes <= 64 && kPreethamThetaNodes % 2 == 0 && kPreethamPhiNodes % 2 == 0);
  const ShL2 fine = project_upper(m, sky.intensity, kPreethamThetaNodes, kPreethamPhiNodes);
  if (error_estimate) {
    const ShL2 coarse = project_upper(m, sky.intensity, kPreethamThetaNodes / 2, kPreethamPhiNodes / 2);
    double diff = 0, scale = 0;
    for (int c = 0; c < kChannelCount; ++c) {
      scale = std::max(scale, std::fabs(fine.c[c][0]));
      for (int i = 0; i < kShCount; ++i) diff = std::max(diff, std::fabs(fine.c[c][i] - coarse.c[c][i]));
    }
    *error_estimate = scale > 0 ? diff / scale : 0.0;
  }
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) radiance.c[c][i] += fine.c[c][i];
  return add_hemisphere_light({0, 0, 0}, sky.ground, radiance);
}

}  // namespace shpack
