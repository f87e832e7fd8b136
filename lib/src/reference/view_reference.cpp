// view_reference.cpp - the cells, the tree and its evaluation (view_reference.h states the
// method and its bound).
#include "shpack/view_reference.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>

#include "reference/reference_tree.h"

namespace shpack {
namespace detail {

void FinestCell::offer(const HeavyTexel& t) noexcept {
  if (heavy_count == kHeavyTexels && !(t.weight > heavy[kHeavyTexels - 1].weight)) return;
  int i = std::min(heavy_count, kHeavyTexels - 1);
  while (i > 0 && t.weight > heavy[i - 1].weight) {
    heavy[i] = heavy[i - 1];
    --i;
  }
  heavy[i] = t;
  heavy_count = std::min(heavy_count + 1, kHeavyTexels);
}

Cap make_cap(const Dir3& centre, double radius) noexcept {
  Cap cap;
  if (!(radius < std::numbers::pi)) return cap;  // the whole sphere: always cut
  cap.c = centre;
  cap.cos_r = std::cos(radius);
  cap.sin_r = std::sin(radius);
  return cap;
}

void add_cut_interval(const Cap& cap, const CellSums& sums, const Dir3& n, ReferenceValue& out) noexcept {
  // cos(alpha -+ R) from s = cos alpha = n.c: 1 when alpha <= R, -1 when alpha + R >= pi.
  const double s = std::clamp(n.x * cap.c.x + n.y * cap.c.y + n.z * cap.c.z, -1.0, 1.0);
  const double sa = std::sqrt(std::max(0.0, 1.0 - s * s));
  const double hi = s >= cap.cos_r ? 1.0 : s * cap.cos_r + sa * cap.sin_r;
  const double lo = s <= -cap.cos_r ? -1.0 : s * cap.cos_r - sa * cap.sin_r;
  const double a = std::max(0.0, lo), b = std::max(0.0, hi);
  const double h0 = std::max(0.0, -hi), h1 = std::max(0.0, -lo);
  for (int ch = 0; ch < 3; ++ch) {
    const double p = sums.positive[ch], q = sums.negative[ch];
    const Dir3& m = sums.m[ch];
    const double nm = n.x * m.x + n.y * m.y + n.z * m.z;
    double low = std::max(p * a - q * b, nm + p * h0 - q * h1);
    double high = std::min(p * b - q * a, nm + p * h1 - q * h0);
    if (low > high) low = high = 0.5 * (low + high);  // only by rounding
    out.e_over_pi[ch] += 0.5 * (low + high) / std::numbers::pi;
    out.bound[ch] += 0.5 * (high - low) / std::numbers::pi;
  }
}

namespace {

void add_sums(CellSums& to, const CellSums& from) noexcept {
  for (int ch = 0; ch < 3; ++ch) {
    to.m[ch].x += from.m[ch].x;
    to.m[ch].y += from.m[ch].y;
    to.m[ch].z += from.m[ch].z;
    to.positive[ch] += from.positive[ch];
    to.negative[ch] += from.negative[ch];
  }
}

CellSums texel_sums(const HeavyTexel& t) noexcept {
  CellSums s;
  for (int ch = 0; ch < 3; ++ch) {
    const double v = t.rgb[ch];
    s.m[ch] = {v * t.flux.x, v * t.flux.y, v * t.flux.z};
    (v > 0 ? s.positive : s.negative)[ch] = std::abs(v) * t.solid_angle;
  }
  return s;
}

// A texel's cap: centred on its centroid direction, which lies within its diameter of every
// point of it (the texel lies in the cap of that radius about any of its points, a convex
// set when the diameter is below pi/2, so its centroid's direction does too).
Cap texel_cap(const HeavyTexel& t) noexcept {
  const double len = std::sqrt(t.flux.x * t.flux.x + t.flux.y * t.flux.y + t.flux.z * t.flux.z);
  if (!(len > 0) || !(t.diameter < 0.5 * std::numbers::pi)) return Cap{};
  return make_cap({t.flux.x / len, t.flux.y / len, t.flux.z / len}, t.diameter);
}

}  // namespace
}  // namespace detail

using detail::Cap;
using detail::CellSums;
using detail::Node;

void ViewReference::State::cell_range(std::uint32_t x0, std::uint32_t x1, std::uint32_t y0, std::uint32_t y1,
                                      double& th0, double& th1, double& lon_lo, double& lon_hi) const noexcept {
  const double pi = std::numbers::pi;
  const std::uint32_t r0 = y0 * block_h, r1 = std::min(height, y1 * block_h);
  const std::uint32_t c0 = x0 * block_w, c1 = std::min(width, x1 * block_w);
  th0 = pi * r0 / height;
  th1 = pi * r1 / height;
  lon_lo = (0.5 - static_cast<double>(c1) / width) * 2 * pi;
  lon_hi = (0.5 - static_cast<double>(c0) / width) * 2 * pi;
}

Status ViewReference::State::build_tree() noexcept {
  try {
    levels.clear();
    level_w = {cells_w};
    level_h = {cells_h};
    while (level_w.back() > detail::kReferenceTopW || level_h.back() > detail::kReferenceTopH) {
      level_w.push_back((level_w.back() + 1) / 2);
      level_h.push_back((level_h.back() + 1) / 2);
    }
    levels.resize(level_w.size());
    heavy_leaves.assign(static_cast<std::size_t>(cells_w) * cells_h * detail::kHeavyTexels, Node{});
    heavy_counts.assign(static_cast<std::size_t>(cells_w) * cells_h, 0);
    mean = {};
    for (std::size_t l = 0; l < levels.size(); ++l) {
      const std::uint32_t w = level_w[l], h = level_h[l], span = 1u << l;
      levels[l].assign(static_cast<std::size_t>(w) * h, Node{});
      for (std::uint32_t y = 0; y < h; ++y) {
        for (std::uint32_t x = 0; x < w; ++x) {
          Node& node = levels[l][static_cast<std::size_t>(y) * w + x];
          const std::uint32_t x0 = x * span, x1 = std::min(cells_w, (x + 1) * span);
          const std::uint32_t y0 = y * span, y1 = std::min(cells_h, (y + 1) * span);
          double extra = 0;
          if (l == 0) {
            const detail::FinestCell& cell = cells[static_cast<std::size_t>(y) * cells_w + x];
            node.sums = cell.sums;
            extra = cell.extra_radius;
          } else {
            const auto& below = levels[l - 1];
            const std::uint32_t bw = level_w[l - 1], bh = level_h[l - 1];
            for (std::uint32_t cy = 2 * y; cy < std::min(bh, 2 * y + 2); ++cy)
              for (std::uint32_t cx = 2 * x; cx < std::min(bw, 2 * x + 2); ++cx)
                detail::add_sums(node.sums, below[static_cast<std::size_t>(cy) * bw + cx].sums);
            for (std::uint32_t cy = y0; cy < y1; ++cy)
              for (std::uint32_t cx = x0; cx < x1; ++cx)
                extra = std::max(extra, cells[static_cast<std::size_t>(cy) * cells_w + cx].extra_radius);
          }
          // The rectangle's cap (view_reference.h): from its centre along the meridian to
          // the point's polar angle, then along that parallel.
          double th0, th1, lon_lo, lon_hi;
          cell_range(x0, x1, y0, y1, th0, th1, lon_lo, lon_hi);
          const double thm = 0.5 * (th0 + th1), lonm = 0.5 * (lon_lo + lon_hi);
          const double half_pi = 0.5 * std::numbers::pi;
          const double sin_max = (th0 <= half_pi && th1 >= half_pi) ? 1.0 : std::max(std::sin(th0), std::sin(th1));
          const double radius = 0.5 * (th1 - th0) + sin_max * 0.5 * (lon_hi - lon_lo) + extra;
          node.cap = detail::make_cap({std::sin(thm) * std::cos(lonm), std::cos(thm), std::sin(thm) * std::sin(lonm)},
                                      radius);
        }
      }
    }
    // The finest cells' heavy texels become leaves of their own, the rest of each cell stays.
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const detail::FinestCell& cell = cells[i];
      Node& rest = levels[0][i];
      for (int ch = 0; ch < 3; ++ch) mean[ch] += (cell.sums.positive[ch] - cell.sums.negative[ch]) / (4 * std::numbers::pi);
      // Only a texel that carries a good part of its cell (kHeavyShare of its sum |L| Omega)
      // is worth a leaf: a lighter one narrows the bound by less than it costs to visit.
      double cell_weight = 0;
      for (int ch = 0; ch < 3; ++ch) cell_weight += cell.sums.positive[ch] + cell.sums.negative[ch];
      int kept = 0;
      while (kept < cell.heavy_count && cell.heavy[kept].weight >= detail::kHeavyShare * cell_weight) ++kept;
      heavy_counts[i] = static_cast<std::uint8_t>(kept);
      for (int k = 0; k < kept; ++k) {
        const CellSums t = detail::texel_sums(cell.heavy[k]);
        Node& leaf = heavy_leaves[i * detail::kHeavyTexels + k];
        leaf.cap = detail::texel_cap(cell.heavy[k]);
        leaf.sums = t;
        for (int ch = 0; ch < 3; ++ch) {
          rest.sums.m[ch].x -= t.m[ch].x;
          rest.sums.m[ch].y -= t.m[ch].y;
          rest.sums.m[ch].z -= t.m[ch].z;
          rest.sums.positive[ch] = std::max(0.0, rest.sums.positive[ch] - t.positive[ch]);
          rest.sums.negative[ch] = std::max(0.0, rest.sums.negative[ch] - t.negative[ch]);
        }
      }
    }
    // Level 0 now holds the rests; the exact sums of a whole finest cell are needed only when
    // it is entirely above the horizon, where rest and heavy texels are added one by one.
    cells.clear();
    cells.shrink_to_fit();
    planes.clear();
    planes.shrink_to_fit();
    finished = true;
    return {};
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory building the reference E/pi");
  }
}

