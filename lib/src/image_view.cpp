#include "shpack/image_view.h"

#include <bit>
#include <cstdlib>

namespace shpack {

Status resolve_view(ImageView& view) noexcept {
  if (view.data == nullptr) return Status::error(Errc::BadView, "image data is null");
  if (view.width == 0 || view.height == 0) return Status::error(Errc::BadView, "image has zero size");
  if (view.channels == 0) return Status::error(Errc::BadView, "image has no channels");
  if (view.type != PixelType::F32 && view.type != PixelType::F16)
    return Status::error(Errc::BadView, "unknown pixel type");
  const std::int64_t value_bytes = pixel_type_size(view.type);
  const std::int64_t pixel_bytes = value_bytes * view.channels;
  if (view.pixel_stride == kAutoStride) view.pixel_stride = pixel_bytes;
  // Rows are at least |pixel_stride| * width apart; a 2^31 x 2^31 view of 4 KiB pixels
  // still fits in int64, so these products cannot overflow for any uint32 size.
  const std::int64_t row_extent = std::llabs(view.pixel_stride) * view.width;
  if (view.row_stride == kAutoStride) view.row_stride = row_extent;
  if (std::llabs(view.pixel_stride) < pixel_bytes && view.width > 1)
    return Status::error(Errc::BadView, "pixel stride is smaller than a pixel: pixels overlap");
  if (std::llabs(view.row_stride) < row_extent && view.height > 1)
    return Status::error(Errc::BadView, "row stride is smaller than a row: rows overlap");
  return Status::success();
}

// IEEE 754 binary16 -> binary32. A half is 1 sign, 5 exponent (bias 15), 10 mantissa
// bits; normal halves and Inf/NaN map by rebiasing the exponent (bias 127), subnormal
// halves (exponent 0) are mantissa * 2^-24, which binary32 represents exactly.
float half_to_float(std::uint16_t h) noexcept {
  const std::uint32_t sign = static_cast<std::uint32_t>(h & 0x8000u) << 16;
  const std::uint32_t exponent = (h >> 10) & 0x1fu;
  const std::uint32_t mantissa = h & 0x3ffu;
  if (exponent == 0) {
    const float magnitude = static_cast<float>(mantissa) * 0x1p-24f;
    return sign ? -magnitude : magnitude;
  }
  const std::uint32_t bits = exponent == 0x1f
                                 ? sign | 0x7f800000u | (mantissa << 13)
                                 : sign | ((exponent + (127 - 15)) << 23) | (mantissa << 13);
  return std::bit_cast<float>(bits);
}

}  // namespace shpack
