#include "shpack/image_view.h"

#include <bit>
#include <cstdint>

namespace shpack {
namespace {

constexpr std::uint64_t kMaxBytes = INT64_MAX;

// |s| in uint64: defined for every int64, INT64_MIN included (std::llabs is not).
constexpr std::uint64_t magnitude(std::int64_t s) noexcept {
  return s < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(s) : static_cast<std::uint64_t>(s);
}

}  // namespace

Status resolve_view(ImageView& view) noexcept {
  if (view.data == nullptr) return Status::error(Errc::BadView, "image data is null");
  if (view.width == 0 || view.height == 0) return Status::error(Errc::BadView, "image has zero size");
  if (view.channels == 0) return Status::error(Errc::BadView, "image has no channels");
  if (view.type != PixelType::F32 && view.type != PixelType::F16)
    return Status::error(Errc::BadView, "unknown pixel type");
  const std::int64_t value_bytes = pixel_type_size(view.type);
  const std::int64_t pixel_bytes = value_bytes * view.channels;
  if (view.pixel_stride == kAutoStride) view.pixel_stride = pixel_bytes;
  // Every byte offset pixel() can form, |row_stride| (height - 1) + |pixel_stride| (width - 1),
  // must fit in int64: strides come from the caller, so the products are checked in uint64
  // before they are formed (an unchecked |stride| * width is signed overflow for a stride
  // of 2^62 and a width of 4).
  const std::uint64_t pixel_step = magnitude(view.pixel_stride);
  if (pixel_step > kMaxBytes / view.width)
    return Status::error(Errc::BadView, "pixel stride is too large: a row does not fit in int64 bytes");
  const std::uint64_t row_extent = pixel_step * view.width;
  if (view.row_stride == kAutoStride) view.row_stride = static_cast<std::int64_t>(row_extent);
  const std::uint64_t row_step = magnitude(view.row_stride);
  if (pixel_step < static_cast<std::uint64_t>(pixel_bytes) && view.width > 1)
    return Status::error(Errc::BadView, "pixel stride is smaller than a pixel: pixels overlap");
  if (row_step < row_extent && view.height > 1)
    return Status::error(Errc::BadView, "row stride is smaller than a row: rows overlap");
  const std::uint64_t last_pixel = pixel_step * (view.width - 1);
  if (view.height > 1 && row_step > (kMaxBytes - last_pixel) / (view.height - 1))
    return Status::error(Errc::BadView, "row stride is too large: the image does not fit in int64 bytes");
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
