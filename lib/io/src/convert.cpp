#include "shpack/io/convert.h"

#include <future>
#include <string>
#include <utility>
#include <vector>

#include "convert_errors.h"
#include "shpack/io/sha256.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;
using detail::check_settings;
using detail::core_error;
using detail::nonfinite_error;

// Stage 3 streamed: bands of rows into the core's EquirectProjector, NaN/Inf counted.
// The same bands go into the reference E/pi of the view error, sampled here.
IoStatus project_streamed(MapSource& source, const ConvertOptions& options, ShL2& radiance, ProjectStats& stats,
                          ViewSamples& samples) {
  const fs::path& path = source.path();
  EquirectProjector projector;
  ViewReference reference;
  const ProjectOptions project{options.method.method, NonFinite::Zero, options.negative, options.threads};
  if (Status st = projector.begin(source.info().width, source.info().height, project); !st.ok())
    return core_error(path, st);
  if (Status st = reference.begin_equirect(source.info().width, source.info().height, project); !st.ok())
    return core_error(path, st);
  if (IoStatus st = source.stream_into(projector, reference, options.threads); !st.ok()) return st;
  if (Status st = projector.finish(radiance, &stats); !st.ok()) return core_error(path, st);
  if (Status st = reference.finish(); !st.ok()) return core_error(path, st);
  if (Status st = sample_view_reference(std::move(reference), samples, options.threads); !st.ok()) return core_error(path, st);
  return IoStatus::success();
}

// The options of stages 2 to 4 with what the source resolved (its colour matrix).
ConvertOptions resolved(const ConvertSettings& settings, const SourceInfo& info) {
  ConvertOptions options = settings.convert;
  options.finish.colour_matrix = info.colour.matrix;
  return options;
}

// Stages 2 to 4 of an opened source.
IoStatus run_stages(MapSource& source, const ConvertSettings& settings, Conversion& out) {
  const fs::path& path = source.path();
  const ConvertOptions options = resolved(settings, source.info());
  const Layout layout = source.info().layout;
  if (Status st = check_convert_options(options, layout, source.cube_frame()); !st.ok()) return core_error(path, st);
  if (streams_rows(options, layout)) {
    ShL2 radiance;
    ProjectStats stats;
    ViewSamples samples;
    if (IoStatus st = project_streamed(source, options, radiance, stats, samples); !st.ok()) return st;
    if (!apply_nonfinite_policy(stats, options.nonfinite).ok()) return nonfinite_error(path, stats, options.method);
    if (Status st = finish_conversion(radiance, stats, Extraction{}, options.finish, &samples, out); !st.ok())
      return core_error(path, st);
    return IoStatus::success();
  }
  MapImage map;
  if (IoStatus st = source.read_whole(map, options.threads); !st.ok()) return st;
  ProjectStats seen;
  if (Status st = convert_map(map, options, out, &seen); !st.ok()) {
    if (st.code == Errc::NonFiniteTexel)
      return nonfinite_error(source.path(seen.first_nonfinite_face), seen, options.method);
    return core_error(path, st);
  }
  return IoStatus::success();
}

ShReading reading_of(const ConvertSettings& settings, const SourceInfo& info) {
  return {settings.source.layer, settings.source.cube_frame, info.colour.name, info.ignored_channels};
}

}  // namespace

IoStatus convert_file(const fs::path& path, const ConvertSettings& settings, Conversion& out, SourceInfo* info) {
  if (IoStatus st = check_settings(path, settings); !st.ok()) return st;
  MapSource source;
  if (IoStatus st = source.open(path, settings.source); !st.ok()) return st;
  if (IoStatus st = run_stages(source, settings, out); !st.ok()) return st;
  if (info != nullptr) *info = source.info();
  return IoStatus::success();
}

IoStatus convert_env_map(const fs::path& path, const ConvertSettings& settings, ShDocument& out) {
  if (IoStatus st = check_settings(path, settings); !st.ok()) return st;
  // The file is hashed on its own thread while it is decoded and projected: hashing is a
  // second pass over the file (about 0.7 s of the 1.4 GB 16384x8192 map's 8 s), which
  // overlapped with the decoder's wait for the disk and page cache costs almost nothing.
  std::string digest;
  std::future<IoStatus> hashed = std::async(std::launch::async, [&] { return sha256_file(path, digest); });
  Conversion conversion;
  SourceInfo info;
  if (IoStatus st = convert_file(path, settings, conversion, &info); !st.ok()) return st;  // ~future waits
  if (IoStatus st = hashed.get(); !st.ok()) return st;
  ShSource source{{path.filename().string()}, {digest}, info.layout, info.width, info.height};
  out = make_document(std::move(source), reading_of(settings, info), resolved(settings, info), conversion);
  return IoStatus::success();
}

IoStatus convert_cube_faces(const std::array<fs::path, kCubeFaceCount>& paths, const ConvertSettings& settings,
                            ShDocument& out) {
  if (IoStatus st = check_settings(paths[0], settings); !st.ok()) return st;
  if (Status st = check_convert_options(settings.convert, Layout::Faces, settings.source.cube_frame); !st.ok())
    return core_error(paths[0], st);  // before six files are read
  MapSource source;
  if (IoStatus st = source.open_faces(paths, settings.source); !st.ok()) return st;
  Conversion conversion;
  if (IoStatus st = run_stages(source, settings, conversion); !st.ok()) return st;
  const SourceInfo& info = source.info();
  ShSource files{{}, {}, Layout::Faces, info.width, info.height};
  for (const fs::path& path : paths) {
    std::string digest;
    if (IoStatus st = sha256_file(path, digest); !st.ok()) return st;
    files.files.push_back(path.filename().string());
    files.sha256.push_back(std::move(digest));
  }
  out = make_document(std::move(files), reading_of(settings, info), resolved(settings, info), conversion);
  return IoStatus::success();
}

}  // namespace shpack::io
