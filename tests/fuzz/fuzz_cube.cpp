// libFuzzer target: project_cube given six arbitrary faces (each its own size, pixel type,
// channel count, strides and values, inside the fuzzer's buffers), and
// cube_texel_basis_integrals given arbitrary sizes, texels, faces and methods.
// Properties: no crash, no sanitizer report; the Status is what project_cube.h promises
// (BadView naming the first bad face; NonFiniteTexel only under NonFinite::Error; otherwise
// finite coefficients, counts that fit, the same bits with 1 and 2 threads); a texel's nine
// integrals are finite and bounded by max |Y_i| times the texel's positive solid angle.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "shpack/project_cube.h"
#include "fuzz_reader.h"

namespace {

using shpack_fuzz::Reader;

void fuzz_texel_integrals(Reader& in) {
  const std::uint32_t size = in.take32(), x = in.take32(), y = in.take32(), face = in.take(8);
  const auto method = static_cast<shpack::SamplingMethod>(in.take(3));
  std::array<double, shpack::kShCount> out{};
  const shpack::Status st = shpack::cube_texel_basis_integrals(size, static_cast<shpack::CubeFace>(face), x, y, method, out);
  const bool valid = size != 0 && x < size && y < size && face < 6 &&
                     (method == shpack::SamplingMethod::Exact || method == shpack::SamplingMethod::Center);
  if (st.ok() != valid) std::abort();
  if (!st.ok()) return;
  // The texel's solid angle is positive and at most a face (2 pi / 3 = 2.09): its relative
  // error is ~10 u / h = 5 u N (project_cube.h), < 3e-6 even at N = 2^32 - 1. Every
  // |int Y_i| <= max |Y_i| Omega <= 0.64 Omega (k3 max|3z^2 - 1| = 0.63).
  const double omega = out[0] / shpack::kBasisScale[0];
  if (!(omega > 0 && omega <= 2.1)) std::abort();
  for (int i = 0; i < shpack::kShCount; ++i)
    if (!std::isfinite(out[i]) || std::fabs(out[i]) > 0.64 * omega * (1 + 1e-5)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Reader in{data, size};
  if (in.take(8) == 7) {  // one input in 8: a single texel's integrals
    fuzz_texel_integrals(in);
    return 0;
  }
  const std::uint32_t n = in.take(12);  // 0 is a bad size
  shpack::ProjectOptions options;
  options.method = static_cast<shpack::SamplingMethod>(in.take(3));  // 2 is not a method
  options.nonfinite = in.take(2) == 0 ? shpack::NonFinite::Error : shpack::NonFinite::Zero;
  options.negative = in.take(2) == 0 ? shpack::Negative::Keep : shpack::Negative::Clamp;

  std::array<std::vector<std::byte>, 6> buffers;
  std::array<shpack::ImageView, 6> faces;
  for (int f = 0; f < 6; ++f) {
    shpack::ImageView& v = faces[f];
    const std::uint32_t odd = in.take(16);  // now and then a face of another size or shape
    v.width = odd == 1 ? n + 1 : n;
    v.height = odd == 2 ? n + 1 : odd == 3 && n > 0 ? n - 1 : n;
    v.channels = in.take(6);
    v.type = in.take(2) == 0 ? shpack::PixelType::F32 : shpack::PixelType::F16;
    const std::int64_t value = shpack::pixel_type_size(v.type);
    std::int64_t ps = (static_cast<std::int64_t>(in.take(9)) - 2) * value;
    if (ps == 0) ps = value * std::max<std::uint32_t>(v.channels, 1);
    const std::int64_t row_extent = std::llabs(ps) * v.width + static_cast<std::int64_t>(in.take(4)) * value;
    const bool flip = in.take(2) == 1;
    buffers[f].resize(static_cast<std::size_t>(row_extent * std::max<std::uint32_t>(v.height, 1) + 64));
    std::int64_t origin = ps < 0 ? -ps * (static_cast<std::int64_t>(v.width) - 1) : 0;
    if (flip) origin += row_extent * (static_cast<std::int64_t>(v.height) - 1);
    v.pixel_stride = ps;
    v.row_stride = flip ? -row_extent : row_extent;
    v.data = v.width == 0 || v.height == 0 ? nullptr : buffers[f].data() + origin;
  }
  // Pixel bytes: the rest of the input, repeated.
  std::size_t k = 0;
  for (auto& b : buffers)
    for (std::byte& byte : b) byte = in.size ? static_cast<std::byte>(in.data[k++ % in.size]) : std::byte{0};

  // What project_cube.h promises, face by face.
  int first_bad = -1;
  for (int f = 0; f < 6 && first_bad < 0; ++f) {
    shpack::ImageView r = faces[f];
    if (!shpack::resolve_view(r).ok() || r.width != r.height || r.width != faces[0].width) first_bad = f;
  }
  const bool method_ok = options.method == shpack::SamplingMethod::Exact || options.method == shpack::SamplingMethod::Center;

  shpack::ShL2 sh;
  shpack::ProjectStats stats;
  options.threads = 1;
  const shpack::Status st = shpack::project_cube(faces, options, sh, &stats);
  if (!method_ok) {
    if (st.code != shpack::Errc::InvalidArgument) std::abort();
    return 0;
  }
  if (first_bad >= 0) {
    if (st.code != shpack::Errc::BadView || st.face != static_cast<std::uint32_t>(first_bad)) std::abort();
    return 0;
  }
  if (!st.ok()) {
    if (st.code != shpack::Errc::NonFiniteTexel || options.nonfinite != shpack::NonFinite::Error || st.face >= 6 ||
        st.x >= n || st.y >= n)
      std::abort();
    return 0;
  }
  for (const auto& channel : sh.c)
    for (double c : channel)
      if (!std::isfinite(c)) std::abort();
  if (stats.nonfinite_texels > 6ull * n * n || stats.negative_texels > 6ull * n * n || !(stats.max_value >= 0)) std::abort();
  options.threads = 2;
  shpack::ShL2 two;
  if (!shpack::project_cube(faces, options, two).ok() || std::memcmp(&two, &sh, sizeof sh) != 0) std::abort();
  return 0;
}
