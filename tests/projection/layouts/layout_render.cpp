#include "layout_render.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "support/band_limited.h"
#include "support/gauss_legendre.h"
#include "support/sh_oracle.h"
#include "support/sphere_map_oracle.h"

namespace shpack_layout_test {
namespace {

using shpack::Dir3;
constexpr double kPi = std::numbers::pi;

Dir3 unit(double x, double y, double z) {
  const double r = std::sqrt(x * x + y * y + z * z);
  return {x / r, y / r, z / r};
}

double angle_between(const Dir3& a, const Dir3& b) {
  // atan2(|a x b|, a.b): accurate at small and large angles.
  const double cx = a.y * b.z - a.z * b.y, cy = a.z * b.x - a.x * b.z, cz = a.x * b.y - a.y * b.x;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), a.x * b.x + a.y * b.y + a.z * b.z);
}

// Accumulates one texel: weighted values of f, the solid angle and the first moment.
struct Accumulator {
  const AnalyticEnvironment& f;
  long double sum[3] = {}, omega = 0, moment[3] = {}, cover = 0;

  void add(const Dir3& d, long double w) {
    const std::array<double, 3> v = f(d);
    for (int c = 0; c < 3; ++c) sum[c] += w * v[c];
    omega += w;
    if (f.in_cap(d)) cover += w;
    moment[0] += w * d.x, moment[1] += w * d.y, moment[2] += w * d.z;
  }
  Texel texel(double diameter) const {
    Texel t;
    for (int c = 0; c < 3; ++c) t.average[c] = omega > 0 ? static_cast<double>(sum[c] / omega) : 0.0;
    t.solid_angle = static_cast<double>(omega);
    t.cap_cover = omega > 0 ? static_cast<double>(cover / omega) : 0.0;
    t.diameter = diameter;
    t.direction = unit(static_cast<double>(moment[0]), static_cast<double>(moment[1]), static_cast<double>(moment[2]));
    return t;
  }
};

// The rule for one texel. Away from the lobe and the cap's edge, f is the band-limited part
// (a quadratic in d) plus a constant (the cap, or none) plus a lobe below
// 100 exp(-kappa (1 - cos kNear)) = 2e-9: one cell of 6 x 6 nodes. Within
// kNear of the lobe (8 of its widths), cells of at most kCell radians (one lobe width) of
// 8 x 8 nodes. Where the cap's edge may cross the texel, cells of at most half the cap's
// radius (up to 32 x 32 cells), so that the rendered disc is close to round: the tolerance
// does not rely on it (layout_render.h), but the measured error is then mostly the
// projection's, not the rendering's. `fine` doubles the cells: the second density that
// measures the rule's error on the smooth part (projection_tolerance's caller adds the
// difference).
constexpr double kNear = 0.4, kCell = 0.05;
struct Rule {
  int sub, q;
};
int cells(double diameter, double cell, int most) {
  return std::clamp(static_cast<int>(std::ceil(diameter / cell)), 1, most);
}
Rule rule_for(const AnalyticEnvironment& f, const Dir3& centre, double diameter, bool fine) {
  const bool near = angle_between(centre, f.axis) - diameter < kNear;
  const bool edge = std::fabs(angle_between(centre, f.cap_axis) - f.cap_radius) <= diameter;
  const int sub = std::max(near ? cells(diameter, kCell, 16) : 1, edge ? cells(diameter, 0.5 * f.cap_radius, 32) : 1);
  const int q = near || edge ? 8 : 6;
  return fine ? Rule{2 * sub, q} : Rule{sub, q};
}

