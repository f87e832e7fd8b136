// image_open.h (private) - opening an image file the way every reader in lib/io does.
#pragma once

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <memory>
#include <string>

#include "shpack/io/io_status.h"

namespace shpack::io::detail {

// Checks that `path` is a regular file and opens it with colour as stored (unassociated
// alpha). On failure `in` is null and the status names the file and the reason.
IoStatus open_image(const std::filesystem::path& path, std::unique_ptr<OIIO::ImageInput>& in);

// The problem with an image spec that shpack cannot project, or "" if there is none.
std::string spec_problem(const OIIO::ImageSpec& spec);

}  // namespace shpack::io::detail
