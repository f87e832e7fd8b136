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
  // A data window other than the display window is fine: image_source.h reads it.
  return {};
}

}  // namespace shpack::io::detail
