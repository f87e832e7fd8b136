#include "pixel_transfer.h"

#include <OpenImageIO/strutil.h>

namespace shpack::io::detail {

bool srgb_encoded(const OIIO::ImageSpec& spec, std::string_view format_name) {
  // Channel 0's type, not spec.format: a file may mix integer colour with float extras.
  if (spec.channelformat(0).is_floating_point()) return false;
  const std::string colour_space = spec.get_string_attribute("oiio:ColorSpace");
  if (OIIO::Strutil::iequals(colour_space, "sRGB")) return true;
  const bool srgb_by_default = format_name == "png" || format_name == "jpeg";
  return colour_space.empty() && srgb_by_default;
}

}  // namespace shpack::io::detail
