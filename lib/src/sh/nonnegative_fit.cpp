#include "sh/nonnegative_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shpack/sh_minimum.h"

namespace shpack {
namespace {

using Vec9 = std::array<double, kShCount>;

constexpr double kEps = std::numeric_limits<double>::epsilon();
// NNLS optimality: every column's gradient b_k . r = -(E/pi at n_k) <= kGradientTolerance
// times the RMS of the input. Rounding of b_k . r is <= 9u |b_k| |r| with |b_k| = 3
// (|b(n)|^2 = sum_i P_i^2 / w_i = 4 pi sum_i Y_i^2 = 9) and |r| = |u| <= |u0| = the RMS:
// 3e-15 of it; 1e-13 is 30 times that and 1e4 times below kFitTolerance, so a plane the
// oracle brings in is never one already satisfied.
constexpr double kGradientTolerance = 1e-13;
// A column whose part orthogonal to the passive columns is below this fraction of its
// length is taken as dependent on them (Householder QR, below).
constexpr double kRankTolerance = 64 * kEps;
// Lawson-Hanson terminates in exact arithmetic; this caps what rounding could add.
constexpr int kMaxNnlsSteps = 4 * kMaxFitPlanes;

double sqrt_weight(int i) noexcept { return kY0 / kBasisScale[i]; }  // sqrt(w_i), header

double dot(const Vec9& a, const Vec9& b) noexcept {
  double sum = 0.0;
  for (int i = 0; i < kShCount; ++i) sum += a[i] * b[i];
  return sum;
}

// min_{x >= 0} ||d - sum_k x_k b_k|| over `columns` columns b_k [Lawson & Hanson ch. 23].
struct Nnls {
  Vec9 d{};
  double gradient_tolerance = 0;
  int columns = 0;
  std::array<Vec9, kMaxFitPlanes> b{};
  std::array<double, kMaxFitPlanes> x{};
  std::array<bool, kMaxFitPlanes> passive{};

