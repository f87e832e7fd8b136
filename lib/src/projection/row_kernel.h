// row_kernel.h (private) - one equirect row: read texels, apply the value policies, and
// form the five column sums per channel (equirect_weights.h) in double.
#pragma once

#include <cstdint>
#include <span>

#include "shpack/image_view.h"
#include "shpack/project.h"

namespace shpack::detail {

// Per-column longitude tables, structure of arrays (equirect_weights.h ColumnTrig).
struct ColumnTables {
  std::span<const double> cos1, sin1, cos2, sin2;
};

// Counts of what a run of rows held; `first_nonfinite_*` is the first in row-major order.
struct TexelCounts {
  std::uint64_t nonfinite = 0, negative = 0;
  std::uint32_t first_nonfinite_x = 0, first_nonfinite_y = 0;
  double max_value = 0.0;

  void merge_after(const TexelCounts& later) noexcept;  // `later` covers later rows
};

// S0, Sc, Ss, Sc2, Ss2 of one channel of one row.
struct ColumnSums {
  double s0 = 0, sc = 0, ss = 0, sc2 = 0, ss2 = 0;
};

// Reads row `y` (a resolved view of exactly that row) into `scratch` (3 * width floats,
// channel planes R, G, B, `width` each) applying the options' NaN/Inf and negative
// policies, and counts into `counts`. A grey image (1 or 2 channels) fills all three
// planes from channel 0; under NonFinite::Error a NaN/Inf texel is stored as 0 (the caller
// fails). Shared by the equirect and cube projections.
void load_row_planes(const ImageView& row, std::uint32_t y, const ProjectOptions& options,
                     std::span<float> scratch, TexelCounts& counts) noexcept;

// Row `y` of a resolved whole-image view through load_row_planes, its counts merged into
// `counts`; fails with Errc::NonFiniteTexel (at the first such texel so far) when the row
// holds one and the options say NonFinite::Error. For projections that read row by row.
Status load_image_row(const ImageView& image, std::uint32_t y, const ProjectOptions& options,
                      std::span<float> planes, TexelCounts& counts) noexcept;

// As load_row_planes (or a fused kernel with the same result), then the column sums of
// each channel.
void row_column_sums(const ImageView& row, std::uint32_t y, const ProjectOptions& options,
                     const ColumnTables& columns, std::span<float> scratch,
                     TexelCounts& counts, ColumnSums (&sums)[3]) noexcept;

}  // namespace shpack::detail
