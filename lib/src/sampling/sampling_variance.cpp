// sample_variance (sampling_variance.h): E[X^2] = sum_t w_t L_t^2 int_t Y_i^2 dw, minus L_i^2.
//
// Texel integrals of P_i^2 (Y_i = k_i P_i, sh_basis.h). With x = s cos lon, y = mu,
// z = s sin lon, s^2 = 1 - mu^2 and dw = dmu dlon (conventions.h), each P_i^2 is a sum of
// (polynomial in mu) x (trigonometric polynomial in lon):
//   P0^2 = 1            P1^2 = mu^2             P2^2 = s^2 sin^2      P3^2 = s^2 cos^2
//   P4^2 = s^2 mu^2 cos^2                       P5^2 = s^2 mu^2 sin^2
//   P6^2 = 9 s^4 sin^4 - 6 s^2 sin^2 + 1        P7^2 = s^4 cos^2 sin^2
//   P8^2 = s^4 cos^4 - 2 s^2 mu^2 cos^2 + mu^4
// Over row j the mu factors are combinations of m_k = int mu^k dmu over [mu1, mu0]
// (k <= 4, exact). Over a column of width D centred on lon_m, int cos(k lon) =
// (2/k) sin(k D/2) cos(k lon_m), and cos^2 = (1 + cos 2)/2, sin^2 = (1 - cos 2)/2,
// cos^4 = 3/8 + cos 2/2 + cos 4/8, sin^4 = 3/8 - cos 2/2 + cos 4/8,
// cos^2 sin^2 = 1/8 - cos 4/8. So a row needs three column sums of v_t = w_t L_t^2:
// S0 = sum v, A = sum v cos 2lon_m, B = sum v cos 4lon_m.
#include "shpack/sampling_variance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <new>
#include <vector>

#include "common/accumulate.h"
#include "common/angles.h"
#include "projection/equirect_weights.h"
#include "projection/row_kernel.h"
#include "sampling/importance_density.h"
#include "shpack/sampling_methods.h"

namespace shpack {
namespace {

using detail::NeumaierSum;

// int f(mu) dmu over row j for the mu factors above. mu0 - mu1 = 2 sin(theta_c) sin(h)
// (no cancellation at the poles), mu0^(k+1) - mu1^(k+1) = (mu0 - mu1) sum_a mu0^a mu1^(k-a).
struct RowMoments {
  double one, mu2, mu4, s2, s2mu2, s4;
};
RowMoments row_moments(std::uint32_t j, std::uint32_t height) noexcept {
  const double h = 0.5 * kPi / height, theta_c = kPi * (j + 0.5) / height;
  const double mu0 = std::cos(kPi * j / height), mu1 = std::cos(kPi * (j + 1.0) / height);
  const double d = 2.0 * std::sin(theta_c) * std::sin(h);
  const double m0 = d;
  const double m2 = d * (mu0 * mu0 + mu0 * mu1 + mu1 * mu1) / 3.0;
  const double m4 = d * (mu0 * mu0 * mu0 * mu0 + mu0 * mu0 * mu0 * mu1 + mu0 * mu0 * mu1 * mu1 +
                         mu0 * mu1 * mu1 * mu1 + mu1 * mu1 * mu1 * mu1) / 5.0;
  return {m0, m2, m4, m0 - m2, m2 - m4, m0 - 2.0 * m2 + m4};
}

// Column sums of v over a row, then its longitude integrals (header comment).
struct RowSums {
  double s0 = 0, a = 0, b = 0;
};
struct LonIntegrals {
  double one, cos2, sin2, cos4, sin4, cos2sin2;
};
LonIntegrals lon_integrals(const RowSums& r, std::uint32_t width) noexcept {
  const double dlon = 2.0 * kPi / width;
  const double a = 0.5 * std::sin(dlon) * r.a;        // (2/2) sin(D) / 2, times A
  const double b = 0.0625 * std::sin(2.0 * dlon) * r.b;  // (2/4) sin(2D) / 8, times B
  return {dlon * r.s0,          0.5 * dlon * r.s0 + a,     0.5 * dlon * r.s0 - a,
          0.375 * dlon * r.s0 + a + b, 0.375 * dlon * r.s0 - a + b, 0.125 * dlon * r.s0 - b};
}

// sum over the row of v_t int_t P_i^2, for each i (the table of the header comment).
std::array<double, kShCount> row_square_integrals(const RowMoments& m, const LonIntegrals& f) noexcept {
  return {m.one * f.one,
          m.mu2 * f.one,
          m.s2 * f.sin2,
          m.s2 * f.cos2,
          m.s2mu2 * f.cos2,
          m.s2mu2 * f.sin2,
          9.0 * m.s4 * f.sin4 - 6.0 * m.s2 * f.sin2 + m.one * f.one,
          m.s4 * f.cos2sin2,
          m.s4 * f.cos4 - 2.0 * m.s2mu2 * f.cos2 + m.mu4 * f.one};
}

// The texel weights w_t = Omega_t / P_t: 4 pi, or for is the sampler's Q / d_t.
struct TexelWeight {
  bool importance = false;
  double mean = 0;  // is: sum_t max(lum_t, 0) Omega_t / (4 pi)
  double operator()(const std::array<double, 3>& rgb) const noexcept {
    if (!importance || !(mean > 0.0)) return 4.0 * kPi;
    const double d = std::max(detail::luminance(rgb), 0.0) + kImportanceFloor * mean;
    return (1.0 + kImportanceFloor) * 4.0 * kPi * mean / d;
  }
};

// One pass over the rows, f(y, rgb of each texel) through the value policies.
template <class F>
Status for_each_texel(const ImageView& image, const ProjectOptions& options, std::vector<float>& planes,
                      F&& f) noexcept {
  detail::TexelCounts counts;
  const std::uint32_t w = image.width;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    if (Status st = detail::load_image_row(image, y, options, planes, counts); !st.ok()) return st;
    for (std::uint32_t x = 0; x < w; ++x)
      f(x, y, std::array<double, 3>{planes[x], planes[w + x], planes[2 * std::size_t{w} + x]});
  }
  return Status::success();
}

}  // namespace

