#include "shpack/irradiance_reference.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "projection/equirect_integrals.h"

namespace shpack {
namespace {

using detail::direction_integral;
using detail::lon_integrals;
using detail::LonIntegrals;
using detail::theta_integrals;
using detail::ThetaIntegrals;

constexpr double kPi = std::numbers::pi;

// The whole texels [first, last) of `count` that overlap the cell [k/cells, (k+1)/cells).
void overlapping(std::uint32_t k, std::uint32_t cells, std::uint32_t count, std::uint32_t& first, std::uint32_t& last) {
  first = static_cast<std::uint32_t>(std::uint64_t{k} * count / cells);
  last = static_cast<std::uint32_t>((std::uint64_t{k + 1} * count + cells - 1) / cells);
}

float texel_value(const ImageView& image, std::uint32_t x, std::uint32_t y, int channel) {
  float v;
  const int c = image.channels >= 3 ? channel : 0;
  std::memcpy(&v, image.pixel(x, y) + 4 * c, sizeof v);
  return v;
}

// The geometry of cell (cx, cy) of a cells_w x cells_h grid: centre direction and a radius
// that bounds the angle from it to any point of the cell (preview.h).
void set_geometry(std::uint32_t cx, std::uint32_t cy, std::uint32_t cells_w, std::uint32_t cells_h, Dir3& centre,
                  double& radius) {
  const double ta = kPi * cy / cells_h, tb = kPi * (cy + 1) / cells_h;
  // Longitude falls as u grows (conventions.h): u in [ua, ub] is lon in [lon(ub), lon(ua)].
  const double pa = (0.5 - static_cast<double>(cx + 1) / cells_w) * 2.0 * kPi;
  const double pb = (0.5 - static_cast<double>(cx) / cells_w) * 2.0 * kPi;
  const double tc = 0.5 * (ta + tb), pc = 0.5 * (pa + pb);
  centre = {std::sin(tc) * std::cos(pc), std::cos(tc), std::sin(tc) * std::sin(pc)};
  const double max_sin = (ta <= 0.5 * kPi && 0.5 * kPi <= tb) ? 1.0 : std::max(std::sin(ta), std::sin(tb));
  radius = 0.5 * (tb - ta) + max_sin * 0.5 * (pb - pa);
}

}  // namespace

ReferenceIrradiance::ReferenceIrradiance(const ImageView& image, double scale, std::uint32_t cells_w,
                                         std::uint32_t cells_h, int levels)
    : cells_w_(cells_w), cells_h_(cells_h), levels_(static_cast<std::size_t>(levels)) {
  const std::uint32_t width = image.width, height = image.height;
  // The finest level from the texels, each cell summing the parts of the texels it overlaps.
  const std::uint32_t fine_w = cells_w << (levels - 1), fine_h = cells_h << (levels - 1);
  std::vector<Cell>& fine = levels_.back();
  fine.resize(std::size_t{fine_w} * fine_h);
  for (std::uint32_t cy = 0; cy < fine_h; ++cy) {
    const double ta = kPi * cy / fine_h, tb = kPi * (cy + 1) / fine_h;
    std::uint32_t y0, y1;
    overlapping(cy, fine_h, height, y0, y1);
    for (std::uint32_t cx = 0; cx < fine_w; ++cx) {
      const double ua = static_cast<double>(cx) / fine_w, ub = static_cast<double>(cx + 1) / fine_w;
      Cell& cell = fine[std::size_t{cy} * fine_w + cx];
      set_geometry(cx, cy, fine_w, fine_h, cell.centre, cell.radius);
      std::uint32_t x0, x1;
      overlapping(cx, fine_w, width, x0, x1);
      for (std::uint32_t y = y0; y < y1; ++y) {
        const ThetaIntegrals t = theta_integrals(std::max(ta, kPi * y / height), std::min(tb, kPi * (y + 1) / height));
        for (std::uint32_t x = x0; x < x1; ++x) {
          const double u0 = std::max(ua, static_cast<double>(x) / width);
          const double u1 = std::min(ub, static_cast<double>(x + 1) / width);
          const LonIntegrals p = lon_integrals((0.5 - u1) * 2.0 * kPi, (0.5 - u0) * 2.0 * kPi);
          const Dir3 w = direction_integral(t, p);
          const double solid = t.solid * p.length;
          for (int c = 0; c < 3; ++c) {
            const double value = scale * texel_value(image, x, y, c);
            cell.flux[c].x += value * w.x;
            cell.flux[c].y += value * w.y;
            cell.flux[c].z += value * w.z;
            (value >= 0 ? cell.positive[c] : cell.negative[c]) += std::fabs(value) * solid;
          }
        }
      }
    }
  }
  // Each coarser level sums 2 x 2 children.
  for (std::size_t level = levels_.size() - 1; level-- > 0;) {
    const std::uint32_t w = cells_w << level, h = cells_h << level;
    levels_[level].resize(std::size_t{w} * h);
    for (std::uint32_t cy = 0; cy < h; ++cy) {
      for (std::uint32_t cx = 0; cx < w; ++cx) {
        Cell& cell = levels_[level][std::size_t{cy} * w + cx];
        set_geometry(cx, cy, w, h, cell.centre, cell.radius);
        for (std::uint32_t k = 0; k < 4; ++k) {
          const Cell& child = levels_[level + 1][std::size_t{2 * cy + k / 2} * (2 * w) + 2 * cx + k % 2];
          for (int c = 0; c < 3; ++c) {
            cell.flux[c].x += child.flux[c].x;
            cell.flux[c].y += child.flux[c].y;
            cell.flux[c].z += child.flux[c].z;
            cell.positive[c] += child.positive[c];
            cell.negative[c] += child.negative[c];
          }
        }
      }
    }
  }
}

void ReferenceIrradiance::add(std::size_t level, std::uint32_t x, std::uint32_t y, const Dir3& n,
                              ReferenceValue& out) const {
  const std::uint32_t w = cells_w_ << level;
  const Cell& cell = levels_[level][std::size_t{y} * w + x];
  const double d = n.x * cell.centre.x + n.y * cell.centre.y + n.z * cell.centre.z;
  if (d <= -cell.radius) return;  // the whole cell faces away: exactly 0
  const bool cut = d < cell.radius;
  if (cut && level + 1 < levels_.size()) {
    for (std::uint32_t k = 0; k < 4; ++k) add(level + 1, 2 * x + k % 2, 2 * y + k / 2, n, out);
    return;
  }
  for (int c = 0; c < 3; ++c) {
    const double linear = n.x * cell.flux[c].x + n.y * cell.flux[c].y + n.z * cell.flux[c].z;
    if (!cut) {  // the whole cell faces n: the cosine is linear on it, exact
      out.e_over_pi[c] += linear;
      continue;
    }
    const double h = cell.radius - d, g = cell.radius + d;
    const double lo = std::max(linear - cell.negative[c] * h, -cell.negative[c] * g);
    const double hi = std::min(linear + cell.positive[c] * h, cell.positive[c] * g);
    out.e_over_pi[c] += 0.5 * (lo + hi);
    out.bound[c] += 0.5 * std::fabs(hi - lo);
  }
}

ReferenceValue ReferenceIrradiance::eval(const Dir3& n) const {
  ReferenceValue out;
  for (std::uint32_t y = 0; y < cells_h_; ++y)
    for (std::uint32_t x = 0; x < cells_w_; ++x) add(0, x, y, n, out);
  for (int c = 0; c < 3; ++c) {
    out.e_over_pi[c] /= kPi;
    out.bound[c] /= kPi;
  }
  return out;
}

}  // namespace shpack
