#include "image_open.h"

#include "file_checks.h"

namespace shpack::io::detail {

IoStatus open_image(const std::filesystem::path& path, std::unique_ptr<OIIO::ImageInput>& in) {
  if (IoStatus st = check_regular_file(path); !st.ok()) return st;
  // Colour is wanted as stored: PNG/TIFF readers would otherwise premultiply it by alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) {
    return IoStatus::error(IoErrc::Unreadable, path,
                           "not an image that can be read (" + OIIO::geterror() + ")");
  }
  return IoStatus::success();
}

std::string spec_problem(const OIIO::ImageSpec& spec) {
  if (spec.width <= 0 || spec.height <= 0) return "the image has zero size";
  if (spec.nchannels <= 0) return "the image has no channels";
  if (spec.deep) return "the image holds deep data, not an environment map";
  if (spec.depth > 1) return "the image is a volume, not an environment map";
  // Texels outside a smaller data window would be lost from the sphere without a word.
  if (spec.x != spec.full_x || spec.y != spec.full_y || spec.width != spec.full_width ||
      spec.height != spec.full_height) {
    return "the data window differs from the display window, which is not supported";
  }
  return {};
}

}  // namespace shpack::io::detail
