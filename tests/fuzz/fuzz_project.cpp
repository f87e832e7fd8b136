// libFuzzer target: the core projection given arbitrary views (sizes, strides, pixel types,
// channel counts, values, band splits, threads). The view always lies inside the fuzzer's
// buffer (a caller's promise the core cannot check); everything else is arbitrary.
// Properties: no crash, no sanitizer report; a view resolve_view rejects is rejected by
// project_equirect too (BadView); an accepted one projects to an error Status only for
// NaN/Inf under NonFinite::Error, and otherwise to finite coefficients, counts that fit the
// image, and the same bits whether streamed in bands or projected in one call (project.h).
// resolve_view also gets arbitrary 64-bit strides (validation only, nothing is read).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "shpack/project.h"
#include "fuzz_reader.h"

namespace {

using shpack_fuzz::Reader;

// resolve_view on any strides and sizes: it only validates (no pixel is read), so the data
// pointer need not cover the view. It must not overflow while checking.
void fuzz_resolve(Reader& in) {
  shpack::ImageView view;
  view.data = reinterpret_cast<const std::byte*>(&in);  // never dereferenced by resolve_view
  view.type = in.take(2) == 0 ? shpack::PixelType::F32 : shpack::PixelType::F16;
  view.width = in.take(0) << 16 | in.take(0);
  view.height = in.take(0) << 16 | in.take(0);
  view.channels = in.take(0);
  view.pixel_stride = in.take64();
  view.row_stride = in.take64();
  (void)shpack::resolve_view(view);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in{data, size};
  if (in.take(16) == 15) {  // one input in 16: the validator alone, with wild strides
    fuzz_resolve(in);
    return 0;
  }
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
  options.method = in.take(2) == 0 ? shpack::SamplingMethod::Exact : shpack::SamplingMethod::Center;
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
    if (shpack::project_equirect(view, options, sh, &stats).code != shpack::Errc::BadView) std::abort();
    return 0;
  }
  shpack::EquirectProjector projector;
  if (!projector.begin(resolved.width, resolved.height, options).ok()) std::abort();  // valid size and method
  for (std::uint32_t y = 0; y < resolved.height; y += band) {
    const std::uint32_t n = std::min(band, resolved.height - y);
    const shpack::Status st = projector.add_rows(resolved.rows(y, n), y);
    if (!st.ok()) {
      // Only NaN/Inf under NonFinite::Error may stop it, at a texel of the rows seen so far.
      if (st.code != shpack::Errc::NonFiniteTexel || options.nonfinite != shpack::NonFinite::Error) std::abort();
      if (st.y >= y + n || st.x >= resolved.width) std::abort();
      return 0;
    }
  }
  if (!projector.finish(sh, &stats).ok()) std::abort();  // every row was added
  for (const auto& channel : sh.c)
    for (double c : channel)
      if (!std::isfinite(c)) std::abort();  // finite inputs (NaN/Inf zeroed) give finite sums
  const std::uint64_t texels = std::uint64_t{resolved.width} * resolved.height;
  if (stats.nonfinite_texels > texels || stats.negative_texels > texels || !(stats.max_value >= 0)) std::abort();
  if (stats.nonfinite_texels != 0 && (stats.first_nonfinite_x >= resolved.width || stats.first_nonfinite_y >= resolved.height))
    std::abort();
  // Bands and threads never change the result (project.h): one call, one thread.
  shpack::ProjectOptions one = options;
  one.threads = 1;
  shpack::ShL2 again;
  shpack::ProjectStats again_stats;
  if (!shpack::project_equirect(view, one, again, &again_stats).ok()) std::abort();
  if (std::memcmp(&again, &sh, sizeof sh) != 0) std::abort();
  if (again_stats.nonfinite_texels != stats.nonfinite_texels || again_stats.negative_texels != stats.negative_texels)
    std::abort();
  return 0;
}
