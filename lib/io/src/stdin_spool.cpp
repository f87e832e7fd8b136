#include "shpack/io/stdin_spool.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace shpack::io {
namespace {

// Writes all of `n` bytes, retrying short writes and EINTR.
bool write_all(int fd, const char* data, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

}  // namespace

StdinSpool::~StdinSpool() {
  if (!path_.empty()) ::unlink(path_.c_str());
}

IoStatus StdinSpool::fill(std::uint64_t max_bytes) {
  const char* dir = std::getenv("TMPDIR");
  std::string name = (dir != nullptr && *dir != '\0') ? dir : "/tmp";
  name.append("/shpack-stdin-XXXXXX");
  std::vector<char> templ(name.begin(), name.end());
  templ.push_back('\0');
  const int fd = ::mkstemp(templ.data());  // O_CREAT | O_EXCL, mode 0600
  if (fd < 0)
    return IoStatus::error(IoErrc::WriteFailed, kStdinName,
                           std::string("cannot make a temporary file to hold it: ") + std::strerror(errno));
  path_ = templ.data();
  std::vector<char> buffer(std::size_t{1} << 20);
  std::uint64_t total = 0;
  IoStatus status = IoStatus::success();
  for (;;) {
    const ssize_t r = ::read(0, buffer.data(), buffer.size());
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      status = IoStatus::error(IoErrc::Unreadable, kStdinName, std::string("read failed: ") + std::strerror(errno));
      break;
    }
    if (r == 0) break;
    if (static_cast<std::uint64_t>(r) > max_bytes - total) {
      status = IoStatus::error(IoErrc::Unsupported, kStdinName,
                               "more than " + std::to_string(max_bytes) + " bytes (the budget of --max-texels)");
      break;
    }
    total += static_cast<std::uint64_t>(r);
    if (!write_all(fd, buffer.data(), static_cast<std::size_t>(r))) {
      status = IoStatus::error(IoErrc::WriteFailed, kStdinName,
                               std::string("cannot write its temporary copy: ") + std::strerror(errno));
      break;
    }
  }
  if (::close(fd) != 0 && status.ok())
    status = IoStatus::error(IoErrc::WriteFailed, kStdinName, "cannot write its temporary copy");
  if (status.ok() && total == 0) status = IoStatus::error(IoErrc::Unreadable, kStdinName, "empty: no image on it");
  if (!status.ok()) {
    ::unlink(path_.c_str());
    path_.clear();
  }
  return status;
}

}  // namespace shpack::io
