// libFuzzer target: shpack's own readers of Radiance pictures and PFM (lib/io/src/hdr_decoder.h,
// pfm_decoder.h) given arbitrary files, opened as lib/io opens every image (image_open.h: by
// magic number, under a budget of 2^16 texels) and read in bands in an order the input
// chooses, as the streamed projector and the whole-image readers ask for them, and backwards.
// The first byte chooses the reads: bits 0-1 the band's rows less one (1 to 4), bit 2 bands
// from the bottom up, bit 3 the channels (the last, then the first) instead of all; the rest
// is the file, written to a scratch folder in /dev/shm. Inputs that do not start with a
// Radiance or PFM magic line are skipped: other formats are fuzz_image_header's.
// Properties: no crash, no sanitizer report, no exception out of the readers, no run past the
// RSS limit or libFuzzer's timeout (so no RLE run writes past a scanline and no header's
// claim is allocated unchecked); a failure to open is one line that starts with the file's
// name.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_scratch.h"
#include "hdr_decoder.h"
#include "image_open.h"
#include "pfm_decoder.h"

namespace {

namespace fs = std::filesystem;
using shpack::io::detail::ImageDecoder;

constexpr std::uint64_t kFuzzMaxTexels = std::uint64_t{1} << 16;

const fs::path& scratch() {
  static const fs::path dir = shpack_fuzz::make_scratch("float_maps");
  return dir;
}

// Reads every row of part 0 once, in bands of `rows`, top down or bottom up.
void read_bands(ImageDecoder& decoder, long long rows, bool upwards, const std::vector<int>& channels) {
  const shpack::io::detail::PixelWindow& data = decoder.parts().at(0).data;
  if (static_cast<std::uint64_t>(data.width) * static_cast<std::uint64_t>(data.height) > kFuzzMaxTexels) std::abort();
  std::vector<float> band(static_cast<std::size_t>(data.width * rows) * channels.size());
  std::string error;
  for (long long k = 0; k * rows < data.height; ++k) {
    const long long first = upwards ? std::max(0LL, data.height - (k + 1) * rows) : k * rows;
    const long long end = upwards ? data.height - k * rows : std::min(data.height, first + rows);
    if (!decoder.read_rows(0, data.y + first, data.y + end, channels, band.data(), error)) return;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view file(reinterpret_cast<const char*>(data + 1), size - 1);
  if (!shpack::io::detail::is_radiance_magic(file) && !shpack::io::detail::is_pfm_magic(file)) return 0;
  const fs::path path = scratch() / "in.map";
  shpack_fuzz::write_input(path, data + 1, size - 1);

  std::unique_ptr<ImageDecoder> decoder;
  const shpack::io::IoStatus st = shpack::io::detail::open_image(path, {kFuzzMaxTexels, 1}, decoder);
  if (!st.ok()) {
    if (decoder || st.message.rfind(path.string() + ": ", 0) != 0 || st.message.find('\n') != std::string::npos)
      std::abort();
    return 0;
  }
  if (!decoder || decoder->parts().size() != 1) std::abort();
  const std::size_t file_channels = decoder->parts()[0].channels.size();
  const std::vector<int> channels =
      (data[0] & 8) != 0 ? std::vector<int>{static_cast<int>(file_channels) - 1, 0} : std::vector<int>{0, 1, 2};
  read_bands(*decoder, 1 + (data[0] & 3), (data[0] & 4) != 0,
             file_channels == 3 || (data[0] & 8) != 0 ? channels : std::vector<int>{0});
  return 0;
}
