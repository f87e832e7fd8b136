// convert.h - one environment map file to the content of its output document.
//
// Reads and projects the file (method_projection.h), hashes it (sha256.h), converts its
// colours to linear Rec. 709 (colorspace.h), applies the intensity and the rotation (rotate.h), convolves to Unity form (convolution.h), windows it (window.h;
// the same band factors go to the radiance, so radiance_sh and the Unity outputs describe
// one function) and finds the lowest E/pi per channel (sh_minimum.h). Writing the document is the caller's choice (json_writer.h).
#pragma once

#include <array>
#include <filesystem>

#include "shpack/io/colorspace.h"
#include "shpack/io/env_map.h"
#include "shpack/io/io_status.h"
#include "shpack/io/sh_document.h"
#include "shpack/sampling_methods.h"
#include "shpack/window.h"

namespace shpack::io {

struct ConvertSettings {
  EnvMapOptions env_map;   // its project.method is ignored: `method` says which runs
  MethodSpec method;       // exact and center stream the file (method_projection.h)
  double intensity = 1.0;  // linear factor on the radiance; finite and >= 0
  double rotate_deg = 0.0; // yaw about +Y, as Skybox/Panoramic's _Rotation (rotate.h)
  Window window;           // deringing (window.h)
  ColorSpace colorspace = ColorSpace::Auto;  // the input's primaries (colorspace.h); Auto: the file's
};

// Fails as project_env_map_with_method does, with InvalidArgument for a bad intensity or
// rotation, and with Unsupported when the result does not fit in float32 (Unity's storage).
IoStatus convert_env_map(const std::filesystem::path& path, const ConvertSettings& settings,
                         ShDocument& out);

// Six face files in Unity's face order (env_map.h project_cube_faces) to one document, as
// convert_env_map (exact or center only); source.files and sha256 list the six faces.
IoStatus convert_cube_faces(const std::array<std::filesystem::path, 6>& paths, const ConvertSettings& settings,
                            ShDocument& out);

}  // namespace shpack::io
