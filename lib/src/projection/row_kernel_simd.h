// row_kernel_simd.h (private) - the row kernel's inner loops, chosen once at run time.
//
// The portable loops are the definition; the x86-64 AVX2 versions compute exactly the same
// sums in exactly the same order (kSumLanes partial sums, lane k taking texels
// i = k mod kSumLanes, combined pairwise as in lane_total, separate multiply and add, no
// FMA), so the result is bit-identical whichever runs.
#pragma once

#include <cstdint>
#include <span>

#include "projection/row_kernel.h"

namespace shpack::detail {

inline constexpr std::uint32_t kSumLanes = 8;

inline double lane_total(const double (&l)[kSumLanes]) noexcept {
  return ((l[0] + l[1]) + (l[2] + l[3])) + ((l[4] + l[5]) + (l[6] + l[7]));
}

ColumnSums plane_sums_portable(const float* v, const ColumnTables& t, std::uint32_t width) noexcept;

// The vector kernels take float RGB(A) rows of packed texels (pixel stride 12 or 16 bytes)
// whatever their values: they apply the NaN/Inf and negative policies (texel_policy.h) and
// count row `y` into `counts` exactly as the portable loader does, so a row costs the same
// with or without such texels. They return false, having done nothing, for other layouts.
struct SimdKernels {
  ColumnSums (*plane_sums)(const float*, const ColumnTables&, std::uint32_t) noexcept;
  // Deinterleaves the row into planes R, G, B; null where no vector loader exists.
  bool (*load_rgb_f32)(const ImageView&, std::uint32_t y, bool clamp_negative, std::span<float>,
                       TexelCounts&) noexcept;
  // Fused: the column sums straight from the interleaved pixels; null where no fused
  // kernel exists.
  bool (*sum_rgb_f32)(const ImageView&, std::uint32_t y, bool clamp_negative, const ColumnTables&,
                      ColumnSums (&)[3], TexelCounts&) noexcept;
};

const SimdKernels& simd_kernels() noexcept;

}  // namespace shpack::detail
