#include "quiet_libpng.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <string>
#include <string_view>

namespace shpack::io::detail {
namespace {

std::mutex& stderr_mutex() {
  static std::mutex mutex;
  return mutex;
}

void write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
}

}  // namespace

QuietLibpng::QuietLibpng(bool active) {
  if (!active) return;
  lock_ = std::unique_lock<std::mutex>(stderr_mutex());
  std::fflush(stderr);
  capture_ = ::memfd_create("shpack-stderr", MFD_CLOEXEC);
  if (capture_ < 0) return;
  saved_ = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
  if (saved_ < 0 || ::dup2(capture_, STDERR_FILENO) < 0) {
    if (saved_ >= 0) ::close(saved_);
    saved_ = -1;
  }
}

QuietLibpng::~QuietLibpng() {
  if (saved_ >= 0) {
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    // Pass on what was not libpng's.
    std::string captured;
    std::array<char, 4096> buffer;
    if (::lseek(capture_, 0, SEEK_SET) == 0) {
      for (ssize_t n; (n = ::read(capture_, buffer.data(), buffer.size())) > 0;)
        captured.append(buffer.data(), static_cast<std::size_t>(n));
    }
    for (std::size_t begin = 0; begin < captured.size();) {
      std::size_t end = captured.find('\n', begin);
      end = end == std::string::npos ? captured.size() : end + 1;
      const std::string_view line(captured.data() + begin, end - begin);
      if (line.rfind("libpng error: ", 0) != 0 && line.rfind("libpng warning: ", 0) != 0)
        write_all(STDERR_FILENO, line.data(), line.size());
      begin = end;
    }
  }
  if (capture_ >= 0) ::close(capture_);
}

}  // namespace shpack::io::detail
