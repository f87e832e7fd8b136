// view_reference_texels.cpp - texels into the reference's cells: equirect rows with their
// closed-form integrals, and single texels of any other layout (view_reference.h).
#include <algorithm>
#include <cmath>
#include <new>

#include "common/angles.h"
#include "reference/reference_tree.h"
#include "shpack/view_reference.h"

namespace shpack {
namespace {

std::uint32_t ceil_div(std::uint32_t a, std::uint32_t b) noexcept { return (a + b - 1) / b; }

}  // namespace

Status ViewReference::begin_equirect(std::uint32_t width, std::uint32_t height, const ProjectOptions& options) noexcept {
  if (width == 0 || height == 0) return Status::error(Errc::BadView, "an empty image has no reference E/pi");
  try {
    auto s = std::make_unique<State>();
    s->kind = State::Kind::Equirect;
    s->options = options;
    s->options.nonfinite = NonFinite::Zero;
    s->width = width;
    s->height = height;
    s->block_w = ceil_div(width, detail::kReferenceCellsW);
    s->block_h = ceil_div(height, detail::kReferenceCellsH);
    s->cells_w = ceil_div(width, s->block_w);
    s->cells_h = ceil_div(height, s->block_h);
    s->cells.assign(static_cast<std::size_t>(s->cells_w) * s->cells_h, detail::FinestCell{});
    s->column_cos.resize(width);
    s->column_sin.resize(width);
    // Column x spans longitudes [p0, p1] = [(0.5 - (x+1)/W) 2 pi, (0.5 - x/W) 2 pi]:
    // sin p1 - sin p0 = 2 cos(pm) sin(dp/2), cos p0 - cos p1 = 2 sin(pm) sin(dp/2), without
    // the cancellation of the differences.
    const double half = std::sin(kPi / width);
    for (std::uint32_t x = 0; x < width; ++x) {
      const double pm = (0.5 - (x + 0.5) / width) * 2 * kPi;
      s->column_cos[x] = 2 * std::cos(pm) * half;
      s->column_sin[x] = 2 * std::sin(pm) * half;
    }
    s->planes.resize(3 * static_cast<std::size_t>(width));
    state_ = std::move(s);
    return {};
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory for the reference E/pi");
  }
}

Status ViewReference::add_rows(const ImageView& rows_in, std::uint32_t first_row) noexcept {
  if (!state_ || state_->finished || state_->kind != State::Kind::Equirect)
    return Status::error(Errc::BadSequence, "ViewReference::add_rows without begin_equirect");
  State& s = *state_;
  ImageView rows = rows_in;
  if (Status st = resolve_view(rows); !st.ok()) return st;
  if (first_row != s.next_row || rows.width != s.width || rows.height > s.height - first_row)
    return Status::error(Errc::BadSequence, "ViewReference::add_rows: not the next rows of the image");
  const double dphi = 2 * kPi / s.width;
  detail::TexelCounts counts;
  for (std::uint32_t r = 0; r < rows.height; ++r) {
    const std::uint32_t y = first_row + r;
    detail::load_row_planes(rows.rows(r, 1), y, s.options, s.planes, counts);
    // The row's polar integrals (view_reference.h), in forms without cancellation.
    const double th0 = kPi * y / s.height, th1 = kPi * (y + 1) / s.height;
    const double dth = th1 - th0, thm = 0.5 * (th0 + th1);
    const double omega = 2 * std::sin(0.5 * dth) * std::sin(thm) * dphi;
    const double sin2 = 0.5 * dth - 0.5 * std::sin(dth) * std::cos(th0 + th1);
    const double sincos = 0.5 * std::sin(th1 - th0) * std::sin(th1 + th0) * dphi;  // (sin^2 th1 - sin^2 th0)/2 dphi
    const double sin_max = (th0 <= 0.5 * kPi && th1 >= 0.5 * kPi) ? 1.0 : std::max(std::sin(th0), std::sin(th1));
    const double diameter = dth + sin_max * dphi;
    const float* plane[3] = {s.planes.data(), s.planes.data() + s.width, s.planes.data() + 2 * s.width};
    detail::FinestCell* cell_row = s.cells.data() + static_cast<std::size_t>(y / s.block_h) * s.cells_w;
    for (std::uint32_t cx = 0; cx < s.cells_w; ++cx) {
      detail::FinestCell& cell = cell_row[cx];
      const std::uint32_t x0 = cx * s.block_w, x1 = std::min(s.width, x0 + s.block_w);
      double sum[3] = {}, sum_cos[3] = {}, sum_sin[3] = {}, sum_pos[3] = {};
      // A texel lighter than kHeavyShare of what its cell holds so far cannot be kept (the
      // cell only gains, build_tree keeps only texels of at least that share of its total), so
      // it is not offered: the texels kept are the same, the offers far fewer. The margin
      // covers the rounding of weight x omega.
      double so_far = 0;
      for (int ch = 0; ch < 3; ++ch) so_far += cell.sums.positive[ch] + cell.sums.negative[ch];
      const double threshold = std::max(cell.heavy_threshold(), detail::kHeavyShare * (1 - 1e-12) * so_far) / omega;
      for (std::uint32_t x = x0; x < x1; ++x) {
        const double cc = s.column_cos[x], ss = s.column_sin[x];
        double weight = 0;
        for (int ch = 0; ch < 3; ++ch) {
          const double v = plane[ch][x];
          sum[ch] += v;
          sum_cos[ch] += v * cc;
          sum_sin[ch] += v * ss;
          sum_pos[ch] += std::max(v, 0.0);
          weight += std::abs(v);
        }
        if (weight > threshold && weight > 0) {
          detail::HeavyTexel t;
          t.weight = weight * omega;
          t.rgb = {plane[0][x], plane[1][x], plane[2][x]};
          t.solid_angle = omega;
          t.flux = {sin2 * cc, sincos, sin2 * ss};
          t.diameter = diameter;
          cell.offer(t);
        }
      }
      for (int ch = 0; ch < 3; ++ch) {
        cell.sums.m[ch].x += sin2 * sum_cos[ch];
        cell.sums.m[ch].y += sincos * sum[ch];
        cell.sums.m[ch].z += sin2 * sum_sin[ch];
        cell.sums.positive[ch] += omega * sum_pos[ch];
        cell.sums.negative[ch] += omega * (sum_pos[ch] - sum[ch]);
      }
    }
  }
  s.next_row += rows.height;
  return {};
}

Status ViewReference::begin_texels() noexcept {
  try {
    auto s = std::make_unique<State>();
    s->kind = State::Kind::Texels;
    s->width = s->cells_w = detail::kReferenceCellsW;
    s->height = s->cells_h = detail::kReferenceCellsH;
    s->cells.assign(static_cast<std::size_t>(s->cells_w) * s->cells_h, detail::FinestCell{});
    state_ = std::move(s);
    return {};
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory for the reference E/pi");
  }
}

void ViewReference::add_texel(const std::array<float, 3>& rgb, double solid_angle, const Dir3& flux,
                              double diameter) noexcept {
  if (!state_ || state_->finished || state_->kind != State::Kind::Texels || !(solid_angle > 0)) return;
  State& s = *state_;
  // The cell of the texel's centroid direction, on the equirect grid of conventions.h.
  const double len = std::sqrt(flux.x * flux.x + flux.y * flux.y + flux.z * flux.z);
  std::uint32_t cx = 0, cy = 0;
  if (len > 0) {
    const double theta = std::acos(std::clamp(flux.y / len, -1.0, 1.0));
    const double u = 0.5 - std::atan2(flux.z, flux.x) / (2 * kPi);
    cy = std::min(s.cells_h - 1, static_cast<std::uint32_t>(theta / kPi * s.cells_h));
    cx = std::min(s.cells_w - 1, static_cast<std::uint32_t>(u * s.cells_w));
  }
  detail::FinestCell& cell = s.cells[static_cast<std::size_t>(cy) * s.cells_w + cx];
  cell.extra_radius = std::max(cell.extra_radius, len > 0 ? diameter : kPi);
  double weight = 0;
  for (int ch = 0; ch < 3; ++ch) {
    const double v = rgb[ch];
    cell.sums.m[ch].x += v * flux.x;
    cell.sums.m[ch].y += v * flux.y;
    cell.sums.m[ch].z += v * flux.z;
    (v > 0 ? cell.sums.positive : cell.sums.negative)[ch] += std::abs(v) * solid_angle;
    weight += std::abs(v) * solid_angle;
  }
  if (weight > 0) cell.offer({weight, rgb, solid_angle, flux, diameter});
}

}  // namespace shpack
