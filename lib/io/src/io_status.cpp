#include "shpack/io/io_status.h"

namespace shpack::io {

IoStatus IoStatus::error(IoErrc code, const std::filesystem::path& file, std::string_view problem) {
  std::string line = file.string() + ": ";
  const std::size_t problem_start = line.size();
  bool pending_break = false;
  for (const char ch : problem) {
    if (ch == '\n' || ch == '\r') {
      pending_break = line.size() > problem_start;  // leading and repeated breaks vanish
      continue;
    }
    if (pending_break) line += "; ";
    pending_break = false;
    line += ch;
  }
  return {code, std::move(line)};
}

}  // namespace shpack::io