// Composite tensor Gauss-Legendre over [x0, x1] x [y0, y1]: sub x sub cells of q x q nodes;
// `node(x, y, w)` receives each node and its weight.
void composite(double x0, double x1, double y0, double y1, Rule rule, const std::function<void(double, double, double)>& node) {
  const shpack_test::GaussRule g = shpack_test::gauss_legendre(rule.q);
  const double hx = (x1 - x0) / rule.sub, hy = (y1 - y0) / rule.sub;
  for (int a = 0; a < rule.sub; ++a)
    for (int b = 0; b < rule.sub; ++b)
      for (int i = 0; i < rule.q; ++i)
        for (int j = 0; j < rule.q; ++j)
          node(x0 + hx * (a + 0.5 + 0.5 * g.nodes[i]), y0 + hy * (b + 0.5 + 0.5 * g.nodes[j]),
               0.25 * hx * hy * g.weights[i] * g.weights[j]);
}

void store(Rendering& r, std::uint32_t x, std::uint32_t y, const Texel& t) {
  for (int c = 0; c < 3; ++c) r.rgb[3 * (std::size_t{y} * r.width + x) + c] = static_cast<float>(t.average[c]);
  r.texels.push_back(t);
}

Dir3 face_direction(int face, double a, double b) {
  const shpack::CubeFaceAxes& f = shpack::kCubeFaceAxes[face];
  return unit(f.normal.x + a * f.u_axis.x + b * f.v_axis.x, f.normal.y + a * f.u_axis.y + b * f.v_axis.y,
              f.normal.z + a * f.u_axis.z + b * f.v_axis.z);
}

// The solid angle per unit image area of a sphere map at (u, v) (project_sphere_map.h).
double sphere_map_jacobian(shpack::SphereMap map, double u, double v) {
  const double rho = std::hypot(u, v);
  if (map == shpack::SphereMap::Angular) return rho > 0 ? kPi * std::sin(kPi * rho) / rho : kPi * kPi;
  if (map == shpack::SphereMap::MirrorBall) return 4.0;
  const double z = 1.0 - std::fabs(u) - std::fabs(v);
  const double px = z >= 0 ? u : (u >= 0 ? 1 : -1) * (1 - std::fabs(v));
  const double py = z >= 0 ? v : (v >= 0 ? 1 : -1) * (1 - std::fabs(u));
  const double p2 = px * px + py * py + z * z;
  return 1.0 / (p2 * std::sqrt(p2));
}

}  // namespace

std::array<double, 3> AnalyticEnvironment::operator()(const Dir3& d) const {
  const std::array<double, 9> y = shpack::eval_basis(d.x, d.y, d.z);  // pinned by sh/basis_test.cpp
  const double lobe_shape = std::exp(kappa * (axis.x * d.x + axis.y * d.y + axis.z * d.z - 1.0));
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 9; ++i) out[c] += band_limited.c[c][i] * y[i];
    out[c] += lobe[c] * lobe_shape;
    if (in_cap(d)) out[c] += cap[c];
  }
  return out;
}

bool AnalyticEnvironment::in_cap(const Dir3& d) const {
  return cap_axis.x * d.x + cap_axis.y * d.y + cap_axis.z * d.z >= std::cos(cap_radius);
}

shpack::ShL2 AnalyticEnvironment::exact() const {
  const double k = kappa, e = std::exp(-2.0 * k);
  const double lambda[3] = {2 * kPi * (1 - e) / k, 2 * kPi * (1 / k - 1 / (k * k) + e * (1 / k + 1 / (k * k))),
                            2 * kPi * (1 / k - 3 / (k * k) + 3 / (k * k * k) - e * (1 / k + 3 / (k * k) + 3 / (k * k * k)))};
  const double s = std::sin(cap_radius), h = std::sin(0.5 * cap_radius);
  const double mu[3] = {4 * kPi * h * h, kPi * s * s, kPi * std::cos(cap_radius) * s * s};
  const std::array<double, 9> y = shpack_test::unity_basis_slow(axis.x, axis.y, axis.z);
  const std::array<double, 9> y_cap = shpack_test::unity_basis_slow(cap_axis.x, cap_axis.y, cap_axis.z);
  shpack::ShL2 out = band_limited;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i)
      out.c[c][i] += lobe[c] * lambda[shpack::kBand[i]] * y[i] + cap[c] * mu[shpack::kBand[i]] * y_cap[i];
  return out;
}

