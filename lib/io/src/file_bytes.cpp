#include "file_bytes.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

namespace shpack::io::detail {

// ByteStream reads this much at a time: a few RLE scanlines of a wide map, one syscall.
constexpr std::size_t kStreamBufferBytes = std::size_t{64} << 10;

FileBytes::~FileBytes() {
  if (fd_ >= 0) ::close(fd_);
}

FileBytes::FileBytes(FileBytes&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), size_(std::exchange(other.size_, 0)) {}

FileBytes& FileBytes::operator=(FileBytes&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

int FileBytes::open(const std::filesystem::path& path) {
  // O_NONBLOCK: should the path have become a FIFO since it was checked, open does not wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) return errno;
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int error = errno;
    ::close(fd);
    return error;
  }
  *this = FileBytes();
  fd_ = fd;
  size_ = static_cast<std::uint64_t>(std::max<off_t>(0, st.st_size));
  return 0;
}

bool FileBytes::read(std::uint64_t at, void* out, std::size_t n) const {
  if (at > size_ || n > size_ - at) return false;
  auto* p = static_cast<char*>(out);
  while (n > 0) {
    const ssize_t got = ::pread(fd_, p, n, static_cast<off_t>(at));
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    p += got;
    at += static_cast<std::uint64_t>(got);
    n -= static_cast<std::size_t>(got);
  }
  return true;
}

std::string FileBytes::read_some(std::uint64_t at, std::size_t n) const {
  if (at >= size_) return {};
  std::string bytes(static_cast<std::size_t>(std::min<std::uint64_t>(n, size_ - at)), '\0');
  if (!read(at, bytes.data(), bytes.size())) return {};
  return bytes;
}

ByteStream::ByteStream(const FileBytes& file) : file_(file), buffer_(kStreamBufferBytes) {}

bool ByteStream::fill() {
  if (pos_ >= file_.size()) return false;
  const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(buffer_.size(), file_.size() - pos_));
  if (!file_.read(pos_, buffer_.data(), n)) {
    held_ = 0;
    return false;
  }
  begin_ = pos_;
  held_ = n;
  return true;
}

bool ByteStream::read(std::uint8_t* out, std::size_t n) {
  while (n > 0) {
    if (pos_ - begin_ >= held_ && !fill()) return false;
    const std::size_t at = static_cast<std::size_t>(pos_ - begin_);
    const std::size_t take = std::min(n, held_ - at);
    std::memcpy(out, buffer_.data() + at, take);
    out += take;
    n -= take;
    pos_ += take;
  }
  return true;
}

}  // namespace shpack::io::detail
