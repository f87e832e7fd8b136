// stdin_spool.h - an image on the standard input (`shpack convert -`), copied whole into a
// temporary file, since the decoders seek (OpenEXR reads its offset tables, OpenImageIO's
// readers their headers twice).
//
// The copy: a new file made by mkstemp in $TMPDIR (else /tmp), mode 0600, never a file or
// link that is already there; at most `max_bytes` are copied, and a longer input is refused
// before anything past the budget is written; the file is removed when the spool is
// destroyed, and when a copy fails. What is decoded from it is then checked as any file is
// (map_source.h: --max-texels against the header before a texel is decoded).
#pragma once

#include <cstdint>
#include <filesystem>

#include "shpack/io/io_status.h"

namespace shpack::io {

inline constexpr const char* kStdinName = "stdin";  // how messages and documents name it

class StdinSpool {
 public:
  StdinSpool() = default;
  ~StdinSpool();
  StdinSpool(const StdinSpool&) = delete;
  StdinSpool& operator=(const StdinSpool&) = delete;

  // Copies the standard input (descriptor 0) to the end. Errors name "stdin": Unreadable (a
  // read failed, or it is empty), Unsupported (more than max_bytes), WriteFailed (the
  // temporary could not be made or written).
  IoStatus fill(std::uint64_t max_bytes);

  const std::filesystem::path& path() const noexcept { return path_; }

 private:
  std::filesystem::path path_;
};

// The budget of a spooled image of at most `max_texels` texels: 16 bytes a texel (four
// float channels, uncompressed) and 1 MiB of headers.
constexpr std::uint64_t stdin_budget(std::uint64_t max_texels) noexcept {
  return max_texels > (UINT64_MAX - (std::uint64_t{1} << 20)) / 16 ? UINT64_MAX : 16 * max_texels + (std::uint64_t{1} << 20);
}

}  // namespace shpack::io
