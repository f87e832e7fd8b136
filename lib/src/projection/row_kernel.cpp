#include "projection/row_kernel.h"

#include <algorithm>
#include <cstring>

#include "projection/row_kernel_simd.h"
#include "projection/texel_policy.h"

namespace shpack::detail {
namespace {

template <PixelType T>
float load_value(const std::byte* p) noexcept {
  if constexpr (T == PixelType::F32) {
    float f;
    std::memcpy(&f, p, sizeof f);
    return f;
  } else {
    std::uint16_t h;
    std::memcpy(&h, p, sizeof h);
    return half_to_float(h);
  }
}

// Deinterleaves a row into three planes; a grey image (1 or 2 channels) feeds channel 0
// to all three. Each texel goes through the options' policies (texel_policy.h);
// NonFinite::Error also zeroes a NaN/Inf: the caller fails the whole projection.
template <PixelType T>
void load_row(const ImageView& row, std::uint32_t y, bool clamp_negative, std::span<float> scratch,
              TexelCounts& counts) noexcept {
  const std::uint32_t width = row.width;
  float* planes[3] = {scratch.data(), scratch.data() + width, scratch.data() + 2 * width};
  const std::int64_t step = pixel_type_size(T);
  const std::int64_t channel_step[3] = {0, row.channels >= 3 ? step : 0, row.channels >= 3 ? 2 * step : 0};
  float row_max = 0.0f;
  for (std::uint32_t x = 0; x < width; ++x) {
    const std::byte* p = row.pixel(x, 0);
    float rgb[3];
    for (int c = 0; c < 3; ++c) rgb[c] = load_value<T>(p + channel_step[c]);
    apply_texel_policy(rgb, x, y, clamp_negative, row_max, counts);
    for (int c = 0; c < 3; ++c) planes[c][x] = rgb[c];
  }
  counts.max_value = std::max(counts.max_value, static_cast<double>(row_max));
}

}  // namespace

ColumnSums plane_sums_portable(const float* v, const ColumnTables& t, std::uint32_t width) noexcept {
  double s0[kSumLanes] = {}, sc[kSumLanes] = {}, ss[kSumLanes] = {}, sc2[kSumLanes] = {},
         ss2[kSumLanes] = {};
  for (std::uint32_t i = 0; i < width; ++i) {
    const std::uint32_t k = i % kSumLanes;
    const double x = v[i];
    s0[k] += x;
    sc[k] += x * t.cos1[i];
    ss[k] += x * t.sin1[i];
    sc2[k] += x * t.cos2[i];
    ss2[k] += x * t.sin2[i];
  }
  return {lane_total(s0), lane_total(sc), lane_total(ss), lane_total(sc2), lane_total(ss2)};
}

void TexelCounts::merge_after(const TexelCounts& later) noexcept {
  if (nonfinite == 0 && later.nonfinite != 0) {
    first_nonfinite_x = later.first_nonfinite_x;
    first_nonfinite_y = later.first_nonfinite_y;
  }
  nonfinite += later.nonfinite;
  negative += later.negative;
  max_value = std::max(max_value, later.max_value);
}

void load_row_planes(const ImageView& row, std::uint32_t y, const ProjectOptions& options,
                     std::span<float> scratch, TexelCounts& counts) noexcept {
  const SimdKernels& simd = simd_kernels();
  const bool clamp_negative = options.negative == Negative::Clamp;
  // The vector loader takes float RGB(A) rows of packed texels, whatever their values;
  // other rows take the portable loader, which gives the same planes and counts.
  const bool rgb_f32 = row.type == PixelType::F32 && row.channels >= 3;
  if (rgb_f32 && simd.load_rgb_f32 && simd.load_rgb_f32(row, y, clamp_negative, scratch, counts)) return;
  if (row.type == PixelType::F32) {
    load_row<PixelType::F32>(row, y, clamp_negative, scratch, counts);
  } else {
    load_row<PixelType::F16>(row, y, clamp_negative, scratch, counts);
  }
}

Status load_image_row(const ImageView& image, std::uint32_t y, const ProjectOptions& options,
                      std::span<float> planes, TexelCounts& counts) noexcept {
  TexelCounts row_counts;
  load_row_planes(image.rows(y, 1), y, options, planes, row_counts);
  counts.merge_after(row_counts);
  if (row_counts.nonfinite != 0 && options.nonfinite == NonFinite::Error)
    return Status::error(Errc::NonFiniteTexel, "NaN or Inf texel", counts.first_nonfinite_x,
                         counts.first_nonfinite_y);
  return Status::success();
}

void row_column_sums(const ImageView& row, std::uint32_t y, const ProjectOptions& options,
                     const ColumnTables& columns, std::span<float> scratch,
                     TexelCounts& counts, ColumnSums (&sums)[3]) noexcept {
  const SimdKernels& simd = simd_kernels();
  // The fused kernel takes float RGB(A) rows of packed texels whatever their values, with
  // the policies applied inside it; any other row is loaded into planes, then summed.
  const bool rgb_f32 = row.type == PixelType::F32 && row.channels >= 3;
  if (rgb_f32 && simd.sum_rgb_f32 &&
      simd.sum_rgb_f32(row, y, options.negative == Negative::Clamp, columns, sums, counts))
    return;
  load_row_planes(row, y, options, scratch, counts);
  for (int c = 0; c < 3; ++c) sums[c] = simd.plane_sums(scratch.data() + c * row.width, columns, row.width);
}

}  // namespace shpack::detail
