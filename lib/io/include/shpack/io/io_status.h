// io_status.h - the error type of shpack_io.
//
// Like the core (status.h), shpack_io returns its errors instead of throwing them: it calls
// libraries that throw (OpenImageIO's helpers, nlohmann-json, the filesystem library) and
// catches at its boundary. Unlike the core's Status, the message is built at run time,
// because it names the file: one line, "<file>: <problem>", ready to print after "shpack: ".
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace shpack::io {

enum class IoErrc : std::uint8_t {
  Ok = 0,
  InvalidArgument,  // an option is out of its domain
  NotFound,         // the path does not exist
  NotAFile,         // the path is a directory (or, for an image, not a regular file)
  Unreadable,       // not an image or JSON file that can be read, or a read error (truncation)
  Unsupported,      // a readable image that shpack cannot use (zero size, deep data, ...)
  UnknownLayout,    // an image whose shape does not say its layout, and none was given
  NonFiniteTexel,   // NaN or Inf texels under NonFinite::Error
  BadDocument,      // a JSON document without the keys and shapes of the output format
  WriteFailed,      // the output could not be written; nothing was clobbered
  Core,             // the core library returned an error (its message is kept)
};

struct [[nodiscard]] IoStatus {
  IoErrc code = IoErrc::Ok;
  std::string message;  // "<file>: <problem>" on one line; empty on success

  bool ok() const noexcept { return code == IoErrc::Ok; }
  static IoStatus success() { return {}; }
  // Joins file and problem; line breaks in `problem` (OpenImageIO's messages have them)
  // become "; " so the message stays one line; other control characters (C0, DEL), in the
  // file name or the problem, are written as \xNN, so a hostile name prints as text.
  static IoStatus error(IoErrc code, const std::filesystem::path& file, std::string_view problem);
};

}  // namespace shpack::io
