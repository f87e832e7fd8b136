// preview_text.h (private) - the labels of `shpack preview` (preview.h): DejaVu Sans drawn by
// FreeType through the OpenImageIO module (oiio_plugin_abi.h), at a size that follows the
// picture's, when the module and the font (Debian's fonts-dejavu-core) are there; else the
// built-in 5x7 bitmap font (preview_draw.h), which has upper case only: its text is shown
// upper-cased, with π written PI. OpenImageIO 2.4's render_text misdecodes multi-byte UTF-8,
// so it is handed ASCII only and π is drawn here (preview_text.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "preview_draw.h"

namespace shpack::io::detail {

inline constexpr const char* kPreviewFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

class TextPainter {
 public:
  // `size`: the TrueType line's height in pixels (>= 8).
  explicit TextPainter(std::uint32_t size);

  bool truetype() const noexcept { return truetype_; }
  std::uint32_t line_height() const noexcept { return truetype_ ? size_ : kGlyphHeight; }

  // Draws `text` (UTF-8) with its top-left corner at (x, y), clipped to the image, blended
  // into what is there by its coverage; returns its width.
  std::uint32_t draw(Rgb8Image& image, std::uint32_t x, std::uint32_t y, std::string_view text,
                     Rgb8 colour = kText) const;
  std::uint32_t width(std::string_view text) const;

 private:
  std::uint32_t size_;
  bool truetype_ = false;
};

// `text` as the bitmap font can show it: upper case, "π" as "PI".
std::string bitmap_text(std::string_view text);

}  // namespace shpack::io::detail
