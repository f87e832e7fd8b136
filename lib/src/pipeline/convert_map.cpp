// convert_map.cpp - stages 3 and 4 of the pipeline (pipeline.h) on a whole image, after stage 2
// (extraction.cpp), and the checks that decide which stages run.
#include <new>
#include <utility>
#include <vector>

#include "shpack/pipeline.h"
#include "shpack/project_cube.h"
#include "shpack/project_sphere_map.h"
#include "pipeline/layout_dispatch.h"

namespace shpack {
using detail::cube_layout_of;
using detail::is_sphere_map;
using detail::sphere_map_of;

namespace {

// The frame's signs on the coefficients (conventions.h cube_frame_sign).
void apply_cube_frame(CubeFrame frame, ShL2& radiance) noexcept {
  for (auto& channel : radiance.c)
    for (int i = 0; i < kShCount; ++i) channel[i] *= cube_frame_sign(frame)[i];
}

// Face-local coordinates of the first NaN/Inf texel -> the image's (single-image cube layouts).
void to_image_coordinates(const MapImage& map, std::uint32_t face_size, ProjectStats& stats) noexcept {
  const CubeLayout layout = cube_layout_of(map.layout);
  const CubeCell cell = cube_layout_cell(layout, static_cast<CubeFace>(stats.first_nonfinite_face));
  const std::uint32_t n = face_size, x = stats.first_nonfinite_x, y = stats.first_nonfinite_y;
  const bool one_texel = map.image.width == 1;  // a 1 x 1 image is every face
  stats.first_nonfinite_x = one_texel ? 0 : cell.column * n + (cell.rotated_180 ? n - 1 - x : x);
  stats.first_nonfinite_y = one_texel ? 0 : cell.row * n + (cell.rotated_180 ? n - 1 - y : y);
}

// Stage 3: the projector the layout and the method choose, counting NaN/Inf (zeroed).
Status project(const MapImage& map, const ConvertOptions& options, ShL2& radiance, ProjectStats& stats) noexcept {
  ProjectOptions project{options.method.method, NonFinite::Zero, options.negative, options.threads};
  if (map.layout == Layout::Equirect) return project_with_method(map.image, options.method, project, radiance, &stats);
  if (is_sphere_map(map.layout)) return project_sphere_map(map.image, sphere_map_of(map.layout), project, radiance, &stats);
  std::array<ImageView, kCubeFaceCount> faces = map.faces;
  if (map.layout != Layout::Faces) {
    if (Status st = cube_face_views(map.image, cube_layout_of(map.layout), faces); !st.ok()) return st;
  }
  if (Status st = project_cube(faces, project, radiance, &stats); !st.ok()) return st;
  apply_cube_frame(map.cube_frame, radiance);
  if (map.layout != Layout::Faces && stats.nonfinite_texels != 0) to_image_coordinates(map, faces[0].width, stats);
  return Status::success();
}

}  // namespace

Status check_convert_options(const ConvertOptions& options, Layout layout, CubeFrame cube_frame) noexcept {
  if (Status st = validate_method(options.method); !st.ok()) return st;
  if (Status st = check_finish_options(options.finish); !st.ok()) return st;
  if (layout == Layout::Auto) return Status::error(Errc::InvalidArgument, "the layout is not resolved");
  const bool closed_form = options.method.method == SamplingMethod::Exact || options.method.method == SamplingMethod::Center;
  if (!closed_form && layout != Layout::Equirect)
    return Status::error(Errc::InvalidArgument, "the sampling methods read equirect maps only; use exact or center");
  if (options.extract_sun && layout != Layout::Equirect)
    return Status::error(Errc::InvalidArgument, "--extract-sun reads equirect maps only");
  if (options.extract_lights > 0 && layout != Layout::Equirect)
    return Status::error(Errc::InvalidArgument, "--extract-lights reads equirect maps only");
  if (options.extract_lights > kMaxExtractedLights)
    return Status::error(Errc::InvalidArgument, "--extract-lights takes at most 8 lights");
  if (options.extract_sun && options.extract_lights > 0)
    return Status::error(Errc::InvalidArgument,
                         "--extract-sun and --extract-lights exclude each other (the sun is --extract-lights' first)");
  if (is_sphere_map(layout) && options.method.method != SamplingMethod::Exact)
    return Status::error(Errc::InvalidArgument, "octahedral, angular and mirror ball maps are projected with exact only");
  if (cube_frame != CubeFrame::Unity && !is_cube_layout(layout))
    return Status::error(Errc::InvalidArgument, "a cube frame applies to cube layouts only");
  return Status::success();
}

bool needs_transform(const ConvertOptions& options) noexcept {
  return options.extract_sun || options.extract_lights > 0;
}

bool streams_rows(const ConvertOptions& options, Layout layout) noexcept {
  return layout == Layout::Equirect && !needs_transform(options) &&
         (options.method.method == SamplingMethod::Exact || options.method.method == SamplingMethod::Center);
}

Status apply_nonfinite_policy(const ProjectStats& stats, NonFinite policy) noexcept {
  if (policy == NonFinite::Error && stats.nonfinite_texels != 0)
    return Status::error(Errc::NonFiniteTexel, "NaN or Inf texels", stats.first_nonfinite_x, stats.first_nonfinite_y,
                         stats.first_nonfinite_face);
  return Status::success();
}

Status convert_map(const MapImage& map, const ConvertOptions& options, Conversion& out, ProjectStats* seen) noexcept {
  if (Status st = check_convert_options(options, map.layout, map.cube_frame); !st.ok()) return st;
  // The truth is the input as it is, before any transform takes a light out of it.
  ViewSamples reference;
  if (Status st = sample_map_reference(map, options, reference); !st.ok()) return st;
  Extraction extraction;
  if (needs_transform(options)) {
    if (Status st = extract_from_map(map, options, reference, extraction); !st.ok()) return st;
  }
  ShL2 radiance;
  ProjectStats stats;
  if (Status st = project(map, options, radiance, stats); !st.ok()) return st;
  if (Status st = apply_nonfinite_policy(stats, options.nonfinite); !st.ok()) {
    if (seen != nullptr) *seen = stats;
    return st;
  }
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) radiance.c[c][i] -= extraction.removed.c[c][i];
  return finish_conversion(radiance, stats, extraction, options.finish, &reference, out);
}

