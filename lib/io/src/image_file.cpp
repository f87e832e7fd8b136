#include "shpack/io/image_file.h"

#include <new>

#include "image_source.h"

namespace shpack::io {

namespace detail {

IoStatus read_image_file(const std::filesystem::path& path, const std::string& layer, const TexelBudget& budget,
                         ImageFile& out) {
  try {
    ImageSource source;
    if (IoStatus st = source.open(path, layer, budget); !st.ok()) return st;
    ImageFile image;
    image.width = source.width();
    image.height = source.height();
    image.file_channels = source.file_channels();
    image.channels = source.channels();
    image.format = source.format();
    image.srgb_decoded = source.srgb_decoded();
    image.chromaticities = source.chromaticities();
    image.pixels.resize(std::size_t{image.width} * image.height * image.channels);
    if (IoStatus st = source.read_rows(0, image.height, image.pixels.data()); !st.ok()) return st;
    out = std::move(image);
    return IoStatus::success();
  } catch (const std::bad_alloc&) {
    return IoStatus::error(IoErrc::Unreadable, path, "out of memory while reading");
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Unreadable, path, e.what());
  }
}

}  // namespace detail

IoStatus read_image_file(const std::filesystem::path& path, const std::string& layer, std::uint64_t max_texels,
                         ImageFile& out) {
  return detail::read_image_file(path, layer, detail::TexelBudget{max_texels, 1}, out);
}

IoStatus read_image_file(const std::filesystem::path& path, const std::string& layer, ImageFile& out) {
  return read_image_file(path, layer, kDefaultMaxTexels, out);
}

}  // namespace shpack::io
