#include "shpack/io/quoted.h"

namespace shpack::io {

void append_printable(std::string& line, char ch) {
  const auto byte = static_cast<unsigned char>(ch);
  if (byte >= 0x20 && byte != 0x7f) {
    line += ch;
    return;
  }
  static constexpr char kHex[] = "0123456789abcdef";
  line += "\\x";
  line += kHex[byte >> 4];
  line += kHex[byte & 0xf];
}

std::string quoted(std::string_view text, std::size_t shown) {
  std::string out(1, '\'');
  for (const char ch : text.substr(0, shown)) append_printable(out, ch);
  out += text.size() > shown ? "...'" : "'";
  return out;
}

}  // namespace shpack::io
