// libFuzzer target: the core projection given arbitrary views (sizes, strides, pixel types,
// channel counts, values, band splits, threads). The view always lies inside the fuzzer's
// buffer (a caller's promise the core cannot check); everything else is arbitrary.
// Property: no crash, no sanitizer report, and either an error Status or finite output
// whenever the policy zeroes non-finite texels.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "shpack/project.h"

namespace {

struct Reader {
  const std::uint8_t* data;
  std::size_t size;
  std::uint32_t take(std::uint32_t modulo) {
    std::uint32_t v = 0;
    for (int k = 0; k < 2 && size > 0; ++k, ++data, --size) v = (v << 8) | *data;
    return modulo == 0 ? v : v % modulo;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in{data, size};
  shpack::ImageView view;
  view.width = in.take(40);
  view.height = in.take(24);
  view.channels = in.take(6);
  view.type = in.take(2) == 0 ? shpack::PixelType::F32 : shpack::PixelType::F16;
  const std::int64_t value = shpack::pixel_type_size(view.type);
  const std::int64_t pixel_stride = (static_cast<std::int64_t>(in.take(9)) - 2) * value;  // may be < a pixel or negative
  const std::int64_t row_pad = static_cast<std::int64_t>(in.take(5)) * value;
  const bool flip_rows = in.take(2) == 1;
  shpack::ProjectOptions options;
  options.method = in.take(2) == 0 ? shpack::Method::Exact : shpack::Method::Center;
  options.nonfinite = in.take(2) == 0 ? shpack::NonFinite::Error : shpack::NonFinite::Zero;
  options.negative = in.take(2) == 0 ? shpack::Negative::Keep : shpack::Negative::Clamp;
  options.threads = in.take(4);
  const std::uint32_t band = 1 + in.take(70);

  // Pixel bytes: the rest of the input, repeated to fill a buffer big enough for the view.
  const std::int64_t ps = pixel_stride == 0 ? value * std::max<std::uint32_t>(view.channels, 1) : pixel_stride;
  const std::int64_t row_extent = std::llabs(ps) * view.width + row_pad;
  const std::size_t bytes = static_cast<std::size_t>(row_extent * std::max<std::uint32_t>(view.height, 1) + 64);
  std::vector<std::byte> buffer(bytes);
  for (std::size_t k = 0; k < bytes; ++k)
    buffer[k] = in.size ? static_cast<std::byte>(in.data[k % in.size]) : std::byte{0};
  // Place the origin so that every pixel the strides reach lies inside the buffer.
  std::int64_t origin = ps < 0 ? -ps * (static_cast<std::int64_t>(view.width) - 1) : 0;
  view.pixel_stride = ps;
  view.row_stride = flip_rows ? -row_extent : row_extent;
  if (flip_rows) origin += row_extent * (static_cast<std::int64_t>(view.height) - 1);
  view.data = view.width == 0 || view.height == 0 ? nullptr : buffer.data() + origin;

  shpack::ShL2 sh;
  shpack::ProjectStats stats;
  shpack::ImageView resolved = view;
  if (!shpack::resolve_view(resolved).ok()) {
    (void)shpack::project_equirect(view, options, sh, &stats);  // must fail cleanly
    return 0;
  }
  shpack::EquirectProjector projector;
  if (!projector.begin(resolved.width, resolved.height, options).ok()) return 0;
  for (std::uint32_t y = 0; y < resolved.height; y += band) {
    const std::uint32_t n = std::min(band, resolved.height - y);
    if (!projector.add_rows(resolved.rows(y, n), y).ok()) return 0;
  }
  if (!projector.finish(sh, &stats).ok()) std::abort();  // every row was added
  for (const auto& channel : sh.c)
    for (double c : channel)
      if (!std::isfinite(c)) std::abort();  // finite inputs (NaN/Inf zeroed) give finite sums
  return 0;
}
