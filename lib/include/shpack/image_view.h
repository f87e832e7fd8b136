// image_view.h - a non-owning, strided, read-only view of caller pixels.
//
// The idea of OpenImageIO's image_span, cut down to what projection needs: an importer
// hands over memory it already holds and shpack reads it in place, never copying it.
//
//   data --> +-----------------------------------+   row 0 (top)
//            | p(0,0) p(1,0) ... p(width-1,0)    |   pixel_stride bytes between pixels
//            +-----------------------------------+   row_stride bytes between rows
//            | p(0,1) ...                        |   (either may be negative: a view of
//            +-----------------------------------+    a bottom-up or mirrored image)
//
// Each pixel holds `channels` values of `type`: 1 = grey, 2 = grey + alpha, 3 = RGB,
// 4 or more = RGB and ignored extra channels. Strides default (kAutoStride) to a tightly
// packed image. Values are linear radiance; the core never applies a transfer function.
#pragma once

#include <cstddef>
#include <cstdint>

#include "shpack/status.h"

namespace shpack {

enum class PixelType : std::uint8_t {
  F32,  // IEEE binary32
  F16,  // IEEE binary16 ("half", as in OpenEXR)
};

constexpr std::int64_t pixel_type_size(PixelType t) noexcept { return t == PixelType::F32 ? 4 : 2; }

inline constexpr std::int64_t kAutoStride = INT64_MIN;

struct ImageView {
  const std::byte* data = nullptr;
  PixelType type = PixelType::F32;
  std::uint32_t width = 0, height = 0, channels = 0;
  std::int64_t pixel_stride = kAutoStride;  // bytes from one pixel to the next in a row
  std::int64_t row_stride = kAutoStride;    // bytes from one row to the next

  // Address of pixel (x, y). Valid only on a resolved view (resolve_view).
  const std::byte* pixel(std::uint32_t x, std::uint32_t y) const noexcept {
    return data + static_cast<std::int64_t>(y) * row_stride +
           static_cast<std::int64_t>(x) * pixel_stride;
  }
  // The view of rows [first, first + count) of this resolved view.
  ImageView rows(std::uint32_t first, std::uint32_t count) const noexcept {
    ImageView v = *this;
    v.data = pixel(0, first);
    v.height = count;
    return v;
  }
};

// Fill in default strides and check the view: non-null data, width, height and channels
// of at least 1, a pixel stride that covers its channels, and rows that do not overlap.
// The one place where defaults and strides are decided.
Status resolve_view(ImageView& view) noexcept;

// A convenience for callers with a tightly packed float RGB(A) buffer.
inline ImageView make_view(const float* data, std::uint32_t width, std::uint32_t height,
                              std::uint32_t channels) noexcept {
  return {reinterpret_cast<const std::byte*>(data), PixelType::F32, width, height, channels,
          kAutoStride, kAutoStride};
}

// IEEE binary16 -> binary32, exact for every half value including subnormals, Inf, NaN.
float half_to_float(std::uint16_t h) noexcept;

}  // namespace shpack
