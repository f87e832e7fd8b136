// method_projection.h - an environment map file projected with any method of
// sampling_methods.h (`shpack convert --method`).
//
// exact and center stream the file in bands (env_map.h), so memory stays bounded whatever
// the map's size. Every other method looks up texels by direction all over the sphere, so
// it needs the whole image: the file is read into memory as float (image_file.h, 12 bytes
// per RGB texel) and handed to project_with_method. Those methods read equirect maps only.
#pragma once

#include <filesystem>

#include "shpack/io/env_map.h"
#include "shpack/io/io_status.h"
#include "shpack/sampling_methods.h"

namespace shpack::io {

// True for the methods that project_env_map streams (exact, center).
constexpr bool streams_file(SamplingMethod method) noexcept {
  return method == SamplingMethod::Exact || method == SamplingMethod::Center;
}

// Projects `path` with `method`; options.project.method is ignored (the spec says which
// method runs), its value policies and thread count are used. Errors as project_env_map,
// plus InvalidArgument for a spec that validate_method rejects and Unsupported for a
// sampling method on a layout other than equirect. Under NonFinite::Error a sampling method
// fails only on the NaN/Inf texels its samples read (sampling_methods.h), and the message
// counts those reads. On failure `out` is left as it was.
IoStatus project_env_map_with_method(const std::filesystem::path& path, const EnvMapOptions& options,
                                     const MethodSpec& method, EnvMapProjection& out);

}  // namespace shpack::io
