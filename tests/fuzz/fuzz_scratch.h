// fuzz_scratch.h - where the file fuzz targets write each input before a reader opens it: a
// folder of this process's own in /dev/shm (no disk), created once.
#pragma once

#include <fcntl.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace shpack_fuzz {

// /dev/shm/shpack_fuzz_<target>_<pid> (or under the temporary folder without /dev/shm).
inline std::filesystem::path make_scratch(std::string_view target) {
  namespace fs = std::filesystem;
  const fs::path base = fs::exists("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
  std::string name = "shpack_fuzz_";
  name += target;
  name += "_";
  name += std::to_string(::getpid());
  fs::path dir = base / name;
  fs::create_directories(dir);
  return dir;
}

// Writes `size` bytes to `path`, replacing it; aborts (a fuzzer finding) if it cannot.
inline void write_input(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) std::abort();
  std::size_t written = 0;
  while (written < size) {
    const ssize_t n = ::write(fd, data + written, size - written);
    if (n <= 0) std::abort();
    written += static_cast<std::size_t>(n);
  }
  ::close(fd);
}

}  // namespace shpack_fuzz
