#include "support/sphere_map_oracle.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "shpack/sh_basis.h"
#include "support/gauss_legendre.h"

namespace shpack_test {
namespace {

using shpack::Dir3;
using shpack::SphereMap;
using LD = long double;

constexpr LD kPiL = std::numbers::pi_v<long double>;
constexpr int kGradedLevels = 16;

struct Square {
  double u0, u1, v0, v1;
};

Square texel_square(std::uint32_t n, std::uint32_t x, std::uint32_t y) {
  const double s = n;
  return {(2.0 * x - s) / s, (2.0 * x + 2.0 - s) / s, (s - 2.0 * y - 2.0) / s, (s - 2.0 * y) / s};
}


// ---------------------------------------------------------------------------------------
// Disc maps

// The direction at angle psi from the centre direction, azimuth alpha.
// Trigonometry in double (correctly rounded to ~1 ulp); sums stay in long double.
Dir3 disc_direction(SphereMap map, double psi, double alpha) {
  const double s = std::sin(psi), c = std::cos(psi);
  return {s * std::cos(alpha), s * std::sin(alpha), map == SphereMap::Angular ? c : -c};
}

LD psi_of(SphereMap map, LD rho) { return map == SphereMap::Angular ? kPiL * rho : 2 * std::asin(std::min<LD>(rho, 1)); }

// Where the ray t (cos alpha, sin alpha), t >= 0, is inside the square.
bool ray_range(const Square& q, LD ca, LD sa, LD& t0, LD& t1) {
  t0 = 0;
  t1 = INFINITY;
  const LD lo[2] = {q.u0, q.v0}, hi[2] = {q.u1, q.v1}, dir[2] = {ca, sa};
  for (int k = 0; k < 2; ++k) {
    if (std::fabs(dir[k]) < 1e-30L) {
      if (lo[k] > 0 || hi[k] < 0) return false;
      continue;
    }
    LD a = lo[k] / dir[k], b = hi[k] / dir[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 < t1;
}

// int over [alpha_a, alpha_b] of the ray integrals, by Gauss-Legendre of order q.
void alpha_interval(SphereMap map, const Square& sq, LD a, LD b, int q, int refine, const DirectionSink& acc) {
  const GaussRule outer = gauss_legendre(q), inner = gauss_legendre(20);
  const LD ha = (b - a) / 2, ma = (a + b) / 2;
  for (std::size_t i = 0; i < outer.nodes.size(); ++i) {
    const LD alpha = ma + ha * outer.nodes[i];
    LD t0, t1;
    if (!ray_range(sq, std::cos(static_cast<double>(alpha)), std::sin(static_cast<double>(alpha)), t0, t1)) continue;
    t1 = std::min<LD>(t1, 1);
    if (!(t0 < t1)) continue;
    const LD p0 = psi_of(map, t0), p1 = psi_of(map, t1);
    const LD hp = (p1 - p0) / (2 * refine);
    for (int part = 0; part < refine; ++part) {
      const LD mp = p0 + (2 * part + 1) * hp;
      for (std::size_t j = 0; j < inner.nodes.size(); ++j) {
        const LD psi = mp + hp * inner.nodes[j];
        acc(disc_direction(map, static_cast<double>(psi), static_cast<double>(alpha)),
            ha * outer.weights[i] * hp * inner.weights[j] * std::sin(static_cast<double>(psi)));
      }
    }
  }
}

void disc_oracle(SphereMap map, const Square& sq, int refine, const DirectionSink& acc) {
  const double nu = std::clamp(0.0, sq.u0, sq.u1), nv = std::clamp(0.0, sq.v0, sq.v1);
  if (nu * nu + nv * nv >= 1.0) return;
  const bool holds_origin = sq.u0 <= 0 && 0 <= sq.u1 && sq.v0 <= 0 && 0 <= sq.v1;
  const LD base = holds_origin ? 0 : std::atan2((LD)(sq.v0 + sq.v1), (LD)(sq.u0 + sq.u1));
  auto relative = [&](LD u, LD v) {
    LD r = std::atan2(v, u) - base;
    while (r > kPiL) r -= 2 * kPiL;
    while (r <= -kPiL) r += 2 * kPiL;
    return r;
  };
  struct Cut {
    LD at;
    bool rim;  // an edge crosses the rim here: the mirror ball's square-root point
  };
  std::vector<Cut> cuts;
  const double us[2] = {sq.u0, sq.u1}, vs[2] = {sq.v0, sq.v1};
  for (double u : us)
    for (double v : vs)
      if (u != 0 || v != 0) cuts.push_back({relative(u, v), false});
  LD lo = INFINITY, hi = -INFINITY;
  for (const Cut& c : cuts) lo = std::min(lo, c.at), hi = std::max(hi, c.at);
  if (holds_origin) lo = -kPiL, hi = kPiL;
  for (double e : us)
    if (std::fabs(e) < 1)
      for (LD v : {-std::sqrt(1 - (LD)e * e), std::sqrt(1 - (LD)e * e)})
        if (sq.v0 <= v && v <= sq.v1) cuts.push_back({relative(e, v), true});
  for (double e : vs)
    if (std::fabs(e) < 1)
      for (LD u : {-std::sqrt(1 - (LD)e * e), std::sqrt(1 - (LD)e * e)})
        if (sq.u0 <= u && u <= sq.u1) cuts.push_back({relative(u, e), true});
  cuts.push_back({lo, false});
  cuts.push_back({hi, false});
  std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.at < y.at; });
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const LD a = std::max(cuts[k].at, lo), b = std::min(cuts[k + 1].at, hi);
    if (!(a < b)) continue;
    const bool grade_a = map == SphereMap::MirrorBall && cuts[k].rim;
    const bool grade_b = map == SphereMap::MirrorBall && cuts[k + 1].rim;
    const LD mid = (a + b) / 2;
    // Each half: graded towards its end when that end is a rim crossing, else two plain parts.
    for (const bool left : {true, false}) {
      const LD end = left ? a : b, sign = left ? 1 : -1;
      const LD half = (b - a) / 2;
      if (!(left ? grade_a : grade_b)) {
        const LD lo_half = left ? a : mid, hi_half = left ? mid : b;
        const int parts = 2 * refine;
        for (int part = 0; part < parts; ++part)
          alpha_interval(map, sq, base + lo_half + (hi_half - lo_half) * part / parts,
                         base + lo_half + (hi_half - lo_half) * (part + 1) / parts, 20, refine, acc);
        continue;
      }
      LD edge = half;
      for (int level = 0; level < kGradedLevels; ++level, edge /= 2) {
        const LD p = end + sign * edge / 2, q = end + sign * edge;
        alpha_interval(map, sq, base + std::min(p, q), base + std::max(p, q), 16, refine, acc);
      }
      alpha_interval(map, sq, base + std::min(end, end + sign * edge), base + std::max(end, end + sign * edge), 16, refine,
                     acc);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Octahedral maps

struct P2 {
  LD u, v;
};
struct P3 {
  LD x, y, z;
};

// The eight triangles of the unfolded octahedron and the linear map on each.
struct OctTriangle {
  P2 corner[3];
  double su, sv;
  bool outer;

  P3 point(LD u, LD v) const {
    const LD a = su * u, b = sv * v;
    if (outer) return {su * (1 - b), sv * (1 - a), 1 - a - b};
    return {u, v, 1 - a - b};
  }
};

std::vector<OctTriangle> oct_triangles() {
  std::vector<OctTriangle> t;
  for (double su : {-1.0, 1.0})
    for (double sv : {-1.0, 1.0}) {
      t.push_back({{{0, 0}, {su, 0}, {0, sv}}, su, sv, false});
      t.push_back({{{su, 0}, {su, sv}, {0, sv}}, su, sv, true});
    }
  for (OctTriangle& tri : t) {  // counter-clockwise
    const LD area = (tri.corner[1].u - tri.corner[0].u) * (tri.corner[2].v - tri.corner[0].v) -
                    (tri.corner[1].v - tri.corner[0].v) * (tri.corner[2].u - tri.corner[0].u);
    if (area < 0) std::swap(tri.corner[1], tri.corner[2]);
  }
  return t;
}

// Sutherland-Hodgman: the part of the convex polygon `poly` left of the directed line a->b.
std::vector<P2> clip(const std::vector<P2>& poly, P2 a, P2 b) {
  std::vector<P2> out;
  auto side = [&](P2 p) { return (b.u - a.u) * (p.v - a.v) - (b.v - a.v) * (p.u - a.u); };
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const P2 p = poly[k], q = poly[(k + 1) % poly.size()];
    const LD sp = side(p), sq = side(q);
    if (sp >= 0) out.push_back(p);
    if ((sp >= 0) != (sq >= 0)) {
      const LD t = sp / (sp - sq);
      out.push_back({p.u + t * (q.u - p.u), p.v + t * (q.v - p.v)});
    }
  }
  return out;
}

std::vector<P2> texel_piece(const Square& sq, const OctTriangle& tri) {
  std::vector<P2> poly = {{sq.u0, sq.v0}, {sq.u1, sq.v0}, {sq.u1, sq.v1}, {sq.u0, sq.v1}};
  for (int e = 0; e < 3 && !poly.empty(); ++e) poly = clip(poly, tri.corner[e], tri.corner[(e + 1) % 3]);
  return poly;
}

LD polygon_area(const std::vector<P2>& p) {
  LD a = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const P2 s = p[k], t = p[(k + 1) % p.size()];
    a += s.u * t.v - t.u * s.v;
  }
  return a / 2;
}

// Collapsed Gauss-Legendre on triangle (A, B, C), split into 4^levels.
void oct_triangle(const OctTriangle& tri, P2 A, P2 B, P2 C, int levels, const DirectionSink& acc) {
  if (levels > 0) {
    const P2 ab{(A.u + B.u) / 2, (A.v + B.v) / 2}, bc{(B.u + C.u) / 2, (B.v + C.v) / 2},
        ca{(C.u + A.u) / 2, (C.v + A.v) / 2};
    oct_triangle(tri, A, ab, ca, levels - 1, acc);
    oct_triangle(tri, ab, B, bc, levels - 1, acc);
    oct_triangle(tri, ca, bc, C, levels - 1, acc);
    oct_triangle(tri, ab, bc, ca, levels - 1, acc);
    return;
  }
  const GaussRule g = gauss_legendre(12);
  const LD det = std::fabs((B.u - A.u) * (C.v - B.v) - (B.v - A.v) * (C.u - B.u));
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const LD s = (1 + (LD)g.nodes[i]) / 2;
    for (std::size_t j = 0; j < g.nodes.size(); ++j) {
      const LD t = (1 + (LD)g.nodes[j]) / 2;
      const LD u = A.u + s * (B.u - A.u) + s * t * (C.u - B.u), v = A.v + s * (B.v - A.v) + s * t * (C.v - B.v);
      const P3 p = tri.point(u, v);
      const LD r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
      const Dir3 d{static_cast<double>(p.x / r), static_cast<double>(p.y / r), static_cast<double>(p.z / r)};
      acc(d, g.weights[i] * g.weights[j] / 4 * s * det / (r * r * r));
    }
  }
}

P3 unit(P3 p) {
  const LD r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  return {p.x / r, p.y / r, p.z / r};
}
P3 cross(P3 a, P3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
LD dot(P3 a, P3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

}  // namespace

bool sphere_map_direction(SphereMap map, double u, double v, Dir3& d) {
  if (map == SphereMap::Octahedral) {
    double x = u, y = v;
    const double z = 1.0 - std::fabs(u) - std::fabs(v);
    if (z < 0) {  // Unity's UnpackNormalOctQuadEncode: n.xy += n.xy >= 0 ? -t : t
      x = (u >= 0 ? 1.0 : -1.0) * (1.0 - std::fabs(v));
      y = (v >= 0 ? 1.0 : -1.0) * (1.0 - std::fabs(u));
    }
    const double r = std::sqrt(x * x + y * y + z * z);
    d = {x / r, y / r, z / r};
    return true;
  }
  const double rho = std::hypot(u, v);
  if (rho > 1.0) return false;
  if (map == SphereMap::Angular) {
    const double psi = std::numbers::pi * rho, k = rho > 0 ? std::sin(psi) / rho : std::numbers::pi;
    d = {k * u, k * v, std::cos(psi)};
  } else {
    const double s = std::sqrt(1.0 - rho * rho);
    d = {2 * u * s, 2 * v * s, 2 * rho * rho - 1};
  }
  return true;
}

void sphere_map_point(SphereMap map, const Dir3& d, double& u, double& v) {
  if (map == SphereMap::Octahedral) {  // Unity's PackNormalOctQuadEncode
    const double l1 = std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    const double x = d.x / l1, y = d.y / l1, t = std::max(-d.z / l1, 0.0);
    u = x + (x >= 0 ? t : -t);
    v = y + (y >= 0 ? t : -t);
    return;
  }
  const double xy = std::hypot(d.x, d.y);
  // Angle from the centre direction, as a radius in the image.
  const double rho = map == SphereMap::Angular ? std::acos(std::clamp(d.z, -1.0, 1.0)) / std::numbers::pi
                                               : std::sqrt((1.0 + d.z) / 2.0);
  u = xy > 0 ? rho * d.x / xy : rho;
  v = xy > 0 ? rho * d.y / xy : 0.0;
}

void sphere_map_texel_integrate(SphereMap map, std::uint32_t n, std::uint32_t x, std::uint32_t y,
                                const DirectionSink& sink, int refine) {
  const Square sq = texel_square(n, x, y);
  if (map != SphereMap::Octahedral) return disc_oracle(map, sq, refine, sink);
  const int levels = 1 + static_cast<int>(std::ceil(std::log2(static_cast<double>(refine))));
  for (const OctTriangle& tri : oct_triangles()) {
    const std::vector<P2> poly = texel_piece(sq, tri);
    if (poly.size() < 3 || polygon_area(poly) < 1e-30L) continue;
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) oct_triangle(tri, poly[0], poly[k], poly[k + 1], levels + 1, sink);
  }
}

std::array<long double, 10> sphere_map_texel_oracle(SphereMap map, std::uint32_t n, std::uint32_t x, std::uint32_t y) {
  std::array<LD, 10> acc{};
  sphere_map_texel_integrate(map, n, x, y, [&acc](const Dir3& d, LD weight) {
    const std::array<double, 9> basis = shpack::eval_basis(d.x, d.y, d.z);
    for (int i = 0; i < 9; ++i) acc[i] += weight * basis[i];
    acc[9] += weight;
  });
  return acc;
}

OctahedralClosedForm octahedral_texel_closed_form(std::uint32_t n, std::uint32_t x, std::uint32_t y) {
  const Square sq = texel_square(n, x, y);
  OctahedralClosedForm out;
  for (const OctTriangle& tri : oct_triangles()) {
    const std::vector<P2> poly = texel_piece(sq, tri);
    if (poly.size() < 3 || polygon_area(poly) < 1e-30L) continue;
    std::vector<P3> p;
    for (const P2& q : poly) p.push_back(tri.point(q.u, q.v));
    for (std::size_t k = 1; k + 1 < p.size(); ++k) {
      const P3 a = p[0], b = p[k], c = p[k + 1];
      const LD la = std::sqrt(dot(a, a)), lb = std::sqrt(dot(b, b)), lc = std::sqrt(dot(c, c));
      const LD num = std::fabs(dot(a, cross(b, c)));
      const LD den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
      out.solid_angle += 2 * std::atan2(num, den);
    }
    for (std::size_t k = 0; k < p.size(); ++k) {
      const P3 a = unit(p[k]), b = unit(p[(k + 1) % p.size()]);
      const P3 axb = cross(a, b);
      const LD s = std::sqrt(dot(axb, axb));
      if (s == 0) continue;  // a repeated vertex of the clipped polygon: no edge
      const LD theta = std::atan2(s, dot(a, b));
      out.first_moment[0] += theta * axb.x / s / 2;
      out.first_moment[1] += theta * axb.y / s / 2;
      out.first_moment[2] += theta * axb.z / s / 2;
    }
  }
  return out;
}

}  // namespace shpack_test
