// preview_draw.h (private) - drawing on an Rgb8Image: rectangles, the bitmap font, the
// tone mapping and the error colour map of `shpack preview` (preview.h).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "shpack/io/preview.h"

namespace shpack::io::detail {

using Rgb8 = std::array<std::uint8_t, 3>;

inline constexpr Rgb8 kBackground = {40, 40, 40};
inline constexpr Rgb8 kText = {225, 225, 225};
inline constexpr Rgb8 kNegativeMark = {255, 0, 255};  // stripes where ShadeSH9 < 0
inline constexpr std::uint32_t kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;

void fill(Rgb8Image& image, const PanelRect& rect, Rgb8 colour);

// Draws `text` with its top-left corner at (x, y), clipped to the image; lower case is
// drawn as upper case and characters without a glyph as '?'. Returns the width drawn.
std::uint32_t draw_text(Rgb8Image& image, std::uint32_t x, std::uint32_t y, std::string_view text,
                        Rgb8 colour = kText);
inline std::uint32_t text_width(std::string_view text) {
  return text.empty() ? 0 : static_cast<std::uint32_t>(text.size()) * kGlyphAdvance - 1;
}

// One channel: Reinhard(k v) then the sRGB encoding, to 8 bits. v must be >= 0.
std::uint8_t tone_map(double value, double exposure);

// The error colour of t in [-1, 1]: (0, 0, 255) at -1, white at 0, (255, 0, 0) at +1,
// linear in display values in between; t is clamped to [-1, 1].
Rgb8 error_colour(double t);

// Magenta stripes on black: the mark of a pixel whose ShadeSH9 has a negative channel.
inline Rgb8 negative_mark(std::uint32_t x, std::uint32_t y) {
  return (x + y) % 6 < 2 ? kNegativeMark : Rgb8{0, 0, 0};
}

}  // namespace shpack::io::detail
