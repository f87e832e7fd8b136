// quiet_libpng.h (OpenImageIO module) - libpng prints "libpng error: ..." on stderr before
// it hands the same text to OpenImageIO (which puts it in its error, and so in shpack's
// one-line message). While a QuietLibpng made with `active` lives, stderr goes to a scratch
// file; when it ends, stderr is restored and every captured line that is not libpng's own is
// written to it. One at a time in the process (a lock); inactive, it does nothing.
#pragma once

#include <mutex>

namespace shpack::io::detail {

class QuietLibpng {
 public:
  explicit QuietLibpng(bool active);
  ~QuietLibpng();
  QuietLibpng(const QuietLibpng&) = delete;
  QuietLibpng& operator=(const QuietLibpng&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
  int saved_ = -1;    // the real stderr, while redirected
  int capture_ = -1;  // the scratch file
};

}  // namespace shpack::io::detail
