// bounded_read.h (private) - the one way the scene loader opens a file: lib/io's checked read
// (file_checks.h read_text_file: checked before it is opened, read whole up to a size limit),
// so that /dev/zero, a FIFO named by a scene, or a 100 GB file is an error instead of a hang
// or a runaway allocation; the files a scene names must moreover be regular files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "shpack/io/io_status.h"

namespace shpack::scene::detail {

inline constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
// The scene file itself (JSON). Parsed, a JSON document takes up to about 13 times its size
// ("[]," is 3 bytes, 40 in memory); 16 MiB holds some 300,000 explicit probes at full double
// precision (a grid of a million is one line).
inline constexpr std::uint64_t kMaxSceneBytes = 16 * kMiB;
// A text mesh (OBJ): read, it takes at most about 6 times its size ("f 1 1 1 1 ...").
inline constexpr std::uint64_t kMaxMeshBytes = 256 * kMiB;

enum class FileKind : std::uint8_t {
  Regular,  // a regular file (or a link to one): files a scene names
  Stream,   // also a pipe this process holds, e.g. /dev/stdin: the file named on the command line
};

// Reads all of `path` into `text`. Fails, with a one-line IoStatus naming `path`, as
// read_text_file does, and for FileKind::Regular if it is not a regular file. `text` is only
// written on success.
io::IoStatus read_bounded(const std::filesystem::path& path, FileKind kind, std::uint64_t max_bytes,
                          std::string& text);

}  // namespace shpack::scene::detail
