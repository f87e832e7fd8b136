#include "shpack/io/exr_writer.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <string>

#include "shpack/io/atomic_write.h"

namespace shpack::io {
namespace {

// OpenEXR's output stream into memory, so that the file itself is written atomically.
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    const auto end = static_cast<std::size_t>(position_) + static_cast<std::size_t>(n);
    if (bytes_.size() < end) bytes_.resize(end);
    std::memcpy(bytes_.data() + position_, c, static_cast<std::size_t>(n));
    position_ = end;
  }
  std::uint64_t tellp() override { return position_; }
  void seekp(std::uint64_t pos) override { position_ = pos; }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
  std::uint64_t position_ = 0;
};

}  // namespace

IoStatus write_exr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                   const std::vector<std::string>& channels, const std::vector<float>& pixels) {
  const std::size_t n = channels.size();
  if (width == 0 || height == 0 || n == 0 || pixels.size() != n * width * height)
    return IoStatus::error(IoErrc::InvalidArgument, path, "the image's size does not match its pixels");
  MemoryStream stream;
  try {
    Imf::Header header(static_cast<int>(width), static_cast<int>(height));
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    const std::size_t xs = n * sizeof(float), ys = xs * width;
    for (std::size_t c = 0; c < n; ++c) {
      header.channels().insert(channels[c], Imf::Channel(Imf::FLOAT));
      // OpenEXR's slices take a writable pointer even for output; it only reads through it.
      char* base = const_cast<char*>(reinterpret_cast<const char*>(pixels.data() + c));
      frame.insert(channels[c], Imf::Slice(Imf::FLOAT, base, xs, ys));
    }
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(static_cast<int>(height));
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::WriteFailed, path, std::string("OpenEXR: ") + e.what());
  }
  return write_file_atomically(path, stream.bytes());
}

IoStatus write_exr_rgb(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                       const std::vector<float>& rgb) {
  return write_exr(path, width, height, {"R", "G", "B"}, rgb);
}

}  // namespace shpack::io
