#include "file_checks.h"

#include <system_error>

namespace shpack::io::detail {

IoStatus check_regular_file(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found)
    return IoStatus::error(IoErrc::NotFound, path, "no such file");
  if (ec) return IoStatus::error(IoErrc::Unreadable, path, ec.message());
  if (fs::is_directory(status)) return IoStatus::error(IoErrc::NotAFile, path, "is a directory");
  if (!fs::is_regular_file(status)) return IoStatus::error(IoErrc::NotAFile, path, "is not a regular file");
  return IoStatus::success();
}

}  // namespace shpack::io::detail