Status finish_conversion(const ShL2& projected, const ProjectStats& stats, const Extraction& extraction,
                         const FinishOptions& options, const ViewSamples* reference, Conversion& out) noexcept {
  try {
    Conversion result;
    result.stats = stats;
    if (Status st = finish_projection(projected, options, result.sh); !st.ok()) return st;
    std::vector<UnitySunLight> shown;  // every light Unity lights the scene with
    if (extraction.sun) {
      result.sun = finish_light(*extraction.sun, options);
      shown.push_back(result.sun->unity);
    }
    for (std::size_t k = 0; k < extraction.lights.size(); ++k) {
      const ChosenLight& step = extraction.choice.lights[k];
      result.lights.push_back({finish_light(extraction.lights[k], options), step.error_before, step.error_after});
      shown.push_back(result.lights.back().light.unity);
    }
    result.light_candidates = extraction.candidates;
    if (reference != nullptr) {
      const ViewTransform transform{options.colour_matrix, options.intensity, options.rotate_deg};
      ViewError error;
      if (Status st = searched_view_error(*reference, transform, result.sh.shader, shown, error); !st.ok()) return st;
      result.view_error = error;
    }
    out = std::move(result);
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory finishing the conversion");
  }
}

Status sample_map_reference(const MapImage& map, const ConvertOptions& options, ViewSamples& out) noexcept {
  ViewReference reference;
  const ProjectOptions project{SamplingMethod::Exact, NonFinite::Zero, options.negative, 1};
  if (Status st = build_view_reference(map, project, reference); !st.ok()) return st;
  return sample_view_reference(std::move(reference), out, options.threads);
}

}  // namespace shpack
