#include "exr_decoder.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <mutex>
#include <string_view>
#include <thread>
#include <tuple>

namespace shpack::io::detail {
namespace {

unsigned cores() { return std::max(1u, std::thread::hardware_concurrency()); }

PixelWindow window_of(const Imath::Box2i& box) {
  return {box.min.x, box.min.y, static_cast<long long>(box.max.x) - box.min.x + 1,
          static_cast<long long>(box.max.y) - box.min.y + 1};
}

// OpenEXR lists channels alphabetically; within each layer R, G, B, A come first, in that
// order, as OpenImageIO listed them, so that messages name a file's channels as before.
void order_channels(std::vector<std::string>& names) {
  const auto key = [](const std::string& name) {
    const std::size_t dot = name.rfind('.');
    const std::string layer = dot == std::string::npos ? std::string() : name.substr(0, dot);
    const std::string base = dot == std::string::npos ? name : name.substr(dot + 1);
    const std::size_t rank = std::string_view("RGBA").find(base.size() == 1 ? base[0] : '\0');
    return std::tuple(layer, std::min<std::size_t>(rank, 4), base);
  };
  std::stable_sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) { return key(a) < key(b); });
}

ImagePart describe(const Imf::Header& header) {
  ImagePart part;
  if (header.hasName()) part.name = header.name();
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it) part.channels.emplace_back(it.name());
  order_channels(part.channels);
  part.data = window_of(header.dataWindow());
  part.display = window_of(header.displayWindow());
  if (part.display.width <= 0 || part.display.height <= 0) part.display = part.data;  // as OpenImageIO did
  if (header.hasType() && Imf::isDeepData(header.type())) part.problem = "the image holds deep data, not an environment map";
  if (Imf::hasChromaticities(header)) {
    const Imf::Chromaticities& c = Imf::chromaticities(header);
    part.chromaticities = std::array<double, 8>{c.red.x, c.red.y, c.green.x, c.green.y,
                                                c.blue.x, c.blue.y, c.white.x, c.white.y};
  }
  return part;
}

// uint samples as OpenImageIO converts them to float: value times 1 / (2^32 - 1), in float.
float uint_to_float(std::uint32_t v) {
  constexpr float kScale = 1.0f / 4294967295.0f;
  return static_cast<float>(v) * kScale;
}

class ExrDecoder final : public ImageDecoder {
 public:
  // As many line buffers as cores, so that any thread count set later can use them all.
  explicit ExrDecoder(const std::filesystem::path& path) : file_(path.c_str(), static_cast<int>(cores())) {
    for (int p = 0; p < file_.parts(); ++p) parts_.push_back(describe(file_.header(p)));
    inputs_.resize(parts_.size());
  }

  const std::string& format() const noexcept override { return format_; }
  const std::vector<ImagePart>& parts() const noexcept override { return parts_; }

  void set_threads(unsigned threads) override {
    // The pool is the process's: it only grows, so files decoded side by side (convert's
    // batches) never shrink it under one another.
    static std::mutex mutex;
    const std::lock_guard<std::mutex> lock(mutex);
    const int wanted = static_cast<int>(threads != 0 ? threads : cores());
    if (Imf::globalThreadCount() < wanted) Imf::setGlobalThreadCount(wanted);
  }

  bool read_rows(std::size_t part, long long y_begin, long long y_end, std::span<const int> channels, float* out,
                 std::string& error) override {
    try {
      const Imf::Header& header = file_.header(static_cast<int>(part));
      const PixelWindow& data = parts_[part].data;
      const Imath::Box2i band(Imath::V2i(static_cast<int>(data.x), static_cast<int>(y_begin)),
                              Imath::V2i(static_cast<int>(data.x + data.width - 1), static_cast<int>(y_end - 1)));
      const std::size_t x_stride = channels.size() * sizeof(float);
      const std::size_t y_stride = x_stride * static_cast<std::size_t>(data.width);
      Imf::FrameBuffer frame;
      bool any_uint = false;
      for (std::size_t k = 0; k < channels.size(); ++k) {
        const std::string& name = parts_[part].channels[static_cast<std::size_t>(channels[k])];
        const Imf::Channel& channel = header.channels()[name];
        if (channel.xSampling != 1 || channel.ySampling != 1) {
          error = "channel '" + name.substr(0, 64) + "' is subsampled, which shpack does not read";
          return false;
        }
        // uint is read as uint (4 bytes, in place) and scaled below; half and float as float.
        const Imf::PixelType type = channel.type == Imf::UINT ? Imf::UINT : Imf::FLOAT;
        any_uint = any_uint || type == Imf::UINT;
        frame.insert(name, Imf::Slice::Make(type, out + k, band, x_stride, y_stride));
      }
      Imf::InputPart& input = this->input(part);
      input.setFrameBuffer(frame);
      input.readPixels(static_cast<int>(y_begin), static_cast<int>(y_end - 1));
      if (any_uint) scale_uint(part, channels, out, static_cast<std::size_t>(data.width * (y_end - y_begin)));
      return true;
    } catch (const std::exception& e) {
      error = e.what();
      return false;
    }
  }

 private:
  Imf::InputPart& input(std::size_t part) {
    if (!inputs_[part]) inputs_[part] = std::make_unique<Imf::InputPart>(file_, static_cast<int>(part));
    return *inputs_[part];
  }

  void scale_uint(std::size_t part, std::span<const int> channels, float* out, std::size_t texels) const {
    const Imf::ChannelList& list = file_.header(static_cast<int>(part)).channels();
    for (std::size_t k = 0; k < channels.size(); ++k) {
      if (list[parts_[part].channels[static_cast<std::size_t>(channels[k])]].type != Imf::UINT) continue;
      for (std::size_t t = 0; t < texels; ++t) {
        float& value = out[t * channels.size() + k];
        std::uint32_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        value = uint_to_float(bits);
      }
    }
  }

  Imf::MultiPartInputFile file_;
  std::string format_ = "openexr";
  std::vector<ImagePart> parts_;
  std::vector<std::unique_ptr<Imf::InputPart>> inputs_;  // made on first read
};

}  // namespace

std::unique_ptr<ImageDecoder> open_exr(const std::filesystem::path& path, std::string& error) {
  try {
    return std::make_unique<ExrDecoder>(path);
  } catch (const std::exception& e) {
    error = e.what();
    return nullptr;
  }
}

}  // namespace shpack::io::detail
