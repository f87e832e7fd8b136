// Texel integrals of the two disc maps, angular maps and mirrored balls
// (project_sphere_map.h gives the mappings).
//
// A texel is the square [u0, u1] x [v0, v1]; what counts is its part inside the unit disc,
// and the integrand is P_i(d(u, v)) J(u, v), J the solid angle per unit image area:
//
//   angular:      J = pi sin(pi rho) / rho, d = (sin(pi rho) u/rho, sin(pi rho) v/rho, cos(pi rho))
//   mirror ball:  J = 4,                    d = (2us, 2vs, 2 rho^2 - 1),  s = sqrt(1 - rho^2)
//
// The angular integrand is an entire function of (u, v) (sin(pi rho)/rho and cos(pi rho) are
// even in rho, so analytic in rho^2 = u^2 + v^2), of exponential type 3 pi along any line:
// type pi for each of J and the three components of d, P_i being of degree 2. The mirror
// ball's is a polynomial of degree 4 in (u, v, s): analytic except on the rim, where s has a
// square-root branch point.
//
// Three cases per texel:
//  - outside: its nearest point to the centre is on or outside the rim: all zero.
//  - inside, and (mirror ball) at least one texel side h away from the rim: the tensor
//    Gauss-Legendre rule on the square. Angular: order from the exponential-type bound with
//    nu = 3 pi on length h. Mirror ball: from the ellipse bound, the branch point being at
//    least the texel's distance delta from the rim beyond its square along either axis.
//  - otherwise (it reaches the rim, or a mirror-ball texel lies within h of it): the chart
//
//       v = c(u) sin(phi),  c(u) = sqrt(1 - u^2),  dv = s dphi,  s = c(u) cos(phi),
//
//    in which the disc is u in [-1, 1], phi in [-pi/2, pi/2] and s is an entire function of
//    phi: the inner integral over phi, between phi_e(u) = asin(v_e / c(u)) (clamped to
//    +-pi/2 where the edge v = v_e lies outside the disc), is a Gauss-Legendre sum of an
//    analytic integrand. As a function of u, F(u) = int dphi is analytic except at the
//    square-root points sigma of c(u) (u = +-1) and of the active limits (the "kinks"
//    u = +-sqrt(1 - v_e^2) where the edge v = v_e crosses the rim): near such a point
//    F = A(u) + sqrt(|u - sigma|) B(u) with A, B analytic (asin(1 - w) = pi/2 - sqrt(w) *
//    analytic(w)). The u range is cut at the kinks, and on each piece whose nearest
//    square-root point sigma lies within one piece length the outer variable is
//    substituted, u = sigma + tau^2 or sigma - tau^2 (du = 2 tau dtau), which makes
//    sqrt(|u - sigma|) = tau analytic; with such points near both ends, the piece is halved
//    and each half substituted towards its own end. The outer order comes from the ellipse
//    bound for the remaining square-root points (in tau, sigma' maps to sqrt(|sigma' - sigma|),
//    real beyond the interval or imaginary) and the type bound.
// The mirror ball's solid angle (element 0) is then replaced by its closed form,
// 4 x the area of the square inside the disc (disc_square_area).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/angles.h"
#include "common/gauss_legendre.h"
#include "projection/sphere_map_texels.h"

namespace shpack::detail {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;
// Longest u piece and phi chunk integrated by one rule (only small N have longer ones).
constexpr double kMaxChunk = 0.25 * std::numbers::pi;
constexpr double kMaxOuterEllipse = 6.0;

// acc += weight * J * P(d), P from sh_basis.h.
void add_basis(const double x, const double y, const double z, double weight, SphereMoments& acc) noexcept {
  const std::array<double, kShCount> p = basis_polynomials(x, y, z);
  for (int i = 0; i < kShCount; ++i) acc[i] += weight * p[i];
}

struct AngularIntegrand {
  static constexpr double kType = 3.0 * kPi;     // along u and v (see the top of the file)
  static constexpr double kPhiType = 3.0 * kPi + 1.0;  // and in phi: c(u) cos(phi) adds 1
  static constexpr int kMinOrder = 2;

