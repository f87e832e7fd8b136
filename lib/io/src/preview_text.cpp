#include "preview_text.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <system_error>
#include <vector>

#include "oiio_plugin.h"

namespace shpack::io::detail {
namespace {

struct Rendered {
  std::vector<std::uint8_t> coverage;
  std::uint32_t width = 0, height = 0;
};

// OpenImageIO 2.4's render_text decodes a multi-byte UTF-8 character from its last byte
// alone (é comes out as ')', π as the missing glyph), so only ASCII is handed to it: the
// text is cut at each π (the one non-ASCII character the labels use), and π drawn here.
constexpr std::string_view kPi = "\xCF\x80";

std::vector<std::string_view> pieces(std::string_view text) {
  std::vector<std::string_view> out;
  for (std::size_t at = text.find(kPi); at != std::string_view::npos; at = text.find(kPi)) {
    if (at > 0) out.push_back(text.substr(0, at));
    out.push_back(kPi);
    text.remove_prefix(at + kPi.size());
  }
  if (!text.empty()) out.push_back(text);
  return out;
}

// π in the proportions of DejaVu Sans (advance 0.6 em, x-height 0.55 em, stem 0.09 em):
// a bar at the x-height over two legs, on the line's baseline (4/5 of its height).
Rendered pi_glyph(std::uint32_t size) {
  Rendered r;
  r.width = std::max<std::uint32_t>(4, static_cast<std::uint32_t>(std::lround(0.6 * size)));
  r.height = size;
  r.coverage.assign(std::size_t{r.width} * r.height, 0);
  const auto stem = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(0.09 * size)));
  const std::uint32_t baseline = (4 * size) / 5;
  const auto top = baseline - std::min(baseline, static_cast<std::uint32_t>(std::lround(0.55 * size)));
  const auto set = [&](std::uint32_t x, std::uint32_t y) {
    if (x < r.width && y < r.height) r.coverage[std::size_t{y} * r.width + x] = 255;
  };
  for (std::uint32_t y = top; y < top + stem; ++y)
    for (std::uint32_t x = r.width / 12; x < r.width - r.width / 12; ++x) set(x, y);
  for (const double at : {0.3, 0.7}) {
    const auto x0 = static_cast<std::uint32_t>(at * r.width) - stem / 2;
    for (std::uint32_t y = top; y < baseline; ++y)
      for (std::uint32_t x = x0; x < x0 + stem; ++x) set(x, y);
  }
  return r;
}

bool render(std::string_view text, std::uint32_t size, Rendered& out) {
  std::string problem;
  const OiioPlugin* plugin = oiio_plugin(problem);
  if (plugin == nullptr) return false;
  const std::string line(text);
  std::string error;
  return plugin->render_text(line.c_str(), kPreviewFont, static_cast<int>(size), &out.coverage, &out.width,
                             &out.height, &error);
}

}  // namespace

std::string bitmap_text(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.substr(i, 2) == "\xCF\x80") {  // π in UTF-8
      out.append("PI");
      ++i;
    } else {
      out.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(text[i]))));
    }
  }
  return out;
}

TextPainter::TextPainter(std::uint32_t size) : size_(std::max<std::uint32_t>(8, size)) {
  std::error_code ec;
  Rendered probe;
  truetype_ = std::filesystem::is_regular_file(kPreviewFont, ec) && render("E", size_, probe);
}

std::uint32_t TextPainter::draw(Rgb8Image& image, std::uint32_t x, std::uint32_t y, std::string_view text,
                                Rgb8 colour) const {
  if (!truetype_) return draw_text(image, x, y, bitmap_text(text), colour);
  std::uint32_t advance = 0;
  for (const std::string_view piece : pieces(text)) {
    Rendered r;
    if (piece == kPi) {
      r = pi_glyph(size_);
    } else if (!render(piece, size_, r)) {
      continue;  // the module went away after the probe: nothing to draw with
    }
    for (std::uint32_t j = 0; j < r.height && y + j < image.height; ++j)
      for (std::uint32_t i = 0; i < r.width && x + advance + i < image.width; ++i) {
        const unsigned a = r.coverage[std::size_t{j} * r.width + i];
        if (a == 0) continue;
        std::uint8_t* p = image.at(x + advance + i, y + j);
        for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>((colour[c] * a + p[c] * (255 - a) + 127) / 255);
      }
    advance += r.width;
  }
  return advance;
}

std::uint32_t TextPainter::width(std::string_view text) const {
  if (!truetype_) return text_width(bitmap_text(text));
  std::uint32_t advance = 0;
  for (const std::string_view piece : pieces(text)) {
    Rendered r;
    if (piece == kPi) advance += pi_glyph(size_).width;
    else if (render(piece, size_, r)) advance += r.width;
  }
  return advance;
}

}  // namespace shpack::io::detail
