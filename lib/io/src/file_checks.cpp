#include "file_checks.h"

#include <system_error>

namespace shpack::io::detail {

namespace fs = std::filesystem;

IoStatus check_not_directory(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found)
    return IoStatus::error(IoErrc::NotFound, path, "no such file");
  if (ec) return IoStatus::error(IoErrc::Unreadable, path, ec.message());
  if (fs::is_directory(status)) return IoStatus::error(IoErrc::NotAFile, path, "is a directory");
  return IoStatus::success();
}

IoStatus check_regular_file(const fs::path& path) {
  if (IoStatus st = check_not_directory(path); !st.ok()) return st;
  std::error_code ec;  // a status error was reported above; here it can only mean "not a file"
  if (!fs::is_regular_file(fs::status(path, ec)))
    return IoStatus::error(IoErrc::NotAFile, path, "is not a regular file");
  return IoStatus::success();
}

}  // namespace shpack::io::detail
