// convert.h - one environment map file to the content of its output document.
//
// Reads and projects the file (env_map.h), hashes it (sha256.h), applies the intensity,
// convolves to Unity form (convolution.h) and finds the lowest E/pi per channel
// (sh_minimum.h). Writing the document is the caller's choice (json_writer.h).
#pragma once

#include <filesystem>

#include "shpack/io/env_map.h"
#include "shpack/io/io_status.h"
#include "shpack/io/sh_document.h"

namespace shpack::io {

struct ConvertSettings {
  EnvMapOptions env_map;
  double intensity = 1.0;  // linear factor on the radiance; finite and >= 0
};

// Fails as project_env_map does, with InvalidArgument for a bad intensity, and with
// Unsupported when the result does not fit in float32 (Unity's storage).
IoStatus convert_env_map(const std::filesystem::path& path, const ConvertSettings& settings,
                         ShDocument& out);

}  // namespace shpack::io