double AnalyticEnvironment::gradient_bound(int channel, double lo, double hi) const {
  // Band-limited part: Cauchy-Schwarz over m with the addition theorem for gradients.
  double g = 0;
  for (int l = 1; l <= 2; ++l) {
    double norm = 0;
    for (int m = -l; m <= l; ++m) norm += band_limited.c[channel][l * (l + 1) + m] * band_limited.c[channel][l * (l + 1) + m];
    g += std::sqrt(norm) * std::sqrt(l * (l + 1.0) * (2 * l + 1.0) / (4 * kPi));
  }
  // Lobe: |grad| = L kappa sin(theta) exp(kappa (cos theta - 1)), which rises to its peak at
  // cos theta* = (-1 + sqrt(1 + 4 kappa^2)) / (2 kappa) (where its derivative vanishes) and
  // falls after it.
  const auto h = [&](double t) { return kappa * std::sin(t) * std::exp(kappa * (std::cos(t) - 1.0)); };
  const double peak = std::acos((-1.0 + std::sqrt(1.0 + 4.0 * kappa * kappa)) / (2.0 * kappa));
  hi = std::min(hi, kPi);
  const double m = lo <= peak && peak <= hi ? h(peak) : std::max(h(lo), h(hi));
  return g + std::fabs(lobe[channel]) * m;
}

AnalyticEnvironment make_environment(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  AnalyticEnvironment f;
  f.band_limited = shpack_test::random_band_limited(rng).coefficients;
  f.axis = unit(0.3, 0.5, 0.8);
  f.kappa = 400.0;
  f.lobe = {100.0, 80.0, 60.0};
  f.cap_axis = unit(-0.6, 0.2, -0.7);
  f.cap_radius = 3.0 * kPi / 180.0;
  f.cap = {40.0, 50.0, 60.0};
  return f;
}

Rendering render_equirect(std::uint32_t width, std::uint32_t height, const AnalyticEnvironment& f, bool fine) {
  Rendering r{width, height, std::vector<float>(std::size_t{3} * width * height), {}};
  for (std::uint32_t y = 0; y < height; ++y) {
    const double t0 = kPi * y / height, t1 = kPi * (y + 1) / height;
    const double max_sin = t0 <= kPi / 2 && kPi / 2 <= t1 ? 1.0 : std::max(std::sin(t0), std::sin(t1));
    for (std::uint32_t x = 0; x < width; ++x) {
      const double lon1 = (0.5 - double(x) / width) * 2 * kPi, lon0 = (0.5 - double(x + 1) / width) * 2 * kPi;
      // A path in theta, then along the latitude circle: D <= dtheta + max sin(theta) dlon.
      const double diameter = (t1 - t0) + max_sin * (lon1 - lon0);
      const Rule rule = rule_for(f, shpack::equirect_direction((x + 0.5) / width, (y + 0.5) / height), diameter, fine);
      Accumulator acc{f};
      composite(t0, t1, lon0, lon1, rule, [&](double theta, double lon, double w) {
        acc.add(shpack::equirect_direction(0.5 - lon / (2 * kPi), theta / kPi), w * std::sin(theta));
      });
      store(r, x, y, acc.texel(diameter));
    }
  }
  return r;
}

