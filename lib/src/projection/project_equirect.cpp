#include <algorithm>
#include <new>
#include <thread>
#include <vector>

#include "common/accumulate.h"
#include "projection/equirect_weights.h"
#include "projection/row_kernel.h"
#include "shpack/work_queue.h"
#include "shpack/project.h"

namespace shpack {
namespace detail {

// One tile of kTileRows rows: compensated sums of the 9 basis integrals per channel,
// added row by row in row order, so the tile's value depends only on its rows. Not in the
// anonymous namespace: EquirectProjector::State holds them.
struct EquirectTile {
  NeumaierSum integral[kChannelCount][kShCount];
  TexelCounts counts;
};

}  // namespace detail

namespace {

using detail::EquirectTile;
using detail::NeumaierSum;

void add_row(const detail::RowWeights& w, const detail::ColumnSums (&s)[3], EquirectTile& tile) noexcept {
  for (int c = 0; c < kChannelCount; ++c) {
    const detail::ColumnSums& r = s[c];
    NeumaierSum* out = tile.integral[c];
    out[0].add(w.k0 * r.s0);
    out[1].add(w.k1 * r.s0);
    out[2].add(w.kx * r.ss);
    out[3].add(w.kx * r.sc);
    out[4].add(w.kxy * r.sc);
    out[5].add(w.kxy * r.ss);
    out[6].add(w.k6_s0 * r.s0 + w.k6_c2 * r.sc2);
    out[7].add(w.k7 * r.ss2);
    out[8].add(w.k8_s0 * r.s0 + w.k8_c2 * r.sc2);
  }
}

// A band of consecutive rows inside one tile.
struct Segment {
  std::uint32_t first_row, row_count;
};

// Segment k of the band of rows [first, end): the part of the band in its k-th tile.
Segment band_segment(std::uint32_t first, std::uint32_t end, std::uint32_t k) noexcept {
  const std::uint32_t tile_start = (first / kTileRows + k) * kTileRows;
  const std::uint32_t start = std::max(first, tile_start);
  return {start, std::min(end, tile_start + kTileRows) - start};
}

std::uint32_t band_segment_count(std::uint32_t first, std::uint32_t end) noexcept {
  return (end - 1) / kTileRows - first / kTileRows + 1;
}

}  // namespace

struct EquirectProjector::State {
  std::uint32_t width = 0, height = 0;
  ProjectOptions options;
  unsigned workers = 1;
  std::vector<double> column_tables;  // cos1 | sin1 | cos2 | sin2, width each
  std::vector<float> scratch;         // 3 * width floats per worker
  std::vector<EquirectTile> tiles;
  std::uint32_t next_row = 0;
  bool failed = false;

  detail::ColumnTables columns() const noexcept {
    const std::span<const double> all(column_tables);
    return {all.subspan(0, width), all.subspan(width, width), all.subspan(2 * width, width),
            all.subspan(3 * width, width)};
  }

  void run_segment(const ImageView& rows, std::uint32_t first_row, Segment seg,
                   unsigned worker) noexcept {
    const std::span<float> own(scratch.data() + std::size_t{3} * width * worker, std::size_t{3} * width);
    EquirectTile& tile = tiles[seg.first_row / kTileRows];
    const detail::ColumnTables cols = columns();
    for (std::uint32_t y = seg.first_row; y < seg.first_row + seg.row_count; ++y) {
      detail::ColumnSums sums[3];
      detail::TexelCounts row_counts;
      detail::row_column_sums(rows.rows(y - first_row, 1), y, options, cols, own, row_counts, sums);
      tile.counts.merge_after(row_counts);
      const detail::RowWeights w = options.method == SamplingMethod::Exact
                                       ? detail::exact_row_weights(y, height, width)
                                       : detail::center_row_weights(y, height, width);
      add_row(w, sums, tile);
    }
  }

