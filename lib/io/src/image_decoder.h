// image_decoder.h (private) - what a format's reader hands to ImageSource (image_source.h):
// the parts of one image file as their headers declare them, and the data rows of a part as
// float. Four readers implement it: OpenEXR's (exr_decoder.h), shpack's own Radiance .hdr
// and PFM readers (hdr_decoder.h, pfm_decoder.h), all linked into lib/io, and OpenImageIO's
// for every other format (lib/io/oiio, a module opened on first use: oiio_plugin.h). None
// chooses channels or windows: ImageSource does, once, for all.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace shpack::io::detail {

// A window in the file's pixel coordinates: [x, x + width) x [y, y + height).
struct PixelWindow {
  long long x = 0, y = 0, width = 0, height = 0;
  friend bool operator==(const PixelWindow&, const PixelWindow&) = default;
};

// One part (EXR part, OpenImageIO subimage) as its header declares it.
struct ImagePart {
  std::string name;                   // the EXR part's name, "" if it has none
  std::vector<std::string> channels;  // channel names in the reader's order
  PixelWindow data;                   // the pixels the file holds
  PixelWindow display;                // the image (the data window where the format has no other)
  bool srgb = false;                  // integer pixels that are sRGB-encoded (linearised after reading)
  std::string problem;                // why the part is no environment map (deep, a volume), or ""
  std::optional<std::array<double, 8>> chromaticities;  // red x, y, green x, y, blue x, y, white x, y
};

class ImageDecoder {
 public:
  virtual ~ImageDecoder() = default;
  virtual const std::string& format() const noexcept = 0;  // "openexr", "hdr", "png", ...
  virtual const std::vector<ImagePart>& parts() const noexcept = 0;
  // Worker threads for the reads that follow (0: one per core).
  virtual void set_threads(unsigned threads) = 0;
  // Data rows [y_begin, y_end) of parts()[part] (file coordinates, inside its data window),
  // the channels `channels` (indices into its channel names) as float, channels.size() a
  // texel, data.width texels a row, into `out`. False, with the reader's reason in `error`
  // (maybe empty), if they cannot be read.
  virtual bool read_rows(std::size_t part, long long y_begin, long long y_end, std::span<const int> channels,
                         float* out, std::string& error) = 0;
};

}  // namespace shpack::io::detail