Status sample_variance(const ImageView& image, SamplingMethod method, const ProjectOptions& options,
                       ShL2& variance) noexcept {
  if (method != SamplingMethod::MonteCarlo && method != SamplingMethod::Importance)
    return Status::error(Errc::InvalidArgument, "a closed-form variance exists for mc and is only");
  ImageView view = image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  ShL2 exact;
  if (Status st = project_with_method(view, MethodSpec{}, options, exact); !st.ok()) return st;
  std::vector<float> planes;
  std::vector<detail::ColumnTrig> columns;
  try {
    planes.resize(std::size_t{3} * view.width);
    for (std::uint32_t x = 0; x < view.width; ++x) columns.push_back(detail::column_trig(x, view.width));
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate a row for the variance");
  }

  TexelWeight weight{method == SamplingMethod::Importance, 0.0};
  if (weight.importance) {  // the sampler's mean luminance (sampling_importance.cpp)
    NeumaierSum lum;
    double row_omega = 0;
    const Status st = for_each_texel(view, options, planes, [&](std::uint32_t x, std::uint32_t y, const std::array<double, 3>& rgb) {
      if (x == 0) row_omega = detail::exact_row_weights(y, view.height, view.width).k0;
      lum.add(std::max(detail::luminance(rgb), 0.0) * row_omega);
    });
    if (!st.ok()) return st;
    weight.mean = lum.value() / (4.0 * kPi);
  }

  NeumaierSum second[kChannelCount][kShCount];
  RowSums row[kChannelCount];
  auto finish_row = [&](std::uint32_t y) noexcept {
    const RowMoments m = row_moments(y, view.height);
    for (int c = 0; c < kChannelCount; ++c) {
      const std::array<double, kShCount> r = row_square_integrals(m, lon_integrals(row[c], view.width));
      for (int i = 0; i < kShCount; ++i) second[c][i].add(r[i]);
      row[c] = {};
    }
  };
  const Status st = for_each_texel(view, options, planes, [&](std::uint32_t x, std::uint32_t y, const std::array<double, 3>& rgb) {
    const double w = weight(rgb);
    // cos 4 lon = 2 cos^2 2lon - 1, from the column's cos 2lon.
    const double cos2 = columns[x].cos2, cos4 = 2.0 * cos2 * cos2 - 1.0;
    for (int c = 0; c < kChannelCount; ++c) {
      const double v = w * rgb[c] * rgb[c];
      row[c].s0 += v;
      row[c].a += v * cos2;
      row[c].b += v * cos4;
    }
    if (x + 1 == view.width) finish_row(y);
  });
  if (!st.ok()) return st;
  for (int c = 0; c < kChannelCount; ++c) {
    for (int i = 0; i < kShCount; ++i) {
      const double k2 = kBasisScale[i] * kBasisScale[i];
      variance.c[c][i] = std::max(0.0, k2 * second[c][i].value() - exact.c[c][i] * exact.c[c][i]);
    }
  }
  return Status::success();
}

}  // namespace shpack
