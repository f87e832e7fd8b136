#include "lights/light_oracle.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "support/gauss_legendre.h"
#include "support/sh_oracle.h"

namespace shpack_test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kGaussPoints = 16;

struct V3 {
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double len(V3 a) { return std::sqrt(dot(a, a)); }
V3 unit(V3 a) { return (1.0 / len(a)) * a; }
V3 v3(shpack::Point3 p) { return {p.x, p.y, p.z}; }
V3 v3(shpack::Dir3 d) { return {d.x, d.y, d.z}; }

// Any two unit vectors orthogonal to unit n and to each other.
void frame_of(V3 n, V3& b1, V3& b2) {
  const V3 helper = std::fabs(n.x) < 0.6 ? V3{1, 0, 0} : V3{0, 1, 0};
  b1 = unit(cross(helper, n));
  b2 = cross(n, b1);
}

// Composite Gauss-Legendre over [a, b] in `panels` panels (outer) times the periodic
// trapezoid rule with `angles` nodes over [0, 2 pi) (inner); f(r, phi, weight) accumulates.
using Sample = std::function<void(double r, double phi, double weight, std::array<double, 9>& acc)>;
std::array<double, 9> polar_rule(double a, double b, int panels, int angles, const Sample& f) {
  const GaussRule rule = gauss_legendre(kGaussPoints);
  std::array<double, 9> acc{};
  const double width = (b - a) / panels;
  for (int p = 0; p < panels; ++p) {
    const double lo = a + p * width;
    for (int k = 0; k < kGaussPoints; ++k) {
      const double r = lo + 0.5 * width * (rule.nodes[k] + 1.0);
      const double wr = 0.5 * width * rule.weights[k];
      for (int j = 0; j < angles; ++j) f(r, 2.0 * kPi * j / angles, wr * 2.0 * kPi / angles, acc);
    }
  }
  return acc;
}

// `fine_terms`: the number of nodes of the rule at 2 * panels.
OracleSh refine(const std::function<std::array<double, 9>(int)>& rule, int panels, double fine_terms) {
  const std::array<double, 9> coarse = rule(panels), fine = rule(2 * panels);
  OracleSh out;
  out.value = fine;
  for (int i = 0; i < 9; ++i) out.error = std::max(out.error, std::fabs(fine[i] - coarse[i]));
  out.scale = std::fabs(fine[0]);
  constexpr double kU = 0.5 * std::numeric_limits<double>::epsilon(), kMaxY = 1.0925484305920792;
  out.rounding = fine_terms * kU * (out.scale / 0.28209479177387814) * kMaxY;
  return out;
}

void add_direction(V3 w, double weight, std::array<double, 9>& acc) {
  const std::array<double, 9> y = unity_basis_slow(w.x, w.y, w.z);
  for (int i = 0; i < 9; ++i) acc[i] += weight * y[i];
}

}  // namespace

OracleSh rect_oracle(const shpack::RectLight& rect, shpack::Point3 probe, int panels) {
  const V3 u = unit(v3(rect.right)), v = unit(v3(rect.up)), n = cross(u, v);
  const V3 c = v3(rect.centre), p = v3(probe);
  const double w = rect.width, h = rect.height;
  return refine(
      [&](int count) {
        const GaussRule rule = gauss_legendre(kGaussPoints);
        std::array<double, 9> acc{};
        const double step = 1.0 / count;
        for (int ps = 0; ps < count; ++ps)
          for (int ks = 0; ks < kGaussPoints; ++ks)
            for (int pt = 0; pt < count; ++pt)
              for (int kt = 0; kt < kGaussPoints; ++kt) {
                const double s = (ps + 0.5 * (rule.nodes[ks] + 1.0)) * step;
                const double t = (pt + 0.5 * (rule.nodes[kt] + 1.0)) * step;
                const V3 x = c + ((s - 0.5) * w) * u + ((t - 0.5) * h) * v;
                const V3 d = x - p;
                const double r = len(d);
                const double cos_x = -dot(n, d) / r;
                if (cos_x <= 0) continue;  // the back of a one-sided light
                const double weight =
                    0.25 * step * step * rule.weights[ks] * rule.weights[kt] * w * h * cos_x / (r * r);
                add_direction((1.0 / r) * d, weight, acc);
              }
        return acc;
      },
      panels, std::pow(2.0 * panels * kGaussPoints, 2));
}

