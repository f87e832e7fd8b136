#include "shpack/colorspace.h"

#include <cmath>
#include <utility>

namespace shpack {
namespace {

constexpr Chromaticities kRec709 = {0.64, 0.33, 0.30, 0.60, 0.15, 0.06, 0.3127, 0.3290};
constexpr Chromaticities kAp1 = {0.713, 0.293, 0.165, 0.830, 0.128, 0.044, 0.32168, 0.33767};
constexpr Chromaticities kAp0 = {0.7347, 0.2653, 0.0, 1.0, 0.0001, -0.0770, 0.32168, 0.33767};
constexpr Chromaticities kP3D65 = {0.680, 0.320, 0.265, 0.690, 0.150, 0.060, 0.3127, 0.3290};
constexpr Chromaticities kRec2020 = {0.708, 0.292, 0.170, 0.797, 0.131, 0.046, 0.3127, 0.3290};

constexpr Matrix3 kBradford = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};

using Array3 = std::array<double, 3>;

Array3 xyz_of(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

Matrix3 multiply(const Matrix3& a, const Matrix3& b) {
  Matrix3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) m[i][j] += a[i][k] * b[k][j];
  return m;
}

Array3 transformed(const Matrix3& m, const Array3& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

// Inverse by the adjugate; false if singular (relative to the entries' scale).
bool invert(const Matrix3& m, Matrix3& out) {
  const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2],
               c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  double scale = 0;
  for (const auto& row : m)
    for (double v : row) scale = std::fmax(scale, std::fabs(v));
  if (!(std::fabs(det) > 1e-12 * scale * scale * scale)) return false;
  out = {{{c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det, (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det},
          {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det, (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det},
          {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det, (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det}}};
  return true;
}

// RGB -> XYZ (SMPTE RP 177): the primaries' XYZ (Y = 1) as columns, scaled so that
// R = G = B = 1 is the white.
bool rgb_to_xyz(const Chromaticities& c, Matrix3& m) {
  for (int k = 1; k < 8; k += 2)
    if (!(c[k] != 0 && std::isfinite(c[k]) && std::isfinite(c[k - 1]))) return false;
  const Array3 r = xyz_of(c[0], c[1]), g = xyz_of(c[2], c[3]), b = xyz_of(c[4], c[5]);
  const Matrix3 p = {{{r[0], g[0], b[0]}, {r[1], g[1], b[1]}, {r[2], g[2], b[2]}}};
  Matrix3 p_inverse;
  if (!invert(p, p_inverse)) return false;
  const Array3 s = transformed(p_inverse, xyz_of(c[6], c[7]));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = p[i][j] * s[j];
  return true;
}

}  // namespace

const char* colorspace_name(ColorSpace space) noexcept {
  switch (space) {
    case ColorSpace::Auto: return "auto";
    case ColorSpace::LinearRec709: return "linear-rec709";
    case ColorSpace::AcesCg: return "acescg";
    case ColorSpace::Aces2065_1: return "aces2065-1";
    case ColorSpace::LinearP3D65: return "linear-p3-d65";
    case ColorSpace::LinearRec2020: return "linear-rec2020";
  }
  return "unknown";
}

Chromaticities colorspace_chromaticities(ColorSpace space) noexcept {
  switch (space) {
    case ColorSpace::AcesCg: return kAp1;
    case ColorSpace::Aces2065_1: return kAp0;
    case ColorSpace::LinearP3D65: return kP3D65;
    case ColorSpace::LinearRec2020: return kRec2020;
    case ColorSpace::Auto:
    case ColorSpace::LinearRec709: break;
  }
  return kRec709;
}

ColorSpace named_colorspace(const Chromaticities& c) noexcept {
  for (const ColorSpace s : {ColorSpace::LinearRec709, ColorSpace::AcesCg, ColorSpace::Aces2065_1,
                             ColorSpace::LinearP3D65, ColorSpace::LinearRec2020}) {
    const Chromaticities k = colorspace_chromaticities(s);
    bool same = true;
    for (int i = 0; i < 8; ++i) same = same && std::fabs(c[i] - k[i]) <= 1e-4;
    if (same) return s;
  }
  return ColorSpace::Auto;
}

bool rgb_to_rec709_matrix(const Chromaticities& c, Matrix3& out, std::string& problem) {
  Matrix3 src, dst, dst_inverse, bradford_inverse;
  if (!rgb_to_xyz(c, src)) {
    problem = "its chromaticities do not define three independent primaries and a white";
    return false;
  }
  (void)rgb_to_xyz(kRec709, dst);
  (void)invert(dst, dst_inverse);
  (void)invert(kBradford, bradford_inverse);
  // Bradford from the source white to D65, in the cone-like space of the Bradford matrix.
  const Array3 w_src = transformed(kBradford, xyz_of(c[6], c[7]));
  const Array3 w_dst = transformed(kBradford, xyz_of(kRec709[6], kRec709[7]));
  Matrix3 scale{};
  for (int i = 0; i < 3; ++i) scale[i][i] = w_dst[i] / w_src[i];
  const Matrix3 adapt = multiply(bradford_inverse, multiply(scale, kBradford));
  out = multiply(dst_inverse, multiply(adapt, src));
  return true;
}

ShL2 mix_channels(const ShL2& sh, const Matrix3& m) noexcept {
  ShL2 out;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i)
      out.c[c][i] = m[c][0] * sh.c[0][i] + m[c][1] * sh.c[1][i] + m[c][2] * sh.c[2][i];
  return out;
}

bool resolve_colorspace(ColorSpace requested, const std::optional<Chromaticities>& file, ColourResolution& out,
                        std::string& problem) {
  Chromaticities chromaticities = colorspace_chromaticities(ColorSpace::LinearRec709);
  ColourResolution result;
  if (requested != ColorSpace::Auto) {
    chromaticities = colorspace_chromaticities(requested);
    result.name = colorspace_name(requested);
  } else if (file.has_value()) {
    chromaticities = *file;
    const ColorSpace named = named_colorspace(*file);
    result.name = named == ColorSpace::Auto ? "file" : colorspace_name(named);
  } else {
    result.name = colorspace_name(ColorSpace::LinearRec709);
  }
  if (named_colorspace(chromaticities) != ColorSpace::LinearRec709) {
    Matrix3 m;
    if (!rgb_to_rec709_matrix(chromaticities, m, problem)) return false;
    result.matrix = m;
  }
  out = std::move(result);
  return true;
}

}  // namespace shpack
