#include "shpack/io/env_map.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include "image_source.h"
#include "shpack/cube_layout.h"
#include "shpack/io/image_file.h"
#include "shpack/project_cube.h"
#include "shpack/project_sphere_map.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;

// Rows per band: whole tiles, one per worker, within kBandBudgetBytes (at least one tile).
std::uint32_t band_rows(std::uint32_t width, std::uint32_t channels, unsigned threads) {
  const unsigned workers = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t row_bytes = std::size_t{width} * channels * sizeof(float);
  const std::size_t tiles_in_budget = kBandBudgetBytes / (row_bytes * kTileRows);
  const std::size_t tiles = std::clamp<std::size_t>(tiles_in_budget, 1, workers);
  return static_cast<std::uint32_t>(tiles * kTileRows);
}

IoStatus core_error(const fs::path& path, const Status& st) {
  return IoStatus::error(st.code == Errc::InvalidArgument ? IoErrc::InvalidArgument : IoErrc::Core, path, st.what);
}

IoStatus nonfinite_error(const fs::path& path, std::uint64_t count, std::uint32_t x, std::uint32_t y) {
  return IoStatus::error(IoErrc::NonFiniteTexel, path,
                         std::to_string(count) + " NaN/Inf texels (first at x=" + std::to_string(x) +
                             ", y=" + std::to_string(y) + ")");
}

// NaN/Inf texels are always counted and zeroed first, and the Error policy applied once the
// whole image is seen, so the message can say how many there are.
ProjectOptions counting(const ProjectOptions& options) {
  ProjectOptions project = options;
  project.nonfinite = NonFinite::Zero;
  return project;
}

IoStatus stream_equirect(const fs::path& path, detail::ImageSource& source, const EnvMapOptions& options,
                         EnvMapProjection& out) {
  const EnvMapInfo& info = out.info;
  const ProjectOptions project = counting(options.project);
  source.set_threads(project.threads);
  EquirectProjector projector;
  if (Status st = projector.begin(info.width, info.height, project); !st.ok()) return core_error(path, st);
  const std::uint32_t used = source.channels();
  const std::uint32_t rows_per_band = band_rows(info.width, used, project.threads);
  std::vector<float> band(std::size_t{info.width} * used * std::min(rows_per_band, info.height));
  for (std::uint32_t first = 0; first < info.height; first += rows_per_band) {
    const std::uint32_t count = std::min(rows_per_band, info.height - first);
    if (IoStatus st = source.read_rows(first, count, band.data()); !st.ok()) return st;
    const ImageView view = make_view(band.data(), info.width, count, used);
    if (Status st = projector.add_rows(view, first); !st.ok()) return core_error(path, st);
  }
  if (Status st = projector.finish(out.radiance, &out.stats); !st.ok()) return core_error(path, st);
  if (options.project.nonfinite == NonFinite::Error && out.stats.nonfinite_texels != 0)
    return nonfinite_error(path, out.stats.nonfinite_texels, out.stats.first_nonfinite_x, out.stats.first_nonfinite_y);
  return IoStatus::success();
}

CubeLayout cube_layout_of(Layout layout) noexcept {
  switch (layout) {
    case Layout::VerticalCross: return CubeLayout::VerticalCross;
    case Layout::HorizontalStrip: return CubeLayout::HorizontalStrip;
    case Layout::VerticalStrip: return CubeLayout::VerticalStrip;
    default: return CubeLayout::HorizontalCross;
  }
}

SphereMap sphere_map_of(Layout layout) noexcept {
  return layout == Layout::Angular ? SphereMap::Angular
         : layout == Layout::MirrorBall ? SphereMap::MirrorBall
                                        : SphereMap::Octahedral;
}

// The frame's signs on the coefficients (conventions.h cube_frame_sign).
void apply_cube_frame(CubeFrame frame, ShL2& radiance) noexcept {
  for (auto& channel : radiance.c)
    for (int i = 0; i < kShCount; ++i) channel[i] *= cube_frame_sign(frame)[i];
}

// Projects six faces; under NonFinite::Error with NaN/Inf texels, projects again with the
// Error policy to learn where the first one is (face-local x, y and the face).
IoStatus project_faces(const fs::path& path, const std::array<ImageView, kCubeFaceCount>& faces,
                       const EnvMapOptions& options, EnvMapProjection& out, Status& first_nonfinite) {
  if (Status st = project_cube(faces, counting(options.project), out.radiance, &out.stats); !st.ok())
    return core_error(path, st);
  apply_cube_frame(options.cube_frame, out.radiance);
  if (options.project.nonfinite == NonFinite::Error && out.stats.nonfinite_texels != 0) {
    ShL2 unused;
    first_nonfinite = project_cube(faces, options.project, unused);
  }
  return IoStatus::success();
}

