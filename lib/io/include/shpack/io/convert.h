// convert.h - the pipeline (shpack/pipeline.h) run on files: `shpack convert`, and the
// environment maps of `shpack bake`.
//
// Stage 1 is the map source (map_source.h); stages 2 to 4 are the core's. When
// streams_rows says so (exact or center on an equirect map, no transform) the file is read
// in bands into the core's EquirectProjector; otherwise it is read whole and handed to
// convert_map. Either way the NaN/Inf policy, the finish and the document are the core's,
// so every option means the same on every path. Errors name the file (the face's file for
// six faces); under NonFinite::Error the message counts the NaN/Inf texels (for the
// sampling methods, the reads of them) and names the first.
#pragma once

#include <array>
#include <filesystem>

#include "shpack/document.h"
#include "shpack/io/io_status.h"
#include "shpack/io/map_source.h"
#include "shpack/pipeline.h"

namespace shpack::io {

struct ConvertSettings {
  SourceOptions source;   // stage 1
  ConvertOptions convert; // stages 2 to 4; its finish.colour_matrix is the source's, not read
};

// Stages 1 to 4 of one file. `info` (if given) receives what the source held.
IoStatus convert_file(const std::filesystem::path& path, const ConvertSettings& settings, Conversion& out,
                      SourceInfo* info = nullptr);

// convert_file, and the document (shpack/document.h) with the file's SHA-256. Errors as
// convert_file's, plus InvalidArgument for options that check_convert_options refuses
// (before the file is read beyond its header) and Unsupported when the result does not fit
// in float32 (Unity's storage). On failure `out` is left as it was.
IoStatus convert_env_map(const std::filesystem::path& path, const ConvertSettings& settings, ShDocument& out);

// Six face files in Unity's face order (map_source.h open_faces) to one document;
// source.files and sha256 list the six faces.
IoStatus convert_cube_faces(const std::array<std::filesystem::path, kCubeFaceCount>& paths,
                            const ConvertSettings& settings, ShDocument& out);

}  // namespace shpack::io
