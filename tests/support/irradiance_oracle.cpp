#include "support/irradiance_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "support/equirect_oracle.h"
#include "support/gauss_legendre.h"

namespace shpack_test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

// max sin over [t0, t1] within [0, pi].
double max_sin(double t0, double t1) {
  if (t0 <= 0.5 * kPi && t1 >= 0.5 * kPi) return 1.0;
  return std::max(std::sin(t0), std::sin(t1));
}

double patch_radius(double t0, double t1, double l0, double l1) {
  // Plus a few ulp for the rounding of n.w_c.
  return 0.5 * (t1 - t0) + max_sin(t0, t1) * 0.5 * (l1 - l0) + 8 * kU;
}

// Integrals of sin^2 theta, sin theta cos theta over [t0, t1] and of cos lon, sin lon over
// [l0, l1] by Gauss-Legendre (frequency 2 in theta, 1 in lon).
struct ThetaInts {
  double sin2, sincos, sin1;
};
ThetaInts theta_integrals(double t0, double t1, int q) {
  const GaussRule r = gauss_legendre(q);
  const double mid = 0.5 * (t0 + t1), half = 0.5 * (t1 - t0);
  ThetaInts out{0, 0, 0};
  for (int k = 0; k < q; ++k) {
    const double t = mid + half * r.nodes[k], w = half * r.weights[k];
    const double s = std::sin(t), c = std::cos(t);
    out.sin2 += w * s * s;
    out.sincos += w * s * c;
    out.sin1 += w * s;
  }
  return out;
}
struct LonInts {
  double cos1, sin1;
};
LonInts lon_integrals(double l0, double l1, int q) {
  const GaussRule r = gauss_legendre(q);
  const double mid = 0.5 * (l0 + l1), half = 0.5 * (l1 - l0);
  LonInts out{0, 0};
  for (int k = 0; k < q; ++k) {
    const double l = mid + half * r.nodes[k], w = half * r.weights[k];
    out.cos1 += w * std::cos(l);
    out.sin1 += w * std::sin(l);
  }
  return out;
}

}  // namespace

IrradianceOracle::IrradianceOracle(const RgbImage& image, int max_depth)
    : image_(image), max_depth_(max_depth) {
  const std::uint32_t W = image.width, H = image.height;
  dlon_ = 2.0 * kPi / W;
  for (int d = 0; d <= max_depth; ++d) {
    const double scale = std::ldexp(1.0, -d);
    theta_order_.push_back(gl_order_for(kPi / H * scale, 2.0, kOracleQuadratureTarget));
    lon_order_.push_back(gl_order_for(dlon_ * scale, 1.0, kOracleQuadratureTarget));
  }
  for (std::uint32_t j = 0; j < H; ++j) {
    const Patch p = texel_patch(0, j, W, H);
    const ThetaInts t = theta_integrals(p.theta0, p.theta1, theta_order_[0]);
    Row row{};
    row.theta0 = p.theta0;
    row.theta1 = p.theta1;
    const double tc = 0.5 * (p.theta0 + p.theta1);
    row.sin_c = std::sin(tc);
    row.cos_c = std::cos(tc);
    row.radius = patch_radius(p.theta0, p.theta1, p.lon0, p.lon1);
    row.int_sin2 = t.sin2;
    row.int_sincos = t.sincos;
    row.omega = t.sin1 * dlon_;
    for (std::uint32_t i = 0; i < W; ++i)
      for (int c = 0; c < 3; ++c) row.abs_sum[c] += std::fabs(static_cast<double>(image.at(i, j, c)));
    rows_.push_back(row);
  }
  for (std::uint32_t i = 0; i < W; ++i) {
    const Patch p = texel_patch(i, 0, W, H);
    const LonInts l = lon_integrals(p.lon0, p.lon1, lon_order_[0]);
    const double lc = 0.5 * (p.lon0 + p.lon1);
    columns_.push_back({p.lon0, p.lon1, std::cos(lc), std::sin(lc), l.cos1, l.sin1});
  }
}

