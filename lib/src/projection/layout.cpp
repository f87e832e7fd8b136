#include "shpack/layout.h"

#include <array>

namespace shpack {
namespace {

// Layouts a single image can have, in the order messages list them.
constexpr std::array<Layout, 8> kImageLayouts = {Layout::Equirect,        Layout::HorizontalCross,
                                                 Layout::VerticalCross,   Layout::HorizontalStrip,
                                                 Layout::VerticalStrip,   Layout::Octahedral,
                                                 Layout::Angular,         Layout::MirrorBall};

// w : h = columns : rows exactly (64-bit: no overflow for any uint32 size).
bool ratio(std::uint32_t w, std::uint32_t h, std::uint64_t columns, std::uint64_t rows) noexcept {
  return std::uint64_t{w} * rows == std::uint64_t{h} * columns && w % columns == 0;
}

// Whether a w x h image has the shape `layout` needs (equirect takes any shape when asked
// for by name, but only 2:1 is detected as equirect).
bool fits(Layout layout, std::uint32_t w, std::uint32_t h, bool detecting) noexcept {
  if (w == 1 && h == 1) return true;
  switch (layout) {
    case Layout::Equirect: return !detecting || ratio(w, h, 2, 1);
    case Layout::HorizontalCross: return ratio(w, h, 4, 3);
    case Layout::VerticalCross: return ratio(w, h, 3, 4);
    case Layout::HorizontalStrip: return ratio(w, h, 6, 1);
    case Layout::VerticalStrip: return ratio(w, h, 1, 6);
    case Layout::Octahedral:
    case Layout::Angular:
    case Layout::MirrorBall: return w == h;
    case Layout::Auto:
    case Layout::Faces: return false;
  }
  return false;
}

const char* shape_of(Layout layout) noexcept {
  switch (layout) {
    case Layout::Equirect: return "2N x N";
    case Layout::HorizontalCross: return "4N x 3N";
    case Layout::VerticalCross: return "3N x 4N";
    case Layout::HorizontalStrip: return "6N x N";
    case Layout::VerticalStrip: return "N x 6N";
    default: return "N x N";
  }
}

// "a, b and c" of the layouts whose detected shape fits, or "none".
std::string fitting(std::uint32_t w, std::uint32_t h) {
  std::string list;
  int count = 0;
  for (const Layout l : kImageLayouts) count += fits(l, w, h, true);
  int seen = 0;
  for (const Layout l : kImageLayouts) {
    if (!fits(l, w, h, true)) continue;
    list += (seen == 0 ? "" : seen + 1 == count ? " and " : ", ") + std::string(layout_name(l));
    ++seen;
  }
  return count == 0 ? "no layout (2:1 equirect, 4:3 hcross, 3:4 vcross, 6:1 hstrip, 1:6 vstrip, "
                      "square octahedral, angular or mirrorball)"
                    : list;
}

}  // namespace

const char* layout_name(Layout layout) noexcept {
  switch (layout) {
    case Layout::Auto: return "auto";
    case Layout::Equirect: return "equirect";
    case Layout::HorizontalCross: return "hcross";
    case Layout::VerticalCross: return "vcross";
    case Layout::HorizontalStrip: return "hstrip";
    case Layout::VerticalStrip: return "vstrip";
    case Layout::Octahedral: return "octahedral";
    case Layout::Angular: return "angular";
    case Layout::MirrorBall: return "mirrorball";
    case Layout::Faces: return "faces";
  }
  return "unknown";
}

Layout resolve_layout(Layout requested, std::uint32_t width, std::uint32_t height) noexcept {
  if (requested != Layout::Auto) return requested;
  if (width == 1 && height == 1) return Layout::Equirect;  // uniform: read exactly as equirect
  for (const Layout l : {Layout::Equirect, Layout::HorizontalCross, Layout::VerticalCross,
                         Layout::HorizontalStrip, Layout::VerticalStrip})
    if (fits(l, width, height, true)) return l;
  return Layout::Auto;
}

std::string layout_shape_problem(Layout requested, std::uint32_t width, std::uint32_t height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (requested == Layout::Auto) {
    if (resolve_layout(Layout::Auto, width, height) != Layout::Auto) return {};
    if (width == height)
      return "the layout of a " + size + " image is ambiguous: it fits " + fitting(width, height);
    return "the layout of a " + size + " image cannot be detected: it fits " + fitting(width, height);
  }
  if (requested == Layout::Faces || fits(requested, width, height, false)) return {};
  return "a " + size + " image is not " + (requested == Layout::Angular || requested == Layout::Octahedral ? "an " : "a ") +
         layout_name(requested) + " (" + shape_of(requested) + "); its shape fits " + fitting(width, height);
}

bool is_cube_layout(Layout layout) noexcept {
  return layout == Layout::HorizontalCross || layout == Layout::VerticalCross ||
         layout == Layout::HorizontalStrip || layout == Layout::VerticalStrip || layout == Layout::Faces;
}

}  // namespace shpack
