// texel_policy.h (private) - the NaN/Inf and negative policies of one texel, as every row
// loader applies them (row_kernel.cpp, row_kernel_simd.cpp), and how a row's texels are
// counted into TexelCounts.
//
// Per value: a NaN or Inf becomes 0 and marks its texel non-finite; a finite value below 0
// marks its texel negative and, under Negative::Clamp, becomes 0 (-0 is not below 0, so it
// is neither counted nor changed). A texel counts once however many of its values are marked.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "projection/row_kernel.h"

namespace shpack::detail {

struct TexelMarks {
  bool nonfinite = false, negative = false;
};

inline float apply_value_policy(float v, bool clamp_negative, TexelMarks& marks) noexcept {
  if (!std::isfinite(v)) {
    marks.nonfinite = true;
    return 0.0f;
  }
  if (v < 0.0f) {
    marks.negative = true;
    if (clamp_negative) return 0.0f;
  }
  return v;
}

// Counts a group of up to 32 consecutive texels of row `y` starting at column `x0`: bit k
// of each mask is texel x0 + k. Groups must be counted in column order, rows in row order,
// so that the first non-finite texel is the first in row-major order.
inline void count_texels(std::uint32_t nonfinite_mask, std::uint32_t negative_mask, std::uint32_t x0,
                         std::uint32_t y, TexelCounts& counts) noexcept {
  if (nonfinite_mask != 0 && counts.nonfinite == 0) {
    counts.first_nonfinite_x = x0 + static_cast<std::uint32_t>(std::countr_zero(nonfinite_mask));
    counts.first_nonfinite_y = y;
  }
  counts.nonfinite += static_cast<std::uint32_t>(std::popcount(nonfinite_mask));
  counts.negative += static_cast<std::uint32_t>(std::popcount(negative_mask));
}

// One RGB texel at column x of row y through the policies, in place; raises `row_max`
// (the largest value after the policies, never below its start of 0).
inline void apply_texel_policy(float (&rgb)[3], std::uint32_t x, std::uint32_t y, bool clamp_negative,
                               float& row_max, TexelCounts& counts) noexcept {
  TexelMarks marks;
  for (float& v : rgb) {
    v = apply_value_policy(v, clamp_negative, marks);
    row_max = std::max(row_max, v);
  }
  count_texels(marks.nonfinite ? 1u : 0u, marks.negative ? 1u : 0u, x, y, counts);
}

}  // namespace shpack::detail
