#include "support/equirect_oracle.h"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "support/gauss_legendre.h"
#include "support/sh_oracle.h"

namespace shpack_test {
namespace {

constexpr double kPi = std::numbers::pi;

// Nodes of a 1-D rule mapped to [a, b].
struct Nodes1D {
  std::vector<double> x, w;
};
Nodes1D map_rule(double a, double b, int q) {
  const GaussRule r = gauss_legendre(q);
  Nodes1D out;
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  for (int k = 0; k < q; ++k) {
    out.x.push_back(mid + half * r.nodes[k]);
    out.w.push_back(half * r.weights[k]);
  }
  return out;
}

int theta_order(const Patch& p) {
  return gl_order_for(p.theta1 - p.theta0, kThetaFrequency, kOracleQuadratureTarget);
}
int lon_order(const Patch& p) {
  return gl_order_for(p.lon1 - p.lon0, kLonFrequency, kOracleQuadratureTarget);
}

// Calls f(dir, weight) at every node of the tensor rule on the patch; weight includes
// sin theta.
template <class F>
void for_each_node(const Patch& p, F&& f) {
  const Nodes1D th = map_rule(p.theta0, p.theta1, theta_order(p));
  const Nodes1D lo = map_rule(p.lon0, p.lon1, lon_order(p));
  for (std::size_t a = 0; a < th.x.size(); ++a) {
    const double s = std::sin(th.x[a]), c = std::cos(th.x[a]);
    for (std::size_t b = 0; b < lo.x.size(); ++b) {
      const shpack::Dir3 d{s * std::cos(lo.x[b]), c, s * std::sin(lo.x[b])};
      f(d, th.w[a] * s * lo.w[b]);
    }
  }
}

}  // namespace

Patch texel_patch(std::uint32_t i, std::uint32_t j, std::uint32_t width, std::uint32_t height) {
  const double w = width, h = height;
  return {kPi * j / h, kPi * (j + 1.0) / h, (0.5 - (i + 1.0) / w) * 2.0 * kPi,
          (0.5 - i / w) * 2.0 * kPi};
}

shpack::Dir3 direction_of(double theta, double lon) {
  return {std::sin(theta) * std::cos(lon), std::cos(theta), std::sin(theta) * std::sin(lon)};
}

double patch_solid_angle(const Patch& p) {
  double sum = 0.0;
  for_each_node(p, [&](const shpack::Dir3&, double w) { sum += w; });
  return sum;
}

std::array<double, 9> patch_basis_integral(const Patch& p) {
  std::array<double, 9> sum{};
  for_each_node(p, [&](const shpack::Dir3& d, double w) {
    const std::array<double, 9> y = unity_basis_slow(d.x, d.y, d.z);
    for (int i = 0; i < 9; ++i) sum[i] += w * y[i];
  });
  return sum;
}

std::array<double, 9> texel_basis_integral(std::uint32_t i, std::uint32_t j, std::uint32_t width,
                                           std::uint32_t height) {
  return patch_basis_integral(texel_patch(i, j, width, height));
}

shpack::ShL2 project_oracle(const RgbImage& image) {
  const std::uint32_t W = image.width, H = image.height;
  // All texels of a row share the theta nodes, all texels of a column the lon nodes.
  const Patch p0 = texel_patch(0, 0, W, H);
  const int qt = theta_order(p0), ql = lon_order(p0);
  std::vector<double> col_cos(std::size_t{W} * ql), col_sin(std::size_t{W} * ql),
      col_w(std::size_t{W} * ql);
  for (std::uint32_t i = 0; i < W; ++i) {
    const Patch p = texel_patch(i, 0, W, H);
    const Nodes1D lo = map_rule(p.lon0, p.lon1, ql);
    for (int b = 0; b < ql; ++b) {
      col_cos[std::size_t{i} * ql + b] = std::cos(lo.x[b]);
      col_sin[std::size_t{i} * ql + b] = std::sin(lo.x[b]);
      col_w[std::size_t{i} * ql + b] = lo.w[b];
    }
  }
  long double total[3][9] = {};
  for (std::uint32_t j = 0; j < H; ++j) {
    const Patch pr = texel_patch(0, j, W, H);
    const Nodes1D th = map_rule(pr.theta0, pr.theta1, qt);
    long double row[3][9] = {};
    for (std::uint32_t i = 0; i < W; ++i) {
      const float r = image.at(i, j, 0), g = image.at(i, j, 1), b = image.at(i, j, 2);
      if (r == 0.0f && g == 0.0f && b == 0.0f) continue;  // contributes exactly 0
      double integral[9] = {};
      for (int a = 0; a < qt; ++a) {
        const double s = std::sin(th.x[a]), c = std::cos(th.x[a]);
        for (int k = 0; k < ql; ++k) {
          const std::size_t n = std::size_t{i} * ql + k;
          const std::array<double, 9> y = unity_basis_slow(s * col_cos[n], c, s * col_sin[n]);
          const double w = th.w[a] * s * col_w[n];
          for (int q = 0; q < 9; ++q) integral[q] += w * y[q];
        }
      }
      const double v[3] = {r, g, b};
      for (int ch = 0; ch < 3; ++ch)
        for (int q = 0; q < 9; ++q) row[ch][q] += static_cast<long double>(v[ch]) * integral[q];
    }
    for (int ch = 0; ch < 3; ++ch)
      for (int q = 0; q < 9; ++q) total[ch][q] += row[ch][q];
  }
  shpack::ShL2 out;
  for (int ch = 0; ch < 3; ++ch)
    for (int q = 0; q < 9; ++q) out.c[ch][q] = static_cast<double>(total[ch][q]);
  return out;
}

namespace {
template <class F>
std::array<double, 3> sum_over_texels(const RgbImage& image, F&& term) {
  std::vector<double> row_omega(image.height);
  for (std::uint32_t j = 0; j < image.height; ++j)
    row_omega[j] = patch_solid_angle(texel_patch(0, j, image.width, image.height));
  long double sum[3] = {};
  for (std::uint32_t j = 0; j < image.height; ++j)
    for (std::uint32_t i = 0; i < image.width; ++i)
      for (int c = 0; c < 3; ++c) sum[c] += term(static_cast<double>(image.at(i, j, c))) * row_omega[j];
  return {static_cast<double>(sum[0]), static_cast<double>(sum[1]), static_cast<double>(sum[2])};
}
}  // namespace

std::array<double, 3> abs_radiance_integral(const RgbImage& image) {
  return sum_over_texels(image, [](double v) { return std::fabs(v); });
}

std::array<double, 3> radiance_energy(const RgbImage& image) {
  return sum_over_texels(image, [](double v) { return v * v; });
}

RgbImage render_texel_averages(std::uint32_t width, std::uint32_t height, const RadianceFunction& f) {
  RgbImage img(width, height);
  for (std::uint32_t j = 0; j < height; ++j)
    for (std::uint32_t i = 0; i < width; ++i) {
      const Patch p = texel_patch(i, j, width, height);
      double sum[3] = {}, omega = 0.0;
      for_each_node(p, [&](const shpack::Dir3& d, double w) {
        const std::array<double, 3> v = f(d);
        for (int c = 0; c < 3; ++c) sum[c] += w * v[c];
        omega += w;
      });
      img.set(i, j, static_cast<float>(sum[0] / omega), static_cast<float>(sum[1] / omega),
              static_cast<float>(sum[2] / omega));
    }
  return img;
}

RgbImage render_texel_centres(std::uint32_t width, std::uint32_t height, const RadianceFunction& f) {
  RgbImage img(width, height);
  for (std::uint32_t j = 0; j < height; ++j)
    for (std::uint32_t i = 0; i < width; ++i) {
      const Patch p = texel_patch(i, j, width, height);
      const std::array<double, 3> v =
          f(direction_of(0.5 * (p.theta0 + p.theta1), 0.5 * (p.lon0 + p.lon1)));
      img.set(i, j, static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
    }
  return img;
}

}  // namespace shpack_test
