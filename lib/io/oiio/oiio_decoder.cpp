// The OpenImageIO module's reader (oiio_plugin_abi.h): every format OpenImageIO reads, for
// the files that are not OpenEXR (image_open.h sends those to OpenEXR itself).
#include <fcntl.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <exception>
#include <memory>

#include "oiio_plugin_abi.h"
#include "pixel_transfer.h"
#include "quiet_libpng.h"

namespace shpack::io::detail {
namespace {

// Whether `path` starts with PNG's signature: then every call into OpenImageIO goes through
// QuietLibpng, from the open on (the format is not known before it).
bool starts_as_png(const char* path) {
  static constexpr std::array<unsigned char, 8> kPng = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) return false;
  std::array<unsigned char, 8> head{};
  const ssize_t got = ::read(fd, head.data(), head.size());
  ::close(fd);
  return got == static_cast<ssize_t>(head.size()) && head == kPng;
}

ImagePart describe(const OIIO::ImageSpec& spec, std::string_view format) {
  ImagePart part;
  part.name = spec.get_string_attribute("oiio:subimagename");
  part.channels = spec.channelnames;
  part.channels.resize(static_cast<std::size_t>(std::max(0, spec.nchannels)));
  part.data = {spec.x, spec.y, spec.width, spec.height};
  // OpenImageIO fills the "full" window with the data window for formats without one.
  part.display = spec.full_width > 0 && spec.full_height > 0
                     ? PixelWindow{spec.full_x, spec.full_y, spec.full_width, spec.full_height}
                     : part.data;
  part.srgb = spec.nchannels > 0 && srgb_encoded(spec, format);
  if (spec.deep) part.problem = "the image holds deep data, not an environment map";
  if (spec.depth > 1) part.problem = "the image is a volume, not an environment map";
  return part;
}

class OiioDecoder final : public ImageDecoder {
 public:
  OiioDecoder(std::unique_ptr<OIIO::ImageInput> in, bool png) : in_(std::move(in)), png_(png) {
    format_ = in_->format_name();
    for (int s = 0;; ++s) {
      const OIIO::ImageSpec spec = in_->spec(s);
      if (spec.format == OIIO::TypeUnknown) break;
      specs_.push_back(spec);
      parts_.push_back(describe(spec, format_));
    }
  }

  const std::string& format() const noexcept override { return format_; }
  const std::vector<ImagePart>& parts() const noexcept override { return parts_; }
  void set_threads(unsigned threads) override { in_->threads(static_cast<int>(threads)); }

  bool read_rows(std::size_t part, long long y_begin, long long y_end, std::span<const int> channels, float* out,
                 std::string& error) override {
    const OIIO::ImageSpec& spec = specs_[part];
    const int subimage = static_cast<int>(part);
    const int first = *std::min_element(channels.begin(), channels.end());
    const int last = *std::max_element(channels.begin(), channels.end()) + 1;
    const QuietLibpng quiet(png_);
    bool in_order = last - first == static_cast<int>(channels.size());
    for (std::size_t k = 0; k < channels.size(); ++k) in_order = in_order && channels[k] == first + static_cast<int>(k);
    if (spec.tile_width == 0 && in_order) {
      if (in_->read_scanlines(subimage, 0, static_cast<int>(y_begin), static_cast<int>(y_end), spec.z, first, last,
                              OIIO::TypeDesc::FLOAT, out))
        return true;
      error = in_->geterror();
      return false;
    }
    // Tiled files are read by whole tile rows (OpenImageIO 2.4's read_scanlines fails on
    // tiled files whose data window is offset); the rows wanted start `skip` rows in.
    long long band_begin = y_begin, band_end = y_end;
    if (spec.tile_width != 0) {
      const long long th = spec.tile_height;
      band_begin = spec.y + (y_begin - spec.y) / th * th;
      band_end = std::min<long long>(spec.y + (y_end - spec.y + th - 1) / th * th,
                                     static_cast<long long>(spec.y) + spec.height);
    }
    const std::size_t range = static_cast<std::size_t>(last - first);
    const std::size_t row = static_cast<std::size_t>(spec.width) * range;
    scratch_.resize(row * static_cast<std::size_t>(band_end - band_begin));
    const bool read =
        spec.tile_width != 0
            ? in_->read_tiles(subimage, 0, spec.x, spec.x + spec.width, static_cast<int>(band_begin),
                              static_cast<int>(band_end), spec.z, spec.z + std::max(1, spec.depth), first, last,
                              OIIO::TypeDesc::FLOAT, scratch_.data())
            : in_->read_scanlines(subimage, 0, static_cast<int>(y_begin), static_cast<int>(y_end), spec.z, first,
                                  last, OIIO::TypeDesc::FLOAT, scratch_.data());
    if (!read) {
      error = in_->geterror();
      return false;
    }
    const std::size_t skip = static_cast<std::size_t>(y_begin - band_begin);
    const std::size_t texels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(y_end - y_begin);
    const float* src = scratch_.data() + skip * row;
    for (std::size_t t = 0; t < texels; ++t)
      for (std::size_t k = 0; k < channels.size(); ++k)
        out[t * channels.size() + k] = src[t * range + static_cast<std::size_t>(channels[k] - first)];
    return true;
  }

 private:
  std::unique_ptr<OIIO::ImageInput> in_;
  bool png_ = false;  // read through QuietLibpng
  std::string format_;
  std::vector<OIIO::ImageSpec> specs_;
  std::vector<ImagePart> parts_;
  std::vector<float> scratch_;  // a band of data rows, when they cannot be read in place
};

}  // namespace
}  // namespace shpack::io::detail

extern "C" int shpack_oiio_abi() { return shpack::io::detail::kOiioPluginAbi; }

extern "C" shpack::io::detail::ImageDecoder* shpack_oiio_open(const char* path, std::string* error) {
  using namespace shpack::io::detail;
  try {
    const bool png = starts_as_png(path);
    // Colour is wanted as stored: PNG/TIFF readers would otherwise premultiply it by alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> in;
    {
      const QuietLibpng quiet(png);
      in = OIIO::ImageInput::open(path, &config);
    }
    if (!in) {
      *error = OIIO::geterror();
      return nullptr;
    }
    return new OiioDecoder(std::move(in), png);
  } catch (const std::exception& e) {
    *error = e.what();
    return nullptr;
  }
}
