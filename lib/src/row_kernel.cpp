#include "row_kernel.h"

#include <algorithm>
#include <cmath>
#include <cstring>

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

// Five dot products of one plane with the column tables. Four independent partial sums
// per quantity (texels i = 0, 1, 2, 3 mod 4) shorten the dependency chain and keep the
// order fixed, so the result does not depend on the machine.
ColumnSums plane_sums(const float* v, const ColumnTables& t, std::uint32_t width) noexcept {
  constexpr int kLanes = 4;
  double s0[kLanes] = {}, sc[kLanes] = {}, ss[kLanes] = {}, sc2[kLanes] = {}, ss2[kLanes] = {};
  std::uint32_t i = 0;
  for (; i + kLanes <= width; i += kLanes) {
    for (int k = 0; k < kLanes; ++k) {
      const double x = v[i + k];
      s0[k] += x;
      sc[k] += x * t.cos1[i + k];
      ss[k] += x * t.sin1[i + k];
      sc2[k] += x * t.cos2[i + k];
      ss2[k] += x * t.sin2[i + k];
    }
  }
  for (int k = 0; i < width; ++i, ++k) {
    const double x = v[i];
    s0[k] += x;
    sc[k] += x * t.cos1[i];
    ss[k] += x * t.sin1[i];
    sc2[k] += x * t.cos2[i];
    ss2[k] += x * t.sin2[i];
  }
  auto total = [](const double (&a)[kLanes]) { return (a[0] + a[1]) + (a[2] + a[3]); };
  return {total(s0), total(sc), total(ss), total(sc2), total(ss2)};
}

}  // namespace

void TexelCounts::merge_after(const TexelCounts& later) noexcept {
  if (nonfinite == 0 && later.nonfinite != 0) {
    first_nonfinite_x = later.first_nonfinite_x;
    first_nonfinite_y = later.first_nonfinite_y;
  }
  nonfinite += later.nonfinite;
  negative += later.negative;
  max_value = std::max(max_value, later.max_value);
}

void row_column_sums(const ImageView& row, std::uint32_t y, const ProjectOptions& options,
                     const ColumnTables& columns, std::span<float> scratch,
                     TexelCounts& counts, ColumnSums (&sums)[3]) noexcept {
  if (row.type == PixelType::F32) {
    load_row<PixelType::F32>(row, y, options, scratch, counts);
  } else {
    load_row<PixelType::F16>(row, y, options, scratch, counts);
  }
  for (int c = 0; c < 3; ++c) sums[c] = plane_sums(scratch.data() + c * row.width, columns, row.width);
}

}  // namespace shpack::detail
