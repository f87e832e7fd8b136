#include "bounded_read.h"

#include "shpack/io/file_checks.h"

namespace shpack::scene::detail {

// lib/io's one checked read (file_checks.h), with the stricter rule for the files a scene
// names: regular files only.
io::IoStatus read_bounded(const std::filesystem::path& path, FileKind kind, std::uint64_t max_bytes,
                          std::string& text) {
  if (kind == FileKind::Regular) {
    if (io::IoStatus st = io::detail::check_regular_file(path); !st.ok()) return st;
  }
  return io::detail::read_text_file(path, max_bytes, text);
}

}  // namespace shpack::scene::detail