  Vec9 residual() const noexcept {
    Vec9 r = d;
    for (int k = 0; k < columns; ++k)
      for (int i = 0; i < kShCount; ++i) r[i] -= x[k] * b[k][i];
    return r;
  }
};

// The unconstrained least-squares z on the passive columns, by Householder QR (Golub & Van
// Loan, "Matrix Computations", 4th ed., sec. 5.3.2): false when a passive column is within
// kRankTolerance of the span of those before it (at most 9 can be independent).
bool passive_least_squares(const Nnls& q, std::array<double, kMaxFitPlanes>& z) noexcept {
  std::array<int, kShCount + 1> index{};
  int p = 0;
  for (int k = 0; k < q.columns; ++k) {
    if (!q.passive[k]) continue;
    if (p == kShCount) return false;
    index[p++] = k;
  }
  std::array<Vec9, kShCount> a{};  // a[j] = column j, reduced in place to R's column j
  for (int j = 0; j < p; ++j) a[j] = q.b[index[j]];
  Vec9 rhs = q.d;
  for (int j = 0; j < p; ++j) {
    double tail = 0.0;
    for (int i = j; i < kShCount; ++i) tail += a[j][i] * a[j][i];
    const double norm = std::sqrt(tail);
    if (!(norm > kRankTolerance * std::sqrt(dot(q.b[index[j]], q.b[index[j]])))) return false;
    // v = a_j[j:] - alpha e_j with alpha = -sign(a_jj) |a_j[j:]|: no cancellation in v_j.
    const double alpha = -std::copysign(norm, a[j][j]);
    Vec9 v{};
    for (int i = j; i < kShCount; ++i) v[i] = a[j][i];
    v[j] -= alpha;
    const double v2 = tail - a[j][j] * a[j][j] + v[j] * v[j];
    auto reflect = [&](Vec9& col) {
      double f = 0.0;
      for (int i = j; i < kShCount; ++i) f += v[i] * col[i];
      f *= 2.0 / v2;
      for (int i = j; i < kShCount; ++i) col[i] -= f * v[i];
    };
    for (int c = j + 1; c < p; ++c) reflect(a[c]);
    reflect(rhs);
    a[j][j] = alpha;
  }
  for (int j = p - 1; j >= 0; --j) {  // R z = (Q^T d)[0:p]
    double sum = rhs[j];
    for (int c = j + 1; c < p; ++c) sum -= a[c][j] * z[index[c]];
    z[index[j]] = sum / a[j][j];
  }
  return true;
}

// Lawson-Hanson from the current x (>= 0, optimal on its passive set). True when no column
// has a gradient above q.gradient_tolerance; false when rounding stopped it first (a column
// that cannot enter, or the step cap), x then still >= 0.
bool solve_nnls(Nnls& q) noexcept {
  std::array<double, kMaxFitPlanes> z{};
  for (int step = 0; step < kMaxNnlsSteps; ++step) {
    const Vec9 r = q.residual();
    int entering = -1;
    double best = q.gradient_tolerance;
    for (int k = 0; k < q.columns; ++k) {
      const double g = q.passive[k] ? 0.0 : dot(q.b[k], r);
      if (g > best) {
        best = g;
        entering = k;
      }
    }
    if (entering < 0) return true;
    q.passive[entering] = true;
    for (int inner = 0;; ++inner) {
      // In exact arithmetic the entering column is independent of the passive ones and
      // gets z > 0 (Lawson & Hanson, Lemma 23.17); if rounding says otherwise it stays out.
      if (!passive_least_squares(q, z) || (inner == 0 && !(z[entering] > 0.0))) {
        if (inner == 0) q.passive[entering] = false;
        return false;
      }
      // Step from x towards z until the first passive x_k reaches 0.
      double alpha = 1.0;
      int leaving = -1;
      for (int k = 0; k < q.columns; ++k) {
        if (!q.passive[k] || z[k] > 0.0) continue;
        const double reach = q.x[k] / (q.x[k] - z[k]);  // in [0, 1]: x_k >= 0 >= z_k
        if (reach < alpha) {
          alpha = reach;
          leaving = k;
        }
      }
      for (int k = 0; k < q.columns; ++k)
        if (q.passive[k]) q.x[k] = leaving < 0 ? z[k] : q.x[k] + alpha * (z[k] - q.x[k]);
      if (leaving < 0) break;
      for (int k = 0; k < q.columns; ++k) {
        if (!q.passive[k] || (k != leaving && q.x[k] > 0.0)) continue;
        q.passive[k] = false;
        q.x[k] = 0.0;
      }
      if (inner >= kShCount) return false;  // each inner step removes a column: cannot recur
    }
  }
  return false;
}

// Coefficient 0 of channel 0 raised until its exact minimum is >= 0: by the deficit, then
// (when rounding of the minimum leaves it just below 0) by 2^k eps max |s_i| more, which ends
// within a few steps because a constant c raises E/pi by c everywhere. A deficit above
// `limit` is not taken (nor a NaN): the caller's bound on what is left to correct.
double raise_to_nonnegative(ShL2& sh, double limit) noexcept {
  double largest = 0.0;
  for (const double s : sh.c[0]) largest = std::max(largest, std::fabs(s));
  const double start = sh.c[0][0];
  double extra = kEps * largest;
  for (int k = 0; k < 64; ++k, extra *= 2.0) {
    const double low = minimum_on_sphere(sh, 0).value;
    if (!(low < 0.0) || -low > limit) break;
    sh.c[0][0] += k == 0 ? -low : std::max(-low, extra);
  }
  return sh.c[0][0] - start;
}

}  // namespace

NonnegativeFit nearest_nonnegative(const ShL2& unity_form, int channel) noexcept {
  // Scaled by 2^-e, max |t_i| 2^-e in [0.5, 1): exact both ways, so the result's E/pi is
  // exactly 2^e times the scaled one's everywhere, and sh_minimum.h, whose squares would
  // over- or underflow beyond about 1e+-150, works on numbers near 1.
  double largest = 0.0;
  for (const double s : unity_form.c[channel]) largest = std::max(largest, std::fabs(s));
  int e = 0;
  std::frexp(largest, &e);
  Nnls q;
  Vec9 u0{};
  for (int i = 0; i < kShCount; ++i) {
    u0[i] = sqrt_weight(i) * std::ldexp(unity_form.c[channel][i], -e);
    q.d[i] = -u0[i];
  }
  const double rms = std::sqrt(dot(u0, u0));  // of the scaled input: in [0.12, 1.9]
  q.gradient_tolerance = kGradientTolerance * rms;

  NonnegativeFit fit;
  ShL2 scaled;  // channel 0: the current iterate s = u / sqrt(w), scaled
  Vec9 u = u0;
  for (bool progress = true;;) {
    for (int i = 0; i < kShCount; ++i) scaled.c[0][i] = u[i] / sqrt_weight(i);
    const SphereMinimum low = minimum_on_sphere(scaled, 0);
    if (!progress || low.value >= -kFitTolerance * rms || fit.planes == kMaxFitPlanes) break;
    const Dir3 n = low.direction;
    const Vec9 p = basis_polynomials(n.x, n.y, n.z);
    for (int i = 0; i < kShCount; ++i) q.b[q.columns][i] = p[i] / sqrt_weight(i);
    fit.directions[q.columns++] = n;
    ++fit.planes;
    progress = solve_nnls(q);
    const Vec9 r = q.residual();  // u = u0 + B^T x = -(d - B^T x)
    for (int i = 0; i < kShCount; ++i) u[i] = -r[i];
  }
  // The deficit, on the scaled numbers; then once more on the result, for sh_minimum.h's own
  // rounding, which is not exactly scale invariant where the minimum is flat (it may find
  // another point of a zero set 1 ulp lower). That second pass corrects no more than the
  // evaluation error of E/pi, 10u sum |s_i P_i| <= 180u max |s_i| (|P_i| <= 2): beyond it,
  // where the unscaled squares over- or underflow, sh_minimum.h is not believed.
  const double raise = raise_to_nonnegative(scaled, std::numeric_limits<double>::infinity());
  ShL2 out;
  double largest_out = 0.0;
  for (int i = 0; i < kShCount; ++i) {
    out.c[0][i] = std::ldexp(scaled.c[0][i], e);
    largest_out = std::max(largest_out, std::fabs(out.c[0][i]));
  }
  fit.raise = std::ldexp(raise, e) + raise_to_nonnegative(out, 128 * kEps * largest_out);
  fit.unity_form = out.c[0];
  for (int k = 0; k < q.columns; ++k) fit.multipliers[k] = std::ldexp(q.x[k], e);
  return fit;
}

NonnegativeFit nearest_nonnegative_l1(const ShL2& unity_form, int channel) noexcept {
  const std::array<double, kShCount>& t = unity_form.c[channel];
  const double length = std::hypot(t[1], t[2], t[3]);
  NonnegativeFit fit;
  const double s0 = (3 * t[0] + length) / 4;
  ShL2 result;
  result.c[0][0] = s0;
  for (int i = 1; i <= 3; ++i) result.c[0][i] = s0 * (t[i] / length);
  // Raised until the exact minimum on the sphere, as finish_projection checks it, is >= 0.
  while (minimum_on_sphere(result, 0).value < 0)
    result.c[0][0] = std::nextafter(result.c[0][0], std::numeric_limits<double>::infinity());
  fit.unity_form = result.c[0];
  fit.raise = result.c[0][0] - s0;
  return fit;
}

}  // namespace shpack