IoStatus project_whole_image(const fs::path& path, detail::ImageSource& source, const EnvMapOptions& options,
                             EnvMapProjection& out) {
  const EnvMapInfo& info = out.info;
  source.set_threads(options.project.threads);
  std::vector<float> pixels(std::size_t{info.width} * info.height * source.channels());
  if (IoStatus st = source.read_rows(0, info.height, pixels.data()); !st.ok()) return st;
  const ImageView image = make_view(pixels.data(), info.width, info.height, source.channels());
  if (is_cube_layout(info.layout)) {
    const CubeLayout layout = cube_layout_of(info.layout);
    std::array<ImageView, kCubeFaceCount> faces;
    if (Status st = cube_face_views(image, layout, faces); !st.ok()) return core_error(path, st);
    Status first{};
    if (IoStatus st = project_faces(path, faces, options, out, first); !st.ok()) return st;
    if (first.code == Errc::NonFiniteTexel) {  // face-local -> image coordinates
      const std::uint32_t n = faces[0].width;
      const CubeCell cell = cube_layout_cell(layout, static_cast<CubeFace>(first.face));
      const std::uint32_t x = info.width == 1 ? 0 : cell.column * n + (cell.rotated_180 ? n - 1 - first.x : first.x);
      const std::uint32_t y = info.width == 1 ? 0 : cell.row * n + (cell.rotated_180 ? n - 1 - first.y : first.y);
      return nonfinite_error(path, out.stats.nonfinite_texels, x, y);
    }
    return IoStatus::success();
  }
  const SphereMap map = sphere_map_of(info.layout);
  if (Status st = project_sphere_map(image, map, counting(options.project), out.radiance, &out.stats); !st.ok())
    return core_error(path, st);
  if (options.project.nonfinite == NonFinite::Error && out.stats.nonfinite_texels != 0)
    return nonfinite_error(path, out.stats.nonfinite_texels, out.stats.first_nonfinite_x, out.stats.first_nonfinite_y);
  return IoStatus::success();
}

// Fills `out` completely or returns an error (project_env_map keeps `out` untouched then).
IoStatus project_opened(const fs::path& path, detail::ImageSource& source, const EnvMapOptions& options,
                        EnvMapProjection& out) {
  EnvMapInfo& info = out.info;
  info.width = source.width();
  info.height = source.height();
  info.channels = source.file_channels();
  info.ignored_channels = source.ignored_channels();
  info.format = source.format();
  info.srgb_decoded = source.srgb_decoded();
  info.chromaticities = source.chromaticities();
  if (const std::string problem = layout_shape_problem(options.layout, info.width, info.height); !problem.empty())
    return IoStatus::error(IoErrc::UnknownLayout, path, problem);
  info.layout = resolve_layout(options.layout, info.width, info.height);
  if (info.layout == Layout::Faces)
    return IoStatus::error(IoErrc::InvalidArgument, path, "the faces layout takes six files, not one image");
  if (options.cube_frame != CubeFrame::Unity && !is_cube_layout(info.layout)) {
    return IoStatus::error(IoErrc::InvalidArgument, path,
                           std::string("a cube frame applies to cube layouts only; this image is read as ") +
                               layout_name(info.layout));
  }
  if (info.layout == Layout::Equirect) return stream_equirect(path, source, options, out);
  return project_whole_image(path, source, options, out);
}

template <class Work>
IoStatus guarded(const fs::path& path, Work work) {
  try {
    return work();
  } catch (const std::bad_alloc&) {
    return IoStatus::error(IoErrc::Unreadable, path, "out of memory while reading");
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Unreadable, path, e.what());
  }
}

}  // namespace

IoStatus project_env_map(const fs::path& path, const EnvMapOptions& options, EnvMapProjection& out) {
  return guarded(path, [&] {
    detail::ImageSource source;
    if (IoStatus st = source.open(path, options.layer); !st.ok()) return st;
    EnvMapProjection result;
    if (IoStatus st = project_opened(path, source, options, result); !st.ok()) return st;
    out = std::move(result);
    return IoStatus::success();
  });
}

IoStatus project_cube_faces(const std::array<fs::path, 6>& paths, const EnvMapOptions& options,
                            EnvMapProjection& out) {
  std::array<ImageFile, kCubeFaceCount> files;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const fs::path& path = paths[f];
    if (IoStatus st = read_image_file(path, options.layer, files[f]); !st.ok()) return st;
    const ImageFile& face = files[f];
    const std::string size = std::to_string(face.width) + "x" + std::to_string(face.height);
    if (face.width != face.height)
      return IoStatus::error(IoErrc::Unsupported, path, "the face is " + size + ", not square");
    if (face.width != files[0].width) {
      return IoStatus::error(IoErrc::Unsupported, path,
                             "the face is " + size + " but " + paths[0].filename().string() + " is " +
                                 std::to_string(files[0].width) + "x" + std::to_string(files[0].height));
    }
    if (face.chromaticities != files[0].chromaticities) {
      return IoStatus::error(IoErrc::Unsupported, path,
                             "the face's chromaticities differ from those of " + paths[0].filename().string());
    }
  }
  return guarded(paths[0], [&] {
    EnvMapProjection result;
    EnvMapInfo& info = result.info;
    info.width = info.height = files[0].width;
    info.layout = Layout::Faces;
    info.format = files[0].format;
    info.chromaticities = files[0].chromaticities;
    std::array<ImageView, kCubeFaceCount> faces;
    for (int f = 0; f < kCubeFaceCount; ++f) {
      info.channels += files[f].file_channels;
      info.ignored_channels += files[f].ignored_channels();
      info.srgb_decoded = info.srgb_decoded || files[f].srgb_decoded;
      faces[f] = files[f].view();
    }
    Status first{};
    if (IoStatus st = project_faces(paths[0], faces, options, result, first); !st.ok()) return st;
    if (first.code == Errc::NonFiniteTexel) {
      const ImageFile& bad = files[first.face];
      std::uint64_t in_face = 0;  // texels with a NaN or Inf channel in that face's file
      for (std::size_t t = 0; t < bad.pixels.size(); t += bad.channels)
        in_face += std::any_of(&bad.pixels[t], &bad.pixels[t] + bad.channels, [](float v) { return !std::isfinite(v); });
      return IoStatus::error(IoErrc::NonFiniteTexel, paths[first.face],
                             std::to_string(in_face) + " NaN/Inf texels (first at x=" + std::to_string(first.x) +
                                 ", y=" + std::to_string(first.y) + ")");
    }
    out = std::move(result);
    return IoStatus::success();
  });
}

}  // namespace shpack::io
