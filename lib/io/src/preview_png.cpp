#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string_view>

#include "shpack/io/atomic_write.h"
#include "shpack/io/preview.h"

namespace shpack::io {

IoStatus write_png(const std::filesystem::path& path, const Rgb8Image& image) {
  try {
    // Encoded in memory (an OpenImageIO IOProxy), then written whole by write_file_atomically.
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    const std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create("png");
    if (!out) return IoStatus::error(IoErrc::WriteFailed, path, "no PNG writer (" + OIIO::geterror() + ")");
    OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    spec.attribute("png:compressionLevel", 9);  // the gallery keeps its images small
    if (!out->set_ioproxy(&memory) || !out->open(path.string(), spec) ||
        !out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data()) || !out->close()) {
      return IoStatus::error(IoErrc::WriteFailed, path, "cannot encode the PNG (" + out->geterror() + ")");
    }
    return write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::WriteFailed, path, e.what());
  }
}

}  // namespace shpack::io
