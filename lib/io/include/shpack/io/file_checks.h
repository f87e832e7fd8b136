// file_checks.h - the checks every input file gets before a library opens it: lib/io's readers
// and the scene loader (lib/scene) give the same plain reasons.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "shpack/io/io_status.h"

namespace shpack::io::detail {

// Success if `path` names an existing regular file (or a link to one). The reason is
// said plainly ("no such file", "is a directory") instead of a reader's "cannot open".
IoStatus check_regular_file(const std::filesystem::path& path);

// Success if `path` exists and is not a directory: also a pipe such as /dev/stdin, for
// inputs that are read front to back (JSON).
IoStatus check_not_directory(const std::filesystem::path& path);

// The plain reason for an errno from stat, open or read of `path`: "permission denied",
// "no such file", "is a directory", else strerror's text (lower case). Always an error.
IoStatus file_error(const std::filesystem::path& path, int error_number);

// check_regular_file, then `path` is opened for reading (and closed): a file this process
// may not read is "permission denied", not a reader's "not an image file".
IoStatus check_readable_file(const std::filesystem::path& path);

// The largest JSON or text document read_text_file is given by shpack's readers (64 MiB).
inline constexpr std::uint64_t kMaxDocumentBytes = std::uint64_t{64} << 20;

// Reads all of `path` into `out`, at most `limit` bytes, checked before anything is read:
//  - "-" is the standard input, checked as /dev/stdin below (a pipe or a redirected file;
//    a terminal is a device), its errors naming "stdin";
//  - a regular file (or a link to one) whose size is above `limit` is refused unread;
//  - a pipe is read only if it is one this process already holds open, named as
//    /dev/stdin, /dev/fd/N or /proc/self/fd/N (`cmd < file`, `... | shpack eval /dev/stdin`,
//    `<(...)`), and then only up to `limit` bytes; a named pipe (FIFO) in the file system is
//    refused without being opened (opening it would wait for a writer);
//  - devices (/dev/zero, a terminal), sockets and directories are refused without being
//    opened for reading.
// Errors name the file: "no such file", "permission denied", "is a device, not a regular
// file", "the file is N bytes, above the limit of L bytes", ...
IoStatus read_text_file(const std::filesystem::path& path, std::uint64_t limit, std::string& out);

}  // namespace shpack::io::detail