void IrradianceOracle::integrate_cut(double t0, double t1, double l0, double l1, int depth,
                                     const shpack::Dir3& n, double& estimate,
                                     double& bound) const {
  const double tc = 0.5 * (t0 + t1), lc = 0.5 * (l0 + l1);
  const double s = std::sin(tc);
  const double c = n.x * s * std::cos(lc) + n.y * std::cos(tc) + n.z * s * std::sin(lc);
  const double r = patch_radius(t0, t1, l0, l1);
  if (c <= -r) return;
  if (c >= r) {  // smooth: n . int w dw
    const ThetaInts t = theta_integrals(t0, t1, theta_order_[depth]);
    const LonInts l = lon_integrals(l0, l1, lon_order_[depth]);
    estimate += n.x * t.sin2 * l.cos1 + n.y * t.sincos * (l1 - l0) + n.z * t.sin2 * l.sin1;
    return;
  }
  if (depth == max_depth_) {
    // Cut leaf: Gauss-Legendre of max(0, n.w); true value and estimate in [0, (c + r) Omega].
    const GaussRule rt = gauss_legendre(theta_order_[depth]);
    const GaussRule rl = gauss_legendre(lon_order_[depth]);
    const double tm = 0.5 * (t0 + t1), th = 0.5 * (t1 - t0);
    const double lm = 0.5 * (l0 + l1), lh = 0.5 * (l1 - l0);
    double sum = 0.0, omega = 0.0;
    for (std::size_t a = 0; a < rt.nodes.size(); ++a) {
      const double t = tm + th * rt.nodes[a];
      const double st = std::sin(t), ct = std::cos(t);
      for (std::size_t b = 0; b < rl.nodes.size(); ++b) {
        const double l = lm + lh * rl.nodes[b];
        const double w = th * rt.weights[a] * st * lh * rl.weights[b];
        const double dot = n.x * st * std::cos(l) + n.y * ct + n.z * st * std::sin(l);
        sum += w * std::max(0.0, dot);
        omega += w;
      }
    }
    estimate += sum;
    bound += (c + r) * omega * (1.0 + 1e-12);
    return;
  }
  const double tm = 0.5 * (t0 + t1), lm = 0.5 * (l0 + l1);
  integrate_cut(t0, tm, l0, lm, depth + 1, n, estimate, bound);
  integrate_cut(t0, tm, lm, l1, depth + 1, n, estimate, bound);
  integrate_cut(tm, t1, l0, lm, depth + 1, n, estimate, bound);
  integrate_cut(tm, t1, lm, l1, depth + 1, n, estimate, bound);
}

IrradianceEstimate IrradianceOracle::eval(const shpack::Dir3& n) const {
  const std::uint32_t W = image_.width, H = image_.height;
  long double total[3] = {}, cut_bound[3] = {}, abs_total[3] = {};
  for (std::uint32_t j = 0; j < H; ++j) {
    const Row& row = rows_[j];
    double sum[3] = {}, bnd[3] = {};
    for (std::uint32_t i = 0; i < W; ++i) {
      const Column& col = columns_[i];
      const double c = n.x * row.sin_c * col.cos_c + n.y * row.cos_c + n.z * row.sin_c * col.sin_c;
      double value;
      if (c >= row.radius) {
        value = n.x * row.int_sin2 * col.int_cos + n.y * row.int_sincos * dlon_ +
                n.z * row.int_sin2 * col.int_sin;
        for (int ch = 0; ch < 3; ++ch) sum[ch] += static_cast<double>(image_.at(i, j, ch)) * value;
      } else if (c > -row.radius) {
        double est = 0.0, b = 0.0;
        integrate_cut(row.theta0, row.theta1, col.lon0, col.lon1, 0, n, est, b);
        for (int ch = 0; ch < 3; ++ch) {
          const double v = image_.at(i, j, ch);
          sum[ch] += v * est;
          bnd[ch] += std::fabs(v) * b;
        }
      }
    }
    for (int ch = 0; ch < 3; ++ch) {
      total[ch] += sum[ch];
      cut_bound[ch] += bnd[ch];
      abs_total[ch] += row.abs_sum[ch] * row.omega;
    }
  }
  IrradianceEstimate out;
  const double rounding = (W + 64.0) * kU;
  for (int ch = 0; ch < 3; ++ch) {
    out.e_over_pi[ch] = static_cast<double>(total[ch]) / kPi;
    out.bound[ch] = (static_cast<double>(cut_bound[ch]) + rounding * static_cast<double>(abs_total[ch])) / kPi;
  }
  return out;
}

}  // namespace shpack_test
