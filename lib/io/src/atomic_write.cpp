#include "shpack/io/atomic_write.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <string>
#include <system_error>

namespace shpack::io {
namespace {

namespace fs = std::filesystem;

std::string errno_text() { return std::generic_category().message(errno); }

// Writes and closes; the error text, or "" on success. fclose reports errors of the final
// flush (a full disk shows up there), so its result counts too.
std::string write_and_close(const fs::path& path, std::string_view contents) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr) return "cannot create " + path.string() + ": " + errno_text();
  const bool written = std::fwrite(contents.data(), 1, contents.size(), file) == contents.size();
  std::string problem = written ? "" : "cannot write " + path.string() + ": " + errno_text();
  if (std::fclose(file) != 0 && problem.empty())
    problem = "cannot write " + path.string() + ": " + errno_text();
  return problem;
}

}  // namespace

IoStatus write_file_atomically(const fs::path& path, std::string_view contents) {
  fs::path temp = path;
  temp += ".tmp." + std::to_string(::getpid());
  std::string problem = write_and_close(temp, contents);
  if (problem.empty()) {
    std::error_code ec;
    fs::rename(temp, path, ec);
    if (ec) problem = "cannot replace the file: " + ec.message();
  }
  if (problem.empty()) return IoStatus::success();
  std::error_code ignored;  // the temporary may not exist; nothing more to report
  fs::remove(temp, ignored);
  return IoStatus::error(IoErrc::WriteFailed, path, problem);
}

}  // namespace shpack::io
