#include "shpack/io/io_status.h"

#include "shpack/io/quoted.h"

namespace shpack::io {

IoStatus IoStatus::error(IoErrc code, const std::filesystem::path& file, std::string_view problem) {
  std::string line;
  // "-" is the standard input, as the commands take it (file_checks.h read_text_file).
  for (const char ch : file == "-" ? std::string("stdin") : file.string()) append_printable(line, ch);
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
    append_printable(line, ch);
  }
  return {code, std::move(line)};
}

}  // namespace shpack::io
