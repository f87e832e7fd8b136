// image_open.h (private) - opening an image file the way every reader in lib/io does.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "image_decoder.h"
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
// with the reader its magic number names, never its extension: OpenEXR with OpenEXR
// (exr_decoder.h), Radiance RGBE and PFM with shpack's own readers (hdr_decoder.h,
// pfm_decoder.h, which check their headers against the file's size and `budget` as they
// read them), any other through shpack's OpenImageIO module (oiio_plugin.h), which is loaded
// then and not before. On failure `decoder` is null and the status names the file and the
// reason.
// An OpenEXR file's header is walked first, before OpenEXR reads it (OpenEXR allocates what
// a header declares): every attribute must fit in the file, every part's data window and
// display window must be within `budget`, and every part's chunk offset table (8 bytes a
// chunk, allocated from the data window) must fit in the file.
IoStatus open_image(const std::filesystem::path& path, const TexelBudget& budget,
                    std::unique_ptr<ImageDecoder>& decoder);

// The problem with a part that shpack cannot project, or "" if there is none.
std::string part_problem(const ImagePart& part);

// `what` followed by " (reason)" when the reader gave a reason; never "()".
std::string with_reason(std::string what, const std::string& reason);

}  // namespace shpack::io::detail
