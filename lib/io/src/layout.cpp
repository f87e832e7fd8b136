#include "shpack/io/layout.h"

namespace shpack::io {

const char* layout_name(Layout layout) noexcept {
  switch (layout) {
    case Layout::Auto: return "auto";
    case Layout::Equirect: return "equirect";
  }
  return "unknown";
}

Layout resolve_layout(Layout requested, std::uint32_t width, std::uint32_t height) noexcept {
  if (requested != Layout::Auto) return requested;
  const bool two_to_one = static_cast<std::uint64_t>(width) == 2 * std::uint64_t{height};
  const bool single_texel = width == 1 && height == 1;
  return two_to_one || single_texel ? Layout::Equirect : Layout::Auto;
}

}  // namespace shpack::io
