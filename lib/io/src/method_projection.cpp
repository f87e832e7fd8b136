#include "shpack/io/method_projection.h"

#include <string>
#include <utility>

#include "shpack/io/image_file.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;

IoStatus project_whole_image(const fs::path& path, const EnvMapOptions& options,
                             const MethodSpec& method, EnvMapProjection& out) {
  ImageFile image;
  if (IoStatus st = read_image_file(path, image); !st.ok()) return st;
  EnvMapProjection result;
  EnvMapInfo& info = result.info;
  info = {image.width, image.height, image.file_channels, image.ignored_channels(),
          resolve_layout(options.layout, image.width, image.height), image.srgb_decoded, image.format,
          image.chromaticities};
  if (info.layout == Layout::Auto) {
    return IoStatus::error(IoErrc::UnknownLayout, path,
                           "the layout of a " + std::to_string(info.width) + "x" +
                               std::to_string(info.height) +
                               " image cannot be detected (2:1 is equirect, 1x1 is uniform)");
  }
  if (info.layout != Layout::Equirect) {
    return IoStatus::error(IoErrc::Unsupported, path,
                           std::string(method_name(method).view()) + " reads equirect maps only (" +
                               layout_name(info.layout) + " given); use exact or center");
  }
  // As in env_map.cpp: NaN/Inf are zeroed and counted, and the Error policy is applied
  // afterwards, so the message can say how many the samples read.
  ProjectOptions project = options.project;
  project.nonfinite = NonFinite::Zero;
  if (Status st = project_with_method(image.view(), method, project, result.radiance, &result.stats);
      !st.ok())
    return IoStatus::error(IoErrc::Core, path, st.what);  // the spec was validated: memory
  if (options.project.nonfinite == NonFinite::Error && result.stats.nonfinite_texels != 0) {
    return IoStatus::error(IoErrc::NonFiniteTexel, path,
                           std::to_string(result.stats.nonfinite_texels) + " NaN/Inf texel reads by " +
                               std::string(method_name(method).view()) + " (first at x=" +
                               std::to_string(result.stats.first_nonfinite_x) +
                               ", y=" + std::to_string(result.stats.first_nonfinite_y) + ")");
  }
  out = std::move(result);
  return IoStatus::success();
}

}  // namespace

IoStatus project_env_map_with_method(const fs::path& path, const EnvMapOptions& options,
                                     const MethodSpec& method, EnvMapProjection& out) {
  if (Status st = validate_method(method); !st.ok())
    return IoStatus::error(IoErrc::InvalidArgument, path, st.what);
  if (!streams_file(method.method)) return project_whole_image(path, options, method, out);
  EnvMapOptions streamed = options;
  streamed.project.method = method.method == SamplingMethod::Exact ? Method::Exact : Method::Center;
  return project_env_map(path, streamed, out);
}

}  // namespace shpack::io
