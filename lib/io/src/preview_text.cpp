#include "preview_text.h"

#include <algorithm>
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

// `text` with π written pi: OpenImageIO 2.4's render_text decodes a multi-byte UTF-8
// character from its last byte alone (é comes out as ')', π as the missing glyph), so only
// ASCII reaches it.
std::string ascii_text(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.substr(i, 2) == "\xCF\x80") {
      out.append("pi");
      ++i;
    } else {
      out.push_back(text[i]);
    }
  }
  return out;
}

bool render(std::string_view text, std::uint32_t size, Rendered& out) {
  std::string problem;
  const OiioPlugin* plugin = oiio_plugin(problem);
  if (plugin == nullptr) return false;
  const std::string line = ascii_text(text);
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
  Rendered r;
  if (!truetype_ || !render(text, size_, r)) return draw_text(image, x, y, bitmap_text(text), colour);
  for (std::uint32_t j = 0; j < r.height && y + j < image.height; ++j)
    for (std::uint32_t i = 0; i < r.width && x + i < image.width; ++i) {
      const unsigned a = r.coverage[std::size_t{j} * r.width + i];
      if (a == 0) continue;
      std::uint8_t* p = image.at(x + i, y + j);
      for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>((colour[c] * a + p[c] * (255 - a) + 127) / 255);
    }
  return r.width;
}

std::uint32_t TextPainter::width(std::string_view text) const {
  Rendered r;
  if (!truetype_ || !render(text, size_, r)) return text_width(bitmap_text(text));
  return r.width;
}

}  // namespace shpack::io::detail