std::array<Rendering, 6> render_cube_faces(std::uint32_t n, const AnalyticEnvironment& f, bool fine) {
  std::array<Rendering, 6> faces;
  // The gnomonic map is 1-Lipschitz (|d(dir)/da| = sqrt(1 + b^2) / r^2 <= 1): D <= sqrt(2) 2/N.
  const double diameter = std::sqrt(2.0) * 2.0 / n;
  for (int face = 0; face < 6; ++face) {
    Rendering& r = faces[face];
    r = {n, n, std::vector<float>(std::size_t{3} * n * n), {}};
    for (std::uint32_t y = 0; y < n; ++y)
      for (std::uint32_t x = 0; x < n; ++x) {
        const Dir3 centre = face_direction(face, 2.0 * (x + 0.5) / n - 1.0, 2.0 * (y + 0.5) / n - 1.0);
        Accumulator acc{f};
        composite(2.0 * x / n - 1.0, 2.0 * (x + 1) / n - 1.0, 2.0 * y / n - 1.0, 2.0 * (y + 1) / n - 1.0,
                  rule_for(f, centre, diameter, fine), [&](double a, double b, double w) {
                    const double r2 = 1.0 + a * a + b * b;
                    acc.add(face_direction(face, a, b), w / (r2 * std::sqrt(r2)));
                  });
        store(r, x, y, acc.texel(diameter));
      }
  }
  return faces;
}

Rendering assemble_cube_image(shpack::CubeLayout layout, const std::array<Rendering, 6>& faces) {
  const shpack::CubeGrid grid = shpack::cube_layout_grid(layout);
  const std::uint32_t n = faces[0].width;
  Rendering r{grid.columns * n, grid.rows * n, std::vector<float>(std::size_t{3} * grid.columns * n * grid.rows * n), {}};
  for (int face = 0; face < 6; ++face) {
    const shpack::CubeCell cell = shpack::cube_layout_cell(layout, static_cast<shpack::CubeFace>(face));
    for (std::uint32_t y = 0; y < n; ++y)
      for (std::uint32_t x = 0; x < n; ++x) {
        // Face texel (x, y) is stored at (N-1-x, N-1-y) of a rotated cell.
        const std::uint32_t ix = cell.column * n + (cell.rotated_180 ? n - 1 - x : x);
        const std::uint32_t iy = cell.row * n + (cell.rotated_180 ? n - 1 - y : y);
        for (int c = 0; c < 3; ++c)
          r.rgb[3 * (std::size_t{iy} * r.width + ix) + c] = faces[face].rgb[3 * (std::size_t{y} * n + x) + c];
      }
    r.texels.insert(r.texels.end(), faces[face].texels.begin(), faces[face].texels.end());
  }
  return r;
}

