// image_source.h (private) - the pixels of one image file as shpack reads them: the chosen
// part and channels, the display window, linear float.
//
// Which pixels:
//  - Part and channels. Without a layer: subimage 0, its channels named R, G, B (any order in
//    the file), else Y (grey), else its one channel if it has only one and that is unnamed.
//    Nothing else is taken for colour: a part with some of R, G, B but not all ("it has G,
//    R"), or with no colour channel at all (only A, Z, ...), fails naming the channels it
//    has; one whose channels all carry a layer prefix ("diffuse.R") fails listing the
//    layers. (The .hdr and PFM readers name their channels R, G, B or Y; OpenImageIO
//    names those of PNG, TIFF, JPEG R, G, B [, A] or Y [, A].) With a layer NAME: the part (EXR part, OpenImageIO subimage) named NAME, read as above; else the
//    channels NAME.R, NAME.G, NAME.B (or NAME.Y) of the first subimage that has them.
//    Anything else fails and lists the file's layers.
//  - Budget. The display window and the data window, as the header declares them, are each
//    at most TexelBudget::max_texels texels (times TexelBudget::images), checked at open(),
//    before anything is allocated or decoded.
//  - Window. The image is the display window (OpenEXR's displayWindow, OpenImageIO's "full"
//    window); texels outside the data window are black (0), and data outside the display
//    window is not kept.
//  - Values. Converted to float by the format's reader (image_decoder.h; integers as value /
//    max), integer sRGB linearised (pixel_encoding.h), nothing else changed; alpha and other
//    channels dropped.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "image_decoder.h"
#include "image_open.h"
#include "shpack/io/image_file.h"
#include "shpack/io/io_status.h"

namespace shpack::io::detail {

class ImageSource {
 public:
  // Opens `path` and chooses its part and channels. Errors name the file.
  IoStatus open(const std::filesystem::path& path, const std::string& layer, const TexelBudget& budget);

  std::uint32_t width() const noexcept { return width_; }    // display window
  std::uint32_t height() const noexcept { return height_; }
  std::uint32_t channels() const noexcept { return used_; }  // per texel read: 1 (grey) or 3
  std::uint32_t file_channels() const noexcept { return file_channels_; }  // of the chosen part
  std::uint32_t ignored_channels() const noexcept { return file_channels_ - used_; }
  bool srgb_decoded() const noexcept { return srgb_; }
  const std::string& format() const noexcept { return format_; }
  // The EXR "chromaticities" attribute (red x, y, green x, y, blue x, y, white x, y), if any.
  const std::optional<std::array<double, 8>>& chromaticities() const noexcept { return chromaticities_; }
  void set_threads(unsigned threads) { decoder_->set_threads(threads); }

  // Display rows [first, first + count) into `out` (count * width() * channels() floats,
  // row-major). Errors name the file and the rows.
  IoStatus read_rows(std::uint32_t first, std::uint32_t count, float* out);

 private:
  std::filesystem::path path_;
  std::unique_ptr<ImageDecoder> decoder_;
  std::size_t part_ = 0;              // the chosen part
  PixelWindow data_, display_;        // of the chosen part
  std::array<int, 3> channel_{};      // file channel of R, G, B (of grey in [0])
  std::uint32_t width_ = 0, height_ = 0, used_ = 0, file_channels_ = 0;
  bool srgb_ = false;
  std::string format_;
  std::optional<std::array<double, 8>> chromaticities_;
  std::vector<float> scratch_;  // a band of data rows, when they are not the display's
};

// read_image_file (image_file.h) under `budget`.
IoStatus read_image_file(const std::filesystem::path& path, const std::string& layer, const TexelBudget& budget,
                         ImageFile& out);

}  // namespace shpack::io::detail
