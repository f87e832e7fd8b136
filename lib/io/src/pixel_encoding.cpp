#include "pixel_encoding.h"

#include <OpenImageIO/strutil.h>

#include "shpack/srgb.h"

namespace shpack::io::detail {

Transfer pixel_transfer(const OIIO::ImageSpec& spec, std::string_view format_name) {
  // Channel 0's type, not spec.format: an EXR may mix half colour with a uint32 id channel.
  if (spec.channelformat(0).is_floating_point()) return Transfer::Linear;
  const std::string colour_space = spec.get_string_attribute("oiio:ColorSpace");
  if (OIIO::Strutil::iequals(colour_space, "sRGB")) return Transfer::Srgb;
  const bool srgb_by_default = format_name == "png" || format_name == "jpeg";
  return colour_space.empty() && srgb_by_default ? Transfer::Srgb : Transfer::Linear;
}

void decode_srgb(std::span<float> values) noexcept {
  for (float& v : values) v = static_cast<float>(srgb_to_linear(v));
}

}  // namespace shpack::io::detail
