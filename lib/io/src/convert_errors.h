// convert_errors.h (private) - the errors of the pipeline's drivers (convert.cpp for files,
// convert_pixels.cpp for pixels in memory), built once so that both say the same thing.
#pragma once

#include <filesystem>

#include "shpack/io/convert.h"
#include "shpack/io/io_status.h"
#include "shpack/pipeline.h"

namespace shpack::io::detail {

// A core Status as an IoStatus naming `source` (a file, or the name of pixels in memory):
// InvalidArgument stays InvalidArgument, OutOfRange (too bright for float32) is Unsupported,
// anything else is Core.
IoStatus core_error(const std::filesystem::path& source, const Status& st);

// The one message for NaN/Inf texels under NonFinite::Error: how many, and the first, in
// `source` (the face's file or name for six faces); for the sampling methods, the reads of
// them.
IoStatus nonfinite_error(const std::filesystem::path& source, const ProjectStats& seen, const MethodSpec& method);

// finish_projection's option checks and validate_method, before any pixel is read.
IoStatus check_settings(const std::filesystem::path& source, const ConvertSettings& settings);

}  // namespace shpack::io::detail