Rendering render_sphere_map(shpack::SphereMap map, std::uint32_t n, const AnalyticEnvironment& f, bool fine) {
  Rendering r{n, n, std::vector<float>(std::size_t{3} * n * n), {}};
  const double h = 2.0 / n;
  for (std::uint32_t y = 0; y < n; ++y) {
    for (std::uint32_t x = 0; x < n; ++x) {
      const double u0 = 2.0 * x / n - 1.0, u1 = u0 + h, v1 = 1.0 - 2.0 * y / n, v0 = v1 - h;
      const double far_u = std::max(std::fabs(u0), std::fabs(u1)), far_v = std::max(std::fabs(v0), std::fabs(v1));
      const double near_u = u0 <= 0 && 0 <= u1 ? 0.0 : std::min(std::fabs(u0), std::fabs(u1));
      const double near_v = v0 <= 0 && 0 <= v1 ? 0.0 : std::min(std::fabs(v0), std::fabs(v1));
      const double rho_far = std::hypot(far_u, far_v), rho_near = std::hypot(near_u, near_v);
      if (map != shpack::SphereMap::Octahedral && rho_near >= 1.0) continue;  // outside the disc: ignored
      // D: the map's Lipschitz bound times the texel's diagonal sqrt(2) h in the image plane;
      // octahedral: |d(p/|p|)| <= |dp| / |p| <= sqrt(3) sqrt(3); angular: pi (radially and
      // tangentially); mirror ball: 2 tangentially (pi/2 for an arc over a chord) plus the
      // whole radial range of psi = 2 asin(rho) over the texel.
      double diameter = std::sqrt(2.0) * h;
      if (map == shpack::SphereMap::Octahedral) diameter *= 3.0;
      if (map == shpack::SphereMap::Angular) diameter *= kPi;
      if (map == shpack::SphereMap::MirrorBall)
        diameter = kPi * diameter + 2.0 * (std::asin(std::min(rho_far, 1.0)) - std::asin(rho_near));
      double cu = u0 + 0.5 * h, cv = v0 + 0.5 * h;  // the centre, pulled into the disc if outside
      if (const double rho = std::hypot(cu, cv); map != shpack::SphereMap::Octahedral && rho > 1.0) cu /= rho, cv /= rho;
      Dir3 centre;
      (void)shpack_test::sphere_map_direction(map, cu, cv, centre);
      Rule rule = rule_for(f, centre, diameter, fine);
      Accumulator acc{f};
      // The plain rule on the square where the integrand is analytic: no fold through the
      // texel (octahedral), or wholly inside the disc and, for the mirror ball (whose
      // s = sqrt(1 - rho^2) has its branch point on the rim), half a texel from the rim, in
      // cells at least 4 times smaller than that gap.
      const bool folded = (u0 < 0 && 0 < u1) || (v0 < 0 && 0 < v1) || (near_u + near_v < 1.0 && far_u + far_v > 1.0);
      const bool plain = map == shpack::SphereMap::Octahedral ? !folded
                         : map == shpack::SphereMap::Angular  ? rho_far <= 1.0
                                                              : rho_far <= 1.0 - 0.5 * h;
      if (map == shpack::SphereMap::MirrorBall && rho_far > 1.0 - 2.0 * h) rule.sub = std::max(rule.sub, fine ? 16 : 8);
      if (plain) {
        composite(u0, u1, v0, v1, rule, [&](double u, double v, double w) {
          Dir3 d;
          (void)shpack_test::sphere_map_direction(map, u, v, d);
          acc.add(d, w * sphere_map_jacobian(map, u, v));
        });
      } else {
        // The oracle's own rules, refined (up to 2 times) near the lobe.
        shpack_test::sphere_map_texel_integrate(
            map, n, x, y, [&](const Dir3& d, long double w) { acc.add(d, w); }, std::min(rule.sub, 2));
      }
      store(r, x, y, acc.texel(diameter));
    }
  }
  return r;
}

bool cut_by_cap_edge(const Texel& t, const AnalyticEnvironment& f) {
  return std::fabs(angle_between(t.direction, f.cap_axis) - f.cap_radius) <= t.diameter;
}

double cut_solid_angle(const std::vector<Texel>& texels, const AnalyticEnvironment& f) {
  double omega = 0;
  for (const Texel& t : texels)
    if (cut_by_cap_edge(t, f)) omega += t.solid_angle;
  return omega;
}

double projection_tolerance(const std::vector<Texel>& texels, const AnalyticEnvironment& f, int channel, int i) {
  const int l = shpack::kBand[i];
  const double g_l = std::sqrt(l * (l + 1.0) * (2 * l + 1.0) / (4 * kPi));
  const double max_y = std::sqrt(5.0 / (4 * kPi));
  const double cap_edge = std::fabs(f.cap[channel]) * max_y * cut_solid_angle(texels, f);
  double discretisation = 0, rounding = 0;
  for (const Texel& t : texels) {
    const double from_axis = angle_between(t.direction, f.axis);
    const double g_f = f.gradient_bound(channel, std::max(0.0, from_axis - t.diameter), from_axis + t.diameter);
    discretisation += t.solid_angle * t.diameter * t.diameter * g_f * g_l;
    rounding += 0x1p-24 * std::fabs(t.average[channel]) * t.solid_angle * max_y;
  }
  return discretisation + cap_edge + rounding;
}

}  // namespace shpack_layout_test
