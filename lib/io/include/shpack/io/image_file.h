// image_file.h - a whole image file read into memory as float, for the readers that need
// every texel at once outside the pipeline (six face files, the bench, preview --input, the
// bake's environment lookups). The pipeline's own source is map_source.h.
//
// Pixels are decoded exactly as map_source.h describes (float as stored, integer sRGB
// linearised, grey kept as one channel, alpha and extra channels dropped and counted; the
// layer chosen by name; the display window, black outside the data window).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shpack/image_view.h"
#include "shpack/io/io_status.h"

namespace shpack::io {

struct ImageFile {
  std::uint32_t width = 0, height = 0;
  std::uint32_t channels = 0;          // channels kept in `pixels`: 1 (grey) or 3 (RGB)
  std::uint32_t file_channels = 0;     // channels in the file
  bool srgb_decoded = false;           // integer sRGB pixels were linearised
  std::string format;                  // the format's name, as OpenImageIO names it
  std::optional<std::array<double, 8>> chromaticities;  // the file's, if it says (colorspace.h)
  std::vector<float> pixels;           // row-major, top row first, `channels` per texel

  std::uint32_t ignored_channels() const noexcept { return file_channels - channels; }
  // A view of `pixels` (valid while this object lives and `pixels` is not resized).
  ImageView view() const noexcept { return make_view(pixels.data(), width, height, channels); }
};

// The most texels an image may declare, by default (--max-texels, docs/security.md): 2^28,
// twice a 16384x8192 map. The display window and the data window are each checked against
// it from the header, before anything is allocated or decoded.
inline constexpr std::uint64_t kDefaultMaxTexels = std::uint64_t{1} << 28;

// Reads all of `path`: the layer `layer` (image_source.h; "" for the default choice), if
// its header declares at most `max_texels` texels (else Unsupported: "the image is WxH (N
// texels), above the budget of B (--max-texels)"). Errors name the file, as MapSource::open's do.
IoStatus read_image_file(const std::filesystem::path& path, const std::string& layer, std::uint64_t max_texels,
                         ImageFile& out);
// The same, within kDefaultMaxTexels.
IoStatus read_image_file(const std::filesystem::path& path, const std::string& layer, ImageFile& out);
inline IoStatus read_image_file(const std::filesystem::path& path, ImageFile& out) {
  return read_image_file(path, std::string(), out);
}

}  // namespace shpack::io
