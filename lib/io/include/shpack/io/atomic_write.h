// atomic_write.h - replace a file whole or not at all.
//
// The contents go to "<path>.tmp.<pid>" in the same folder (so the rename stays on one
// file system), which is then renamed over `path`: readers see the old file or the new one,
// never a half-written one, and a failure leaves an existing file untouched and removes the
// temporary. There is no fsync: this guards against failed runs, not against power loss.
#pragma once

#include <filesystem>
#include <string_view>

#include "shpack/io/io_status.h"

namespace shpack::io {

IoStatus write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace shpack::io
