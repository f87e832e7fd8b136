#include <string_view>
#include <vector>

#include "oiio_plugin.h"
#include "shpack/io/atomic_write.h"
#include "shpack/io/preview.h"

namespace shpack::io {

IoStatus write_png(const std::filesystem::path& path, const Rgb8Image& image) {
  // Encoded in memory by the OpenImageIO module, then written whole by write_file_atomically.
  std::string problem;
  const detail::OiioPlugin* plugin = detail::oiio_plugin(problem);
  if (plugin == nullptr) return IoStatus::error(IoErrc::WriteFailed, path, "PNG is written through OpenImageIO: " + problem);
  std::vector<unsigned char> bytes;
  if (!plugin->encode_png(image.width, image.height, image.pixels.data(), &bytes, &problem))
    return IoStatus::error(IoErrc::WriteFailed, path, problem);
  return write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace shpack::io
