// file_bytes.h (private) - a file read by offset (FileBytes), or forward through a buffer
// (ByteStream), for the readers that walk a header or decode rows without holding the file:
// OpenEXR's header walk (image_open.cpp), the Radiance and PFM readers (hdr_decoder.h,
// pfm_decoder.h). Reads go through pread, so no file position is shared, and each is checked
// against the file's size (from fstat at open) before it is made.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace shpack::io::detail {

class FileBytes {
 public:
  FileBytes() = default;
  ~FileBytes();
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;
  FileBytes(FileBytes&& other) noexcept;
  FileBytes& operator=(FileBytes&& other) noexcept;

  // Opens `path` read-only (file_checks.h has said it is a regular file). 0, or the errno.
  int open(const std::filesystem::path& path);

  std::uint64_t size() const noexcept { return size_; }

  // The `n` bytes at offset `at` into `out`: false if they are not all inside the file, or
  // if a read fails.
  bool read(std::uint64_t at, void* out, std::size_t n) const;

  // The bytes from `at`, at most `n` (fewer at the end of the file): for headers.
  std::string read_some(std::uint64_t at, std::size_t n) const;

 private:
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

// The bytes of a file read forward through a buffer of 64 KiB, from any offset (seek).
class ByteStream {
 public:
  explicit ByteStream(const FileBytes& file);

  std::uint64_t tell() const noexcept { return pos_; }
  void seek(std::uint64_t at) noexcept { pos_ = at; }
  bool at_end() const noexcept { return pos_ >= file_.size(); }

  // The next byte; false at the end of the file or if it cannot be read.
  bool get(std::uint8_t& out) {
    if (pos_ - begin_ >= held_ && !fill()) return false;
    out = buffer_[static_cast<std::size_t>(pos_ - begin_)];
    ++pos_;
    return true;
  }

  // The next `n` bytes; false if the file ends before them or they cannot be read.
  bool read(std::uint8_t* out, std::size_t n);

 private:
  bool fill();  // the buffer from pos_; false if nothing is left

  const FileBytes& file_;
  std::vector<std::uint8_t> buffer_;
  std::uint64_t begin_ = 0;  // the file offset of buffer_[0]
  std::size_t held_ = 0;     // bytes in buffer_
  std::uint64_t pos_ = 0;
};

}  // namespace shpack::io::detail