OracleSh disk_oracle(const shpack::DiskLight& disk, shpack::Point3 probe, int panels) {
  const V3 n = unit(v3(disk.normal)), c = v3(disk.centre), p = v3(probe);
  V3 b1, b2;
  frame_of(n, b1, b2);
  return refine(
      [&](int count) {
        return polar_rule(0.0, disk.radius, count, 64 * count, [&](double rho, double phi, double wt, auto& acc) {
          const V3 x = c + (rho * std::cos(phi)) * b1 + (rho * std::sin(phi)) * b2;
          const V3 d = x - p;
          const double r = len(d), cos_x = -dot(n, d) / r;
          if (cos_x > 0) add_direction((1.0 / r) * d, wt * rho * cos_x / (r * r), acc);
        });
      },
      panels, 2.0 * panels * kGaussPoints * 64 * 2.0 * panels);
}

OracleSh sphere_surface_oracle(shpack::Point3 centre, double radius, shpack::Point3 probe, int panels) {
  const V3 c = v3(centre), p = v3(probe);
  const V3 a = unit(p - c);
  V3 b1, b2;
  frame_of(a, b1, b2);
  const double r = len(p - c);
  // The visible surface, cos(alpha) in [R/r, 1] (alpha from the axis towards the probe), in
  // the variable t = ln s, s = |x - p| in [r - R, sqrt(r^2 - R^2)]: s^2 = r^2 + R^2 - 2 r R
  // cos(alpha) gives R^2 dcos(alpha) cos(theta_x) / s^2 = (R/r) cos(theta_x) dt, smooth even
  // when the probe almost touches the sphere (the 1/s^2 peak is gone).
  const double t0 = std::log(r - radius), t1 = 0.5 * std::log((r - radius) * (r + radius));
  return refine(
      [&](int count) {
        return polar_rule(t0, t1, count, 64 * count, [&](double t, double phi, double wt, auto& acc) {
          const double s = std::exp(t);
          const double ca = std::clamp(((r - s) * (r + s) + radius * radius) / (2.0 * r * radius), -1.0, 1.0);
          const double sa = std::sqrt((1.0 - ca) * (1.0 + ca));
          const V3 normal = ca * a + (sa * std::cos(phi)) * b1 + (sa * std::sin(phi)) * b2;
          const V3 d = c + radius * normal - p;
          const double dist = len(d), cos_x = -dot(normal, d) / dist;
          if (cos_x > 0) add_direction((1.0 / dist) * d, wt * (radius / r) * cos_x, acc);
        });
      },
      panels, 2.0 * panels * kGaussPoints * 64 * 2.0 * panels);
}

OracleSh cap_oracle(shpack::Dir3 axis, double half_angle, int panels) {
  const V3 d = unit(v3(axis));
  V3 b1, b2;
  frame_of(d, b1, b2);
  // Polar angle theta' in [0, a] about the axis, weight sin(theta'): accurate for tiny caps.
  return refine(
      [&](int count) {
        return polar_rule(0.0, half_angle, count, 32 * count, [&](double th, double phi, double wt, auto& acc) {
          const double s = std::sin(th);
          add_direction(std::cos(th) * d + (s * std::cos(phi)) * b1 + (s * std::sin(phi)) * b2, wt * s, acc);
        });
      },
      panels, 2.0 * panels * kGaussPoints * 32 * 2.0 * panels);
}

OracleSh zonal_y_oracle(std::array<double, 2> upper, std::array<double, 2> lower, int panels) {
  // Polar coordinates about +Y: y = cos theta in [-1, 0] and [0, 1], each its own rule, so the
  // step at the horizon falls on a panel edge.
  const auto half = [&](double lo, double hi, std::array<double, 2> f, int count) {
    return polar_rule(lo, hi, count, 32 * count, [&](double y, double phi, double wt, auto& acc) {
      const double s = std::sqrt((1.0 - y) * (1.0 + y));
      add_direction({s * std::cos(phi), y, s * std::sin(phi)}, wt * (f[0] + f[1] * y), acc);
    });
  };
  return refine(
      [&](int count) {
        std::array<double, 9> a = half(0.0, 1.0, upper, count), b = half(-1.0, 0.0, lower, count);
        for (int i = 0; i < 9; ++i) a[i] += b[i];
        return a;
      },
      panels, 2.0 * (2.0 * panels * kGaussPoints * 32 * 2.0 * panels));
}

OracleSh upper_hemisphere_oracle(const std::function<double(double x, double y, double z)>& f, int panels) {
  return refine(
      [&](int count) {
        return polar_rule(0.0, 1.0, count, 64 * count, [&](double y, double phi, double wt, auto& acc) {
          const double s = std::sqrt((1.0 - y) * (1.0 + y));
          const V3 w{s * std::cos(phi), y, s * std::sin(phi)};
          add_direction(w, wt * f(w.x, w.y, w.z), acc);
        });
      },
      panels, 2.0 * panels * kGaussPoints * 64 * 2.0 * panels);
}

}  // namespace shpack_test
