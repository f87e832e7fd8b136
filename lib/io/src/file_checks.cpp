#include "shpack/io/file_checks.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <string_view>
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

IoStatus file_error(const fs::path& path, int error_number) {
  switch (error_number) {
    case EACCES:
    case EPERM: return IoStatus::error(IoErrc::Unreadable, path, "permission denied");
    case ENOENT: return IoStatus::error(IoErrc::NotFound, path, "no such file");
    case ENOTDIR: return IoStatus::error(IoErrc::NotFound, path, "no such file (a folder on the path is a file)");
    case EISDIR: return IoStatus::error(IoErrc::NotAFile, path, "is a directory");
    default: break;
  }
  std::string text = std::strerror(error_number);
  if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return IoStatus::error(IoErrc::Unreadable, path, text);
}

namespace {

// Closes a descriptor this file opened.
struct Descriptor {
  int fd = -1;
  bool owned = false;
  ~Descriptor() {
    if (owned && fd >= 0) ::close(fd);
  }
};

// The descriptor N that `path` names if it is /dev/stdin, /dev/fd/N or /proc/self/fd/N,
// else -1. Only the spelling is looked at; the caller checks that the descriptor is the
// file `path` leads to.
constexpr std::string_view kStdin = "/dev/stdin";

int named_descriptor(const fs::path& path) {
  const std::string text = path.string();
  if (text == kStdin) return 0;
  for (const std::string_view prefix : {std::string_view("/dev/fd/"), std::string_view("/proc/self/fd/")}) {
    if (text.size() <= prefix.size() || text.compare(0, prefix.size(), prefix) != 0) continue;
    int fd = -1;
    const char* first = text.data() + prefix.size();
    const char* last = text.data() + text.size();
    const auto [end, ec] = std::from_chars(first, last, fd);
    if (ec == std::errc() && end == last && fd >= 0) return fd;
  }
  return -1;
}

// A file of `size` bytes (exact), or an input that went on past `limit` bytes.
IoStatus too_large(const fs::path& path, std::uint64_t size, std::uint64_t limit, bool exact) {
  const std::string limit_text = "the limit of " + std::to_string(limit) + " bytes";
  return IoStatus::error(IoErrc::Unreadable, path,
                         exact ? "the file is " + std::to_string(size) + " bytes, above " + limit_text
                               : "the input goes on past " + limit_text);
}

}  // namespace

IoStatus check_readable_file(const fs::path& path) {
  if (IoStatus st = check_regular_file(path); !st.ok()) return st;
  // O_NONBLOCK: should the path have become a FIFO since the check, open does not wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) return file_error(path, errno);
  ::close(fd);
  return IoStatus::success();
}

IoStatus read_text_file(const fs::path& path, std::uint64_t limit, std::string& out) {
  if (path == "-") {
    IoStatus st = read_text_file(kStdin, limit, out);
    if (!st.ok()) st.message.replace(0, kStdin.size(), "stdin");  // the message starts "/dev/stdin: "
    return st;
  }
  struct stat named {};
  if (::stat(path.c_str(), &named) != 0) return file_error(path, errno);
  Descriptor in;
  if (S_ISDIR(named.st_mode)) return IoStatus::error(IoErrc::NotAFile, path, "is a directory");
  if (S_ISREG(named.st_mode)) {
    if (static_cast<std::uint64_t>(named.st_size) > limit)
      return too_large(path, static_cast<std::uint64_t>(named.st_size), limit, true);
    in.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    in.owned = true;
    if (in.fd < 0) return file_error(path, errno);
    struct stat opened {};
    if (::fstat(in.fd, &opened) != 0) return file_error(path, errno);
    if (!S_ISREG(opened.st_mode))  // replaced between the stat and the open
      return IoStatus::error(IoErrc::NotAFile, path, "is not a regular file");
    ::fcntl(in.fd, F_SETFL, ::fcntl(in.fd, F_GETFL) & ~O_NONBLOCK);
  } else if (S_ISFIFO(named.st_mode) || S_ISSOCK(named.st_mode)) {
    // Only a pipe already open in this process: the one `path` names by number.
    const int fd = named_descriptor(path);
    struct stat held {};
    if (fd < 0 || ::fstat(fd, &held) != 0 || held.st_dev != named.st_dev || held.st_ino != named.st_ino) {
      return IoStatus::error(IoErrc::NotAFile, path,
                             S_ISFIFO(named.st_mode) ? "is a named pipe (FIFO), not a regular file"
                                                     : "is a socket, not a regular file");
    }
    in.fd = fd;
  } else {
    return IoStatus::error(IoErrc::NotAFile, path,
                           S_ISCHR(named.st_mode) || S_ISBLK(named.st_mode) ? "is a device, not a regular file"
                                                                            : "is not a regular file");
  }
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(in.fd, buffer, sizeof buffer);
    if (got < 0) {
      if (errno == EINTR) continue;
      return file_error(path, errno);
    }
    if (got == 0) break;
    if (text.size() + static_cast<std::size_t>(got) > limit) return too_large(path, limit, limit, false);
    text.append(buffer, static_cast<std::size_t>(got));
  }
  out = std::move(text);
  return IoStatus::success();
}

}  // namespace shpack::io::detail
