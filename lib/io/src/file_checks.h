// file_checks.h (private) - the checks every input file gets before a library opens it.
#pragma once

#include <filesystem>

#include "shpack/io/io_status.h"

namespace shpack::io::detail {

// Success if `path` names an existing regular file (or a link to one). The reason is
// said plainly ("no such file", "is a directory") instead of a reader's "cannot open".
IoStatus check_regular_file(const std::filesystem::path& path);

// Success if `path` exists and is not a directory: also a pipe such as /dev/stdin, for
// inputs that are read front to back (JSON).
IoStatus check_not_directory(const std::filesystem::path& path);

}  // namespace shpack::io::detail
