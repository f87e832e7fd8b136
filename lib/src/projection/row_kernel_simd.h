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

struct SimdKernels {
  ColumnSums (*plane_sums)(const float*, const ColumnTables&, std::uint32_t) noexcept;
  // Deinterleaves a float RGB(A) row into planes if every R, G, B value is finite and
  // >= 0 (raising max_value), and returns true; returns false otherwise (planes undefined).
  // Null where no fast loader exists.
  bool (*load_clean_rgb_f32)(const ImageView&, std::span<float>, double& max_value) noexcept;
  // Fused: the column sums of a clean float RGB(A) row straight from the interleaved
  // pixels, true if the row was clean (as above); null where no fused kernel exists.
  bool (*sum_clean_rgb_f32)(const ImageView&, const ColumnTables&, ColumnSums (&)[3],
                            double& max_value) noexcept;
};

const SimdKernels& simd_kernels() noexcept;

}  // namespace shpack::detail
