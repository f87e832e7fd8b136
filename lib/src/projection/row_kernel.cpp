#include "projection/row_kernel.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "projection/row_kernel_simd.h"

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
// to all three. Non-finite and negative values are counted per texel and replaced as the
// options say (NonFinite::Error also zeroes them: the caller fails the whole projection).
template <PixelType T>
void load_row(const ImageView& row, std::uint32_t y, const ProjectOptions& options,
              std::span<float> scratch, TexelCounts& counts) noexcept {
  const std::uint32_t width = row.width;
  float* planes[3] = {scratch.data(), scratch.data() + width, scratch.data() + 2 * width};
  const std::int64_t step = pixel_type_size(T);
  const std::int64_t channel_step[3] = {0, row.channels >= 3 ? step : 0, row.channels >= 3 ? 2 * step : 0};
  const bool clamp_negative = options.negative == Negative::Clamp;
  for (std::uint32_t x = 0; x < width; ++x) {
    const std::byte* p = row.pixel(x, 0);
    bool nonfinite = false, negative = false;
    for (int c = 0; c < 3; ++c) {
      float v = load_value<T>(p + channel_step[c]);
      if (!std::isfinite(v)) {
        nonfinite = true;
        v = 0.0f;
      } else if (v < 0.0f) {
        negative = true;
        if (clamp_negative) v = 0.0f;
      }
      counts.max_value = std::max(counts.max_value, static_cast<double>(v));
      planes[c][x] = v;
    }
    if (nonfinite && counts.nonfinite++ == 0) {
      counts.first_nonfinite_x = x;
      counts.first_nonfinite_y = y;
    }
    counts.negative += negative ? 1 : 0;
  }
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
  // The fast loader handles clean rows (every value finite and >= 0) of float RGB(A);
  // any other row, or a row it finds unclean, takes the careful loader that counts.
  const bool clean = row.type == PixelType::F32 && row.channels >= 3 && simd.load_clean_rgb_f32 &&
                     simd.load_clean_rgb_f32(row, scratch, counts.max_value);
  if (!clean) {
    if (row.type == PixelType::F32) {
      load_row<PixelType::F32>(row, y, options, scratch, counts);
    } else {
      load_row<PixelType::F16>(row, y, options, scratch, counts);
    }
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
  // The fast kernels handle clean rows (every value finite and >= 0) of float RGB(A);
  // any other row, or a row they find unclean, takes the careful loader that counts.
  const bool rgb_f32 = row.type == PixelType::F32 && row.channels >= 3;
  if (rgb_f32 && simd.sum_clean_rgb_f32 && simd.sum_clean_rgb_f32(row, columns, sums, counts.max_value))
    return;
  load_row_planes(row, y, options, scratch, counts);
  for (int c = 0; c < 3; ++c) sums[c] = simd.plane_sums(scratch.data() + c * row.width, columns, row.width);
}

}  // namespace shpack::detail
