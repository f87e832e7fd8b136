#include "shpack/io/image_file.h"

#include <new>
#include <span>

#include "image_open.h"
#include "pixel_encoding.h"

namespace shpack::io {

IoStatus read_image_file(const std::filesystem::path& path, ImageFile& out) {
  try {
    std::unique_ptr<OIIO::ImageInput> in;
    if (IoStatus st = detail::open_image(path, in); !st.ok()) return st;
    const OIIO::ImageSpec& spec = in->spec();
    if (const std::string problem = detail::spec_problem(spec); !problem.empty())
      return IoStatus::error(IoErrc::Unsupported, path, problem);
    ImageFile image;
    image.width = static_cast<std::uint32_t>(spec.width);
    image.height = static_cast<std::uint32_t>(spec.height);
    image.file_channels = static_cast<std::uint32_t>(spec.nchannels);
    image.channels = image.file_channels >= 3 ? 3 : 1;
    image.format = in->format_name();
    image.srgb_decoded = detail::pixel_transfer(spec, image.format) == detail::Transfer::Srgb;
    image.pixels.resize(std::size_t{image.width} * image.height * image.channels);
    if (!in->read_image(0, 0, 0, static_cast<int>(image.channels), OIIO::TypeDesc::FLOAT,
                        image.pixels.data())) {
      return IoStatus::error(IoErrc::Unreadable, path, "cannot read the pixels (" + in->geterror() + ")");
    }
    if (image.srgb_decoded) detail::decode_srgb(image.pixels);
    out = std::move(image);
    return IoStatus::success();
  } catch (const std::bad_alloc&) {
    return IoStatus::error(IoErrc::Unreadable, path, "out of memory while reading");
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Unreadable, path, e.what());
  }
}

}  // namespace shpack::io