  // Runs the band's segments on up to `workers` threads (work_queue.h); each segment
  // belongs to a different tile, so workers never share a tile.
  void run_band(const ImageView& rows, std::uint32_t first_row) noexcept {
    const std::uint32_t end = first_row + rows.height;
    detail::run_queue(band_segment_count(first_row, end), workers, [&](std::uint32_t k, unsigned worker) noexcept {
      run_segment(rows, first_row, band_segment(first_row, end, k), worker);
    });
  }
};

EquirectProjector::EquirectProjector() noexcept = default;
EquirectProjector::~EquirectProjector() = default;

Status EquirectProjector::begin(std::uint32_t width, std::uint32_t height,
                                const ProjectOptions& options) noexcept {
  state_.reset();
  if (width == 0 || height == 0) return Status::error(Errc::BadView, "image has zero size");
  if (options.method != SamplingMethod::Exact && options.method != SamplingMethod::Center)
    return Status::error(Errc::InvalidArgument, "unknown projection method");
  try {
    auto s = std::make_unique<State>();
    s->width = width;
    s->height = height;
    s->options = options;
    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    s->workers = options.threads == 0 ? hw : options.threads;
    s->workers = std::min<unsigned>(s->workers, (height + kTileRows - 1) / kTileRows);
    s->column_tables.resize(std::size_t{4} * width);
    for (std::uint32_t i = 0; i < width; ++i) {
      const detail::ColumnTrig t = detail::column_trig(i, width);
      s->column_tables[i] = t.cos1;
      s->column_tables[width + i] = t.sin1;
      s->column_tables[2 * std::size_t{width} + i] = t.cos2;
      s->column_tables[3 * std::size_t{width} + i] = t.sin2;
    }
    s->scratch.resize(std::size_t{3} * width * s->workers);
    s->tiles.resize((height + kTileRows - 1) / kTileRows);
    state_ = std::move(s);
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the projection tables");
  }
  return Status::success();
}

Status EquirectProjector::add_rows(const ImageView& rows, std::uint32_t first_row) noexcept {
  if (!state_ || state_->failed) return Status::error(Errc::BadSequence, "add_rows before begin or after an error");
  State& s = *state_;
  ImageView view = rows;
  if (Status st = resolve_view(view); !st.ok()) return st;
  if (view.width != s.width) return Status::error(Errc::BadView, "row width differs from the image width");
  if (first_row != s.next_row || view.height > s.height - first_row)
    return Status::error(Errc::BadSequence, "rows are not the next rows of the image");

  s.run_band(view, first_row);
  s.next_row += view.height;

  if (s.options.nonfinite == NonFinite::Error) {
    for (std::uint32_t t = first_row / kTileRows; t <= (s.next_row - 1) / kTileRows; ++t) {
      const detail::TexelCounts& c = s.tiles[t].counts;
      if (c.nonfinite != 0) {
        s.failed = true;
        return Status::error(Errc::NonFiniteTexel, "NaN or Inf texel", c.first_nonfinite_x,
                             c.first_nonfinite_y);
      }
    }
  }
  return Status::success();
}

Status EquirectProjector::finish(ShL2& radiance, ProjectStats* stats) noexcept {
  if (!state_ || state_->failed || state_->next_row != state_->height)
    return Status::error(Errc::BadSequence, "finish before every row was added");
  NeumaierSum total[kChannelCount][kShCount];
  detail::TexelCounts counts;
  for (const EquirectTile& tile : state_->tiles) {
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) total[c][i].add(tile.integral[c][i]);
    counts.merge_after(tile.counts);
  }
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) radiance.c[c][i] = kBasisScale[i] * total[c][i].value();
  if (stats != nullptr) {
    *stats = {counts.nonfinite, counts.negative, counts.first_nonfinite_x,
              counts.first_nonfinite_y, counts.max_value};
  }
  state_.reset();
  return Status::success();
}

Status project_equirect(const ImageView& image, const ProjectOptions& options, ShL2& radiance,
                        ProjectStats* stats) noexcept {
  ImageView view = image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  EquirectProjector projector;
  if (Status st = projector.begin(view.width, view.height, options); !st.ok()) return st;
  if (Status st = projector.add_rows(view, 0); !st.ok()) return st;
  return projector.finish(radiance, stats);
}

}  // namespace shpack