  void operator()(double u, double v, double /*s*/, double weight, SphereMoments& acc) const noexcept {
    const double rho = std::hypot(u, v), x = kPi * rho;
    // sin(pi rho)/rho; below x = 1e-3 its Taylor series, whose next term x^6/5040 is < 2e-22.
    const double sinc = x < 1e-3 ? kPi * (1.0 - x * x / 6.0 + x * x * x * x / 120.0) : std::sin(x) / rho;
    add_basis(sinc * u, sinc * v, std::cos(x), weight * kPi * sinc, acc);
  }
};

struct MirrorBallIntegrand {
  static constexpr double kType = 0.0;      // a polynomial in u (and c(u), handled by the chart)
  static constexpr double kPhiType = 5.0;   // trigonometric of degree 4 + 1 (the Jacobian s) in phi
  static constexpr int kMinOrder = 4;       // exact for the degree-5 polynomial parts

  void operator()(double u, double v, double s, double weight, SphereMoments& acc) const noexcept {
    const double rho_sq = u * u + v * v;
    // 2 rho^2 - 1 = 1 - 2 s^2: whichever term is the smaller keeps its relative accuracy.
    const double z = rho_sq < 0.5 ? 2.0 * rho_sq - 1.0 : 1.0 - 2.0 * s * s;
    add_basis(2.0 * u * s, 2.0 * v * s, z, 4.0 * weight, acc);
  }
};

// The tensor rule of order q on the whole square.
template <class F>
void integrate_square(const TexelSquare& t, int q, const F& f, SphereMoments& acc) noexcept {
  const GaussRule rule = gauss_legendre(q);
  const double hu = 0.5 * (t.u1 - t.u0), mu = 0.5 * (t.u0 + t.u1);
  const double hv = 0.5 * (t.v1 - t.v0), mv = 0.5 * (t.v0 + t.v1);
  for (int i = 0; i < q; ++i) {
    const double u = mu + hu * rule.nodes[i];
    for (int j = 0; j < q; ++j) {
      const double v = mv + hv * rule.nodes[j];
      const double s = std::sqrt(std::fmax(0.0, (1.0 - u) * (1.0 + u) - v * v));
      f(u, v, s, hu * hv * rule.weights[i] * rule.weights[j], acc);
    }
  }
}

// The edges v = v0 (lower limit) and v = v1 (upper), and whether each is inside the disc
// (active) over a piece of the u range.
struct ChartLimits {
  double v0, v1;
  bool lo_active, hi_active;
};

// phi of the edge v_e at c = c(u): asin(v_e / c), clamped to the rim.
double edge_phi(double v_e, double c) noexcept { return std::asin(std::clamp(v_e / c, -1.0, 1.0)); }

// The square-root points of F on a piece: u = +-1 and the kinks of the active limits.
struct SingularPoints {
  double at[6];
  int count = 0;
};

double kink(double v_e) noexcept { return std::sqrt((1.0 - v_e) * (1.0 + v_e)); }

SingularPoints singular_points(const ChartLimits& lim) noexcept {
  SingularPoints s;
  s.at[s.count++] = -1.0;
  s.at[s.count++] = 1.0;
  if (lim.lo_active) s.at[s.count++] = -kink(lim.v0), s.at[s.count++] = kink(lim.v0);
  if (lim.hi_active) s.at[s.count++] = -kink(lim.v1), s.at[s.count++] = kink(lim.v1);
  return s;
}

// How the outer variable of a piece is parametrised, and what remains singular:
//  - Plain: u itself.
//  - Square: u = sigma + side tau^2 (side = +1 when sigma lies below the piece, -1 above):
//    sqrt(|u - sigma|) = tau.
//  - CoshSquare, for two square-root points on the same side, sigma (the farther) and
//    sigma + side D (the nearer): u = sigma + side D cosh^2(t), so that
//    sqrt(|u - sigma|) = sqrt(D) cosh t and sqrt(|u - sigma - side D|) = sqrt(D) sinh t are
//    both entire. Without it the farther point, at sqrt(D) i in tau, would sit next to a
//    tau interval much longer than sqrt(D) (texels at u = +-1 beside the line v = 0, where
//    the edge's kink is D ~ h^2/8 from the rim's branch point).
struct Outer {
  enum Kind : std::uint8_t { Plain, Square, CoshSquare } kind = Plain;
  double sigma = 0, gap = 0;  // Square, CoshSquare: sigma; CoshSquare: D
  int side = 0;
};

// The outer interval in the variable of `outer`.
void outer_interval(const Outer& o, double a, double b, double& t0, double& t1) noexcept {
  const double near_end = o.side > 0 ? a - o.sigma : o.sigma - b;  // |u - sigma| at the near end
  const double far_end = o.side > 0 ? b - o.sigma : o.sigma - a;
  switch (o.kind) {
    case Outer::Plain: t0 = a, t1 = b; return;
    case Outer::Square: t0 = std::sqrt(near_end), t1 = std::sqrt(far_end); return;
    case Outer::CoshSquare:
      t0 = std::acosh(std::sqrt(near_end / o.gap)), t1 = std::acosh(std::sqrt(far_end / o.gap));
      return;
  }
}

// u, 1 - u, 1 + u and du/dt at t. At sigma = +-1, 1 -+ u is computed from t itself: no
// cancellation in c(u) next to the rim.
struct OuterPoint {
  double u, one_minus_u, one_plus_u, du_dt;
};
OuterPoint outer_point(const Outer& o, double t) noexcept {
  double offset = 0, du_dt = 1;  // |u - sigma| and its derivative
  switch (o.kind) {
    case Outer::Plain: return {t, 1.0 - t, 1.0 + t, 1.0};
    case Outer::Square: offset = t * t, du_dt = 2.0 * t; break;
    case Outer::CoshSquare: {
      const double ch = std::cosh(t);
      offset = o.gap * ch * ch, du_dt = o.gap * std::sinh(2.0 * t);
      break;
    }
  }
  const double u = o.sigma + o.side * offset;
  const double one_minus_u = o.sigma == 1.0 && o.side < 0 ? offset : o.sigma == -1.0 && o.side > 0 ? 2.0 - offset : 1.0 - u;
  const double one_plus_u = o.sigma == -1.0 && o.side > 0 ? offset : o.sigma == 1.0 && o.side < 0 ? 2.0 - offset : 1.0 + u;
  return {u, one_minus_u, one_plus_u, du_dt};
}

// The ellipse parameter of the outer rule: from the square-root points that the
// parametrisation leaves singular. Plain: each is a real point beyond the interval. Square:
// a point on the piece's side maps to the real tau = sqrt(|sigma' - sigma|), one on the
// other side to the imaginary tau = i sqrt(|sigma' - sigma|). CoshSquare: a point on the
// piece's side maps to a real t; the others, and the growth of cosh^2, are kept at bay by
// the strip |Im t| < eta with D sinh(2 t1) eta / 2 = the distance to the nearest such point
// (the imaginary excursion of u), and eta <= pi/2.
double outer_ellipse(const Outer& o, double a, double b, double t0, double t1, const SingularPoints& sing) noexcept {
  const double half = 0.5 * (t1 - t0);
  double r = INFINITY;
  for (int k = 0; k < sing.count; ++k) {
    const double x = sing.at[k];
    if (o.kind == Outer::Plain) {
      r = std::fmin(r, ellipse_for_real_gap(x >= b ? x - b : a - x, half));
      continue;
    }
    const double beyond = o.side * (x - o.sigma);  // > 0: on the piece's side of sigma
    if (o.kind == Outer::Square) {
      if (beyond > 0 && std::sqrt(beyond) > t1) r = std::fmin(r, ellipse_for_real_gap(std::sqrt(beyond) - t1, half));
      if (beyond < 0) {
        const double eta = std::sqrt(-beyond) / half;
        r = std::fmin(r, eta + std::sqrt(1.0 + eta * eta));
      }
      continue;
    }
    if (beyond > o.gap && std::sqrt(beyond / o.gap) > std::cosh(t1)) {
      const double far = o.side > 0 ? x - b : a - x;
      r = std::fmin(r, ellipse_for_real_gap(std::acosh(std::sqrt(beyond / o.gap)) - t1, half));
      const double eta = std::fmin(kHalfPi, 2.0 * far / (o.gap * std::sinh(2.0 * t1))) / half;
      r = std::fmin(r, eta + std::sqrt(1.0 + eta * eta));
    }
  }
  return r;
}

// int over [a, b] of F(u) du (see the top of the file) with the given parametrisation.
template <class F>
void chart_piece(double a, double b, const Outer& outer, const ChartLimits& lim, const SingularPoints& sing,
                 const F& f, SphereMoments& acc) noexcept {
  double t0 = 0, t1 = 0;
  outer_interval(outer, a, b, t0, t1);
  const double length = t1 - t0;
  if (!(length > 0)) return;
  // The ellipse bound needs the integrand's maximum on the ellipse; after the substitutions
  // it behaves near t0 like a polynomial of degree up to ~8 times an analytic function, so
  // across a very large ellipse it grows far above its size on the interval. Capped at
  // kMaxOuterEllipse, where that growth stays below ~10^4 (x^8 from 1 to 3.3).
  const double r = std::fmin(outer_ellipse(outer, a, b, t0, t1, sing), kMaxOuterEllipse);
  const double du_dt = std::fmax(outer_point(outer, t0).du_dt, outer_point(outer, t1).du_dt);  // bounds the chain rule
  const int q_outer = std::max({gauss_order_for_ellipse(r),
                                gauss_order_for_type(length, F::kType * du_dt), F::kMinOrder});

  // The widest phi range on the piece sets the inner order.
  double widest = 0;
  for (const double u : {a, 0.5 * (a + b), b}) {
    const double c = std::sqrt((1.0 - u) * (1.0 + u));
    if (c == 0) continue;
    const double lo = lim.lo_active ? edge_phi(lim.v0, c) : -kHalfPi;
    const double hi = lim.hi_active ? edge_phi(lim.v1, c) : kHalfPi;
    widest = std::fmax(widest, hi - lo);
  }
  // Long phi ranges (small N) are cut into chunks of at most kMaxChunk: the bounds are for
  // exponential type, which the composed integrand only has locally.
  const int chunks = std::max(1, static_cast<int>(std::ceil(widest / kMaxChunk)));
  const int q_inner = std::max(gauss_order_for_type(widest / chunks, F::kPhiType), F::kMinOrder);

  const GaussRule ro = gauss_legendre(q_outer), ri = gauss_legendre(q_inner);
  const double ht = 0.5 * length, mt = 0.5 * (t0 + t1);
  for (int i = 0; i < q_outer; ++i) {
    const OuterPoint p = outer_point(outer, mt + ht * ro.nodes[i]);
    const double weight = ht * ro.weights[i] * p.du_dt;
    const double c = std::sqrt(p.one_minus_u * p.one_plus_u);
    if (c == 0) continue;
    const double lo = lim.lo_active ? edge_phi(lim.v0, c) : -kHalfPi;
    const double hi = lim.hi_active ? edge_phi(lim.v1, c) : kHalfPi;
    if (!(lo < hi)) continue;
    const double hp = 0.5 * (hi - lo) / chunks;
    for (int chunk = 0; chunk < chunks; ++chunk) {
      const double mp = lo + (2 * chunk + 1) * hp;
      for (int j = 0; j < q_inner; ++j) {
        const double phi = mp + hp * ri.nodes[j];
        const double s = c * std::cos(phi);
        f(p.u, c * std::sin(phi), s, weight * hp * ri.weights[j] * s, acc);
      }
    }
  }
}

// The parametrisation towards the square-root points on one side of [a, b] (side = +1:
// below a, -1: above b): Square at the nearest, or CoshSquare when the next one is closer to
// it than the tau interval is long.
Outer towards(double a, double b, int side, const SingularPoints& sing) noexcept {
  double nearest = INFINITY, next = INFINITY;  // distances beyond the piece's end
  for (int k = 0; k < sing.count; ++k) {
    const double d = side > 0 ? a - sing.at[k] : sing.at[k] - b;
    if (d < 0) continue;
    if (d < nearest) next = nearest, nearest = d;
    else if (d > nearest && d < next) next = d;
  }
  const double end = side > 0 ? a : b;
  const double sigma_near = end - side * nearest;
  const double tau_length = std::sqrt(nearest + (b - a)) - std::sqrt(nearest);
  if (std::isfinite(next) && std::sqrt(next - nearest) < tau_length)
    return {Outer::CoshSquare, end - side * next, next - nearest, side};
  return {Outer::Square, sigma_near, 0, side};
}

// Cuts [max(u0, -1), min(u1, 1)] at the kinks of the texel's edges; on each piece, the
// limits' activity is constant.
struct Cuts {
  double at[6];
  int count = 0;
};

Cuts kink_cuts(const TexelSquare& t) noexcept {
  Cuts cuts;
  const double ua = std::fmax(t.u0, -1.0), ub = std::fmin(t.u1, 1.0);
  cuts.at[cuts.count++] = ua;
  for (const double v_e : {t.v0, t.v1}) {
    if (std::fabs(v_e) >= 1.0) continue;
    const double k = kink(v_e);
    if (ua < -k && -k < ub) cuts.at[cuts.count++] = -k;
    if (ua < k && k < ub) cuts.at[cuts.count++] = k;
  }
  cuts.at[cuts.count++] = ub;
  for (int i = 1; i < cuts.count; ++i)  // insertion sort of at most 6 values
    for (int j = i; j > 0 && cuts.at[j] < cuts.at[j - 1]; --j) std::swap(cuts.at[j], cuts.at[j - 1]);
  return cuts;
}

// The limits on piece [a, b], or false where the strip [v0, v1] misses the disc.
bool piece_limits(const TexelSquare& t, double a, double b, ChartLimits& lim) noexcept {
  const double m = 0.5 * (a + b), c = std::sqrt((1.0 - m) * (1.0 + m));
  if (t.v0 >= c || t.v1 <= -c) return false;
  lim = {t.v0, t.v1, t.v0 > -c, t.v1 < c};
  return true;
}

template <class F>
void integrate_chart_piece(double a, double b, const ChartLimits& lim, const F& f, SphereMoments& acc) noexcept {
  const SingularPoints sing = singular_points(lim);
  double below = -INFINITY, above = INFINITY;  // the nearest square-root points outside
  for (int j = 0; j < sing.count; ++j) {
    if (sing.at[j] <= a) below = std::fmax(below, sing.at[j]);
    if (sing.at[j] >= b) above = std::fmin(above, sing.at[j]);
  }
  const double length = b - a, gap_below = a - below, gap_above = above - b;
  if (gap_below <= length && gap_above <= length) {
    const double m = 0.5 * (a + b);
    chart_piece(a, m, towards(a, m, +1, sing), lim, sing, f, acc);
    chart_piece(m, b, towards(m, b, -1, sing), lim, sing, f, acc);
  } else if (gap_below <= length && gap_below <= gap_above) {
    chart_piece(a, b, towards(a, b, +1, sing), lim, sing, f, acc);
  } else if (gap_above <= length) {
    chart_piece(a, b, towards(a, b, -1, sing), lim, sing, f, acc);
  } else {
    chart_piece(a, b, {}, lim, sing, f, acc);
  }
}

template <class F>
void integrate_chart(const TexelSquare& t, const F& f, SphereMoments& acc) noexcept {
  const Cuts cuts = kink_cuts(t);
  for (int k = 0; k + 1 < cuts.count; ++k) {
    const double a = cuts.at[k], b = cuts.at[k + 1];
    ChartLimits lim;
    if (!(a < b) || !piece_limits(t, a, b, lim)) continue;
    // Pieces longer than kMaxChunk (small N) are cut further, for the reason above.
    const int parts = std::max(1, static_cast<int>(std::ceil((b - a) / kMaxChunk)));
    for (int part = 0; part < parts; ++part)
      integrate_chart_piece(a + (b - a) * part / parts, part + 1 == parts ? b : a + (b - a) * (part + 1) / parts,
                            lim, f, acc);
  }
}

// int_a^b sqrt(1 - u^2) du = ((b c_b - a c_a) + (asin b - asin a)) / 2, each difference in a
// form without cancellation when b - a is small:
//   b c_b - a c_a = ((b - a)/2) ((c_a + c_b) - (a + b)^2 / (c_a + c_b))
//   (from c_b - c_a = (a^2 - b^2)/(c_a + c_b)), and
//   asin b - asin a = atan2(b c_a - a c_b, c_a c_b + a b)   (the angle-difference formula),
//   b c_a - a c_b = (b - a) (c_a + a (a + b) / (c_a + c_b))  (the same identity again).
// For a piece crossing u = 0 (long, small N) the sums may cancel; nothing is then small.
double half_chord_integral(double a, double b) noexcept {
  const double ca = std::sqrt((1.0 - a) * (1.0 + a)), cb = std::sqrt((1.0 - b) * (1.0 + b));
  const double sum = ca + cb;
  if (!(sum > 0)) return 0.5 * std::atan2(0.0, a * b);  // a, b = +-1: pi/2 from -1 to 1, else 0
  const double product_difference = 0.5 * (b - a) * (sum - (a + b) * (a + b) / sum);
  const double angle_difference = std::atan2((b - a) * (ca + a * (a + b) / sum), ca * cb + a * b);
  return 0.5 * (product_difference + angle_difference);
}

// Area of the square inside the unit disc, in closed form: on each piece between kinks the
// height is (v1 or c(u)) - (v0 or -c(u)).
double disc_square_area(const TexelSquare& t) noexcept {
  const Cuts cuts = kink_cuts(t);
  double area = 0;
  for (int k = 0; k + 1 < cuts.count; ++k) {
    const double a = cuts.at[k], b = cuts.at[k + 1];
    ChartLimits lim;
    if (!(a < b) || !piece_limits(t, a, b, lim)) continue;
    const double chord = half_chord_integral(a, b);
    area += (lim.hi_active ? t.v1 * (b - a) : chord) - (lim.lo_active ? t.v0 * (b - a) : -chord);
  }
  return area;
}

enum class Place : std::uint8_t { Outside, Inside, Rim };

// Where the square lies, and (inside) the distance from its farthest corner to the rim.
Place place_of(const TexelSquare& t, double& rim_gap) noexcept {
  const double nu = std::clamp(0.0, t.u0, t.u1), nv = std::clamp(0.0, t.v0, t.v1);
  if (nu * nu + nv * nv >= 1.0) return Place::Outside;
  const double fu = std::fmax(std::fabs(t.u0), std::fabs(t.u1)), fv = std::fmax(std::fabs(t.v0), std::fabs(t.v1));
  const double far_sq = fu * fu + fv * fv;
  if (far_sq >= 1.0) return Place::Rim;
  rim_gap = 1.0 - std::sqrt(far_sq);
  return Place::Inside;
}

}  // namespace

