// image_open.h (private) - opening an image file the way every reader in lib/io does.
#pragma once

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "shpack/io/io_status.h"

namespace shpack::io::detail {

// The most texels an image may declare (--max-texels); `images` of that size are to be held
// (6 for the faces of a cube), so the budget is of images * texels.
struct TexelBudget {
  std::uint64_t max_texels = 0;
  std::uint32_t images = 1;
};

// The budget problem of a window of w x h texels (`what`: "the image", "the data window"),
// or "": "the image is WxH (N texels), above the budget of B (--max-texels)".
std::string budget_problem(const char* what, long long w, long long h, const TexelBudget& budget);

// Checks that `path` is a regular file this process may read (file_checks.h) and opens it
// with colour as stored (unassociated alpha). On failure `in` is null and the status names
// the file and the reason. `png` says whether the file starts with PNG's signature (the
// reads of such a file go through QuietLibpng).
// An OpenEXR file's header is walked first, before OpenEXR reads it (OpenEXR allocates what
// a header declares): every attribute must fit in the file, every part's data window and
// display window must be within `budget`, and every part's chunk offset table (8 bytes a
// chunk, allocated from the data window) must fit in the file.
IoStatus open_image(const std::filesystem::path& path, const TexelBudget& budget,
                    std::unique_ptr<OIIO::ImageInput>& in, bool& png);

// The problem with an image spec that shpack cannot project, or "" if there is none.
std::string spec_problem(const OIIO::ImageSpec& spec);

// `what` followed by " (reason)" when OpenImageIO gave a reason; never "()".
std::string with_reason(std::string what, const std::string& reason);

// libpng prints "libpng error: ..." on stderr before it hands the same text to OpenImageIO
// (which puts it in its error, and so in shpack's one-line message). While a QuietLibpng
// made with `active` lives, stderr goes to a scratch file; when it ends, stderr is restored
// and every captured line that is not libpng's own is written to it. One at a time in the
// process (a lock); inactive, it does nothing.
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
