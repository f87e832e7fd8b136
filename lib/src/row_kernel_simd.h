// row_kernel_simd.h (private) - the row kernel's inner loops, chosen once at run time.
//
// The portable loops are the definition; the x86-64 AVX2 versions compute exactly the same
// sums in exactly the same order (kSumLanes partial sums, lane k taking texels
// i = k mod kSumLanes, combined as (l0 + l1) + (l2 + l3), separate multiply and add, no
// FMA), so the result is bit-identical whichever runs.
#pragma once

#include <cstdint>
#include <span>

#include "row_kernel.h"

namespace shpack::detail {

inline constexpr std::uint32_t kSumLanes = 4;

inline double lane_total(const double (&lanes)[kSumLanes]) noexcept {
  return (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
}

ColumnSums plane_sums_portable(const float* v, const ColumnTables& t, std::uint32_t width) noexcept;

struct SimdKernels {
  ColumnSums (*plane_sums)(const float*, const ColumnTables&, std::uint32_t) noexcept;
  // Deinterleaves a float RGB(A) row into planes if every R, G, B value is finite and
  // >= 0 (raising max_value), and returns true; returns false otherwise (planes undefined).
  // Null where no fast loader exists.
  bool (*load_clean_rgb_f32)(const ImageView&, std::span<float>, double& max_value) noexcept;
};

const SimdKernels& simd_kernels() noexcept;

}  // namespace shpack::detail