namespace {

// +1 entirely above the horizon of n, -1 entirely below, 0 cut.
int side(const Cap& cap, const Dir3& n) noexcept {
  if (cap.cos_r <= 0) return 0;
  const double s = n.x * cap.c.x + n.y * cap.c.y + n.z * cap.c.z;
  if (s >= cap.sin_r) return 1;
  if (s <= -cap.sin_r) return -1;
  return 0;
}

void add_exact(const CellSums& sums, const Dir3& n, ReferenceValue& out) noexcept {
  for (int ch = 0; ch < 3; ++ch)
    out.e_over_pi[ch] += (n.x * sums.m[ch].x + n.y * sums.m[ch].y + n.z * sums.m[ch].z) / std::numbers::pi;
}

}  // namespace

void ViewReference::State::add_node(std::size_t level, std::uint32_t x, std::uint32_t y, const Dir3& n,
                                    ReferenceValue& out) const noexcept {
  const Node& node = levels[level][static_cast<std::size_t>(y) * level_w[level] + x];
  const int where = side(node.cap, n);
  if (where < 0) return;
  if (level > 0) {
    if (where > 0) return add_exact(node.sums, n, out);
    const std::uint32_t bw = level_w[level - 1], bh = level_h[level - 1];
    for (std::uint32_t cy = 2 * y; cy < std::min(bh, 2 * y + 2); ++cy)
      for (std::uint32_t cx = 2 * x; cx < std::min(bw, 2 * x + 2); ++cx) add_node(level - 1, cx, cy, n, out);
    return;
  }
  // A finest cell: its rest, then its heavy texels, each exactly or by its own cap.
  if (where > 0) {
    add_exact(node.sums, n, out);
  } else {
    detail::add_cut_interval(node.cap, node.sums, n, out);
  }
  const std::size_t i = static_cast<std::size_t>(y) * level_w[0] + x;
  for (int k = 0; k < heavy_counts[i]; ++k) {
    const Node& leaf = heavy_leaves[i * detail::kHeavyTexels + k];
    const int s = where > 0 ? 1 : side(leaf.cap, n);
    if (s > 0) add_exact(leaf.sums, n, out);
    else if (s == 0) detail::add_cut_interval(leaf.cap, leaf.sums, n, out);
  }
}

ViewReference::ViewReference() noexcept = default;
ViewReference::~ViewReference() = default;
ViewReference::ViewReference(ViewReference&&) noexcept = default;
ViewReference& ViewReference::operator=(ViewReference&&) noexcept = default;

bool ViewReference::finished() const noexcept { return state_ && state_->finished; }

Status ViewReference::finish() noexcept {
  if (!state_ || state_->finished) return Status::error(Errc::BadSequence, "ViewReference::finish without begin, or twice");
  if (state_->kind == State::Kind::Equirect && state_->next_row != state_->height)
    return Status::error(Errc::BadSequence, "ViewReference::finish before the last row");
  return state_->build_tree();
}

ReferenceValue ViewReference::eval(const Dir3& n) const noexcept {
  ReferenceValue out;
  if (!finished()) return out;
  const State& s = *state_;
  const std::size_t top = s.levels.size() - 1;
  for (std::uint32_t y = 0; y < s.level_h[top]; ++y)
    for (std::uint32_t x = 0; x < s.level_w[top]; ++x) s.add_node(top, x, y, n, out);
  return out;
}

std::array<double, 3> ViewReference::mean_e_over_pi() const noexcept {
  return finished() ? state_->mean : std::array<double, 3>{};
}

}  // namespace shpack