SphereMoments angular_texel_moments(const TexelSquare& t) noexcept {
  SphereMoments acc{};
  double rim_gap = 0;
  const AngularIntegrand f;
  switch (place_of(t, rim_gap)) {
    case Place::Outside: break;
    case Place::Inside:
      integrate_square(t, std::max(gauss_order_for_type(t.h, AngularIntegrand::kType), AngularIntegrand::kMinOrder), f, acc);
      break;
    case Place::Rim: integrate_chart(t, f, acc); break;
  }
  return acc;
}

SphereMoments mirror_ball_texel_moments(const TexelSquare& t) noexcept {
  SphereMoments acc{};
  double rim_gap = 0;
  const MirrorBallIntegrand f;
  const Place place = place_of(t, rim_gap);
  if (place == Place::Outside) return acc;
  if (place == Place::Inside && rim_gap >= t.h) {
    const int q = gauss_order_for_ellipse(ellipse_for_real_gap(rim_gap, 0.5 * t.h));
    integrate_square(t, std::max(q, MirrorBallIntegrand::kMinOrder), f, acc);
  } else {
    integrate_chart(t, f, acc);
  }
  acc[0] = 4.0 * disc_square_area(t);  // dw = 4 du dv: the closed form
  return acc;
}

}  // namespace shpack::detail
