#include "support/exr_file.h"

#include <OpenImageIO/imageio.h>

namespace shpack_test {

bool read_exr_rgb(const std::filesystem::path& path, RgbImage& out, std::string& error) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    error = "cannot open " + path.string() + ": " + OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3 || spec.width <= 0 || spec.height <= 0 || spec.depth != 1) {
    error = path.string() + ": not a 2-D image with at least 3 channels";
    return false;
  }
  RgbImage img(static_cast<std::uint32_t>(spec.width), static_cast<std::uint32_t>(spec.height));
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, img.rgb.data())) {
    error = path.string() + ": " + in->geterror();
    return false;
  }
  in->close();
  out = std::move(img);
  return true;
}

bool write_exr_rgb(const std::filesystem::path& path, const RgbImage& image, std::string& error) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) {
    error = "cannot create " + path.string() + ": " + OIIO::geterror();
    return false;
  }
  OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 3,
                       OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data()) ||
      !out->close()) {
    error = path.string() + ": " + out->geterror();
    return false;
  }
  return true;
}

}  // namespace shpack_test
