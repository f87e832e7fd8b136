#include "shpack/io/io_status.h"

namespace shpack::io {
namespace {

// Appends `ch`, a control character (C0 or DEL) written as \xNN so that a name from a
// file or the command line cannot move the cursor, colour the terminal or break the line.
void append_escaped(std::string& line, char ch) {
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

}  // namespace

IoStatus IoStatus::error(IoErrc code, const std::filesystem::path& file, std::string_view problem) {
  std::string line;
  // "-" is the standard input, as the commands take it (file_checks.h read_text_file).
  for (const char ch : file == "-" ? std::string("stdin") : file.string()) append_escaped(line, ch);
  line += ": ";
  const std::size_t problem_start = line.size();
  bool pending_break = false;
  for (const char ch : problem) {
    if (ch == '\n' || ch == '\r') {
      pending_break = line.size() > problem_start;  // leading and repeated breaks vanish
      continue;
    }
    if (pending_break) line += "; ";
    pending_break = false;
    append_escaped(line, ch);
  }
  return {code, std::move(line)};
}

}  // namespace shpack::io
