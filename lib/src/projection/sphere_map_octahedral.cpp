// Texel integrals of octahedral maps (project_sphere_map.h gives the mapping).
//
// In the quadrant (sgn u, sgn v) = (su, sv), with a = su u >= 0 and b = sv v >= 0, the map is
// linear on each side of the fold a + b = 1:
//
//   inner (a + b <= 1, z >= 0):  p = (su a,       sv b,       1 - a - b)
//   outer (a + b >= 1, z <= 0):  p = (su (1 - b), sv (1 - a), 1 - a - b)
//
// and dw = da db / |p|^3 on both (project_sphere_map.h). So a texel is cut by u = 0, v = 0
// and |u| + |v| = 1 into at most eight convex pieces, on each of which the integrand
// P_i(p/|p|) / |p|^3 is analytic: |p|^2 = sum_k p_k^2 >= 1/3 on the real pieces, and for
// complex (a, b) it vanishes only when the imaginary parts (a', b') give sum_k (Im p_k)^2
// >= 1/3; Im p = a' p_a + b' p_b with |p_a|^2 = |p_b|^2 = 2, p_a . p_b = 1 (largest singular
// value sqrt 3), so |(a', b')| >= 1/3 and one of them exceeds kImaginaryGap = 0.23. Each
// piece is integrated by the tensor Gauss-Legendre rule (rectangles) or the collapsed
// (Duffy) rule on a fan of triangles, x(s, t) = A + s (B - A) + s t (C - B),
// dx = s |det(B - A, C - B)| ds dt, with the order of the ellipse bound for a singularity at
// that imaginary distance from an interval of half-length H (the piece's longest side / 2):
// r = eta/H + sqrt(1 + (eta/H)^2).
#include <algorithm>
#include <cmath>

#include "common/gauss_legendre.h"
#include "projection/sphere_map_texels.h"

namespace shpack::detail {
namespace {

constexpr double kImaginaryGap = 0.23;

struct Point {
  double a, b;
};

// A piece of one quadrant on one side of the fold.
struct Side {
  double su, sv;
  bool outer;

  // acc += weight * P(d) / |p|^3 at (a, b).
  void add(double a, double b, double weight, SphereMoments& acc) const noexcept {
    const double z = 1.0 - a - b;
    const double x = outer ? su * (1.0 - b) : su * a;
    const double y = outer ? sv * (1.0 - a) : sv * b;
    const double r_sq = x * x + y * y + z * z, r = std::sqrt(r_sq);
    const std::array<double, kShCount> p = basis_polynomials(x / r, y / r, z / r);
    const double w = weight / (r_sq * r);
    for (int i = 0; i < kShCount; ++i) acc[i] += w * p[i];
  }
};

int order_for(double longest_side) noexcept {
  const double eta = kImaginaryGap / (0.5 * longest_side);
  return std::max(2, gauss_order_for_ellipse(eta + std::sqrt(1.0 + eta * eta)));
}

void integrate_rectangle(const Side& side, double a0, double a1, double b0, double b1,
                         SphereMoments& acc) noexcept {
  const int q = order_for(std::fmax(a1 - a0, b1 - b0));
  const GaussRule rule = gauss_legendre(q);
  const double ha = 0.5 * (a1 - a0), ma = 0.5 * (a0 + a1), hb = 0.5 * (b1 - b0), mb = 0.5 * (b0 + b1);
  for (int i = 0; i < q; ++i)
    for (int j = 0; j < q; ++j)
      side.add(ma + ha * rule.nodes[i], mb + hb * rule.nodes[j], ha * hb * rule.weights[i] * rule.weights[j], acc);
}

void integrate_triangle(const Side& side, Point p0, Point p1, Point p2, SphereMoments& acc) noexcept {
  const double e1a = p1.a - p0.a, e1b = p1.b - p0.b, e2a = p2.a - p1.a, e2b = p2.b - p1.b;
  const double det = std::fabs(e1a * e2b - e1b * e2a);
  if (det == 0) return;
  const double longest = std::fmax(std::fmax(std::hypot(e1a, e1b), std::hypot(e2a, e2b)),
                                   std::hypot(p2.a - p0.a, p2.b - p0.b));
  const int q = std::min(order_for(longest) + 1, kMaxGaussOrder);  // + 1: the collapsed rule's factor s
  const GaussRule rule = gauss_legendre(q);
  for (int i = 0; i < q; ++i) {
    const double s = 0.5 * (1.0 + rule.nodes[i]);
    for (int j = 0; j < q; ++j) {
      const double t = 0.5 * (1.0 + rule.nodes[j]);
      const double a = p0.a + s * e1a + s * t * e2a, b = p0.b + s * e1b + s * t * e2b;
      side.add(a, b, 0.25 * rule.weights[i] * rule.weights[j] * s * det, acc);
    }
  }
}

// The part of the rectangle on one side of a + b = 1 (keep_below: a + b <= 1), as a convex
// polygon of at most 5 vertices (Sutherland-Hodgman against one line).
int clip_to_fold(const Point (&rect)[4], bool keep_below, Point (&out)[5]) noexcept {
  int n = 0;
  for (int k = 0; k < 4; ++k) {
    const Point p = rect[k], q = rect[(k + 1) % 4];
    const double fp = (p.a + p.b) - 1.0, fq = (q.a + q.b) - 1.0;
    const bool p_in = keep_below ? fp <= 0 : fp >= 0, q_in = keep_below ? fq <= 0 : fq >= 0;
    if (p_in) out[n++] = p;
    if (p_in != q_in && fp != fq) {
      // The rectangle's edges are axis-parallel: the crossing has one coordinate of p, q.
      out[n++] = p.a == q.a ? Point{p.a, 1.0 - p.a} : Point{1.0 - p.b, p.b};
    }
  }
  return n;
}

void integrate_quadrant(double su, double sv, double a0, double a1, double b0, double b1,
                        SphereMoments& acc) noexcept {
  if (a1 + b1 <= 1.0) return integrate_rectangle({su, sv, false}, a0, a1, b0, b1, acc);
  if (a0 + b0 >= 1.0) return integrate_rectangle({su, sv, true}, a0, a1, b0, b1, acc);
  const Point rect[4] = {{a0, b0}, {a1, b0}, {a1, b1}, {a0, b1}};
  for (const bool outer : {false, true}) {
    Point poly[5];
    const int n = clip_to_fold(rect, !outer, poly);
    for (int k = 1; k + 1 < n; ++k) integrate_triangle({su, sv, outer}, poly[0], poly[k], poly[k + 1], acc);
  }
}

}  // namespace

SphereMoments octahedral_texel_moments(const TexelSquare& t) noexcept {
  SphereMoments acc{};
  for (const double su : {-1.0, 1.0}) {
    // The texel's part with sgn u = su, as a = su u in [a0, a1].
    const double a0 = su > 0 ? std::fmax(t.u0, 0.0) : std::fmax(-t.u1, 0.0);
    const double a1 = su > 0 ? t.u1 : -t.u0;
    if (!(a0 < a1)) continue;
    for (const double sv : {-1.0, 1.0}) {
      const double b0 = sv > 0 ? std::fmax(t.v0, 0.0) : std::fmax(-t.v1, 0.0);
      const double b1 = sv > 0 ? t.v1 : -t.v0;
      if (b0 < b1) integrate_quadrant(su, sv, a0, a1, b0, b1, acc);
    }
  }
  return acc;
}

}  // namespace shpack::detail
