// atomic_write.h - write an output file whole or not at all, and never anywhere else.
//
// The rules (docs/security.md, "Output files"), by what `path` names when the write starts:
//
// - "-", /dev/stdout, /dev/stderr, /dev/stdin, /dev/fd/N, /proc/self/fd/N: that open
//   descriptor is written as it is (no file is opened, created or renamed).
// - Nothing, or a regular file: replaced atomically. The bytes go to a new temporary in the
//   same folder, ".<name>.<10 random characters>", created with
//   O_CREAT|O_EXCL|O_NOFOLLOW (never a file or link that is already there, so a planted link
//   or FIFO cannot redirect or stall the write), mode 0600 while it is written; then fsync,
//   the mode of the file it replaces (its permission bits; as root, also its owner) or
//   0666 & ~umask for a new file, and rename over `path`, then an fsync of the folder.
//   Readers see the old file or the new one, never a part; on any failure the old file is
//   untouched and the temporary removed. A hard link to the old file keeps the old contents.
// - A symbolic link: the link itself is replaced by the new regular file (like the rename of
//   most tools); the file it pointed to is left as it was. Except a link to a device, FIFO
//   or socket, owned by the caller or by root (such as /dev/stdout), which is written in
//   place; one owned by another user is refused (a link planted in a shared folder).
// - A device, FIFO or socket: written in place (opened for writing without O_CREAT, never
//   replaced, never truncated), so `-o /dev/null` stays a device.
// - A directory (or a link to one): an error naming it; nothing is written.
//
// SIGINT, SIGTERM and SIGHUP remove the temporaries being written and then end the process
// with the signal's default action, when their disposition was the default (a program that
// ignores them or handles them itself keeps its choice).
#pragma once

#include <filesystem>
#include <string_view>

#include "shpack/io/io_status.h"

namespace shpack::io {

// Writes `contents` to `path` by the rules above; WriteFailed (nothing clobbered) or success.
IoStatus write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// The descriptor `path` names by the first rule ("-" and /dev/stdout are 1, /dev/fd/N is N),
// or -1 when it names a file.
int output_descriptor(const std::filesystem::path& path);

}  // namespace shpack::io
