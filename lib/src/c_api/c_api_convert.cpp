// c_api_convert.cpp - shpack_convert (shpack_c.h): a map of any layout with every option of
// `shpack convert`, handed to the pipeline's convert_map (pipeline.h). This file only
// translates: the C structs into a MapImage and ConvertOptions (stage 1, the caller's
// pixels), and the Conversion back into C structs.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "c_api_common.h"
#include "shpack/shpack_c.h"

namespace {

using shpack::Errc;
using shpack::Status;
using shpack::c_api::invalid;
using shpack::c_api::report;

static_assert(SHPACK_LAYOUT_AUTO == static_cast<int>(shpack::Layout::Auto) &&
                  SHPACK_LAYOUT_EQUIRECT == static_cast<int>(shpack::Layout::Equirect) &&
                  SHPACK_LAYOUT_HCROSS == static_cast<int>(shpack::Layout::HorizontalCross) &&
                  SHPACK_LAYOUT_VCROSS == static_cast<int>(shpack::Layout::VerticalCross) &&
                  SHPACK_LAYOUT_HSTRIP == static_cast<int>(shpack::Layout::HorizontalStrip) &&
                  SHPACK_LAYOUT_VSTRIP == static_cast<int>(shpack::Layout::VerticalStrip) &&
                  SHPACK_LAYOUT_OCTAHEDRAL == static_cast<int>(shpack::Layout::Octahedral) &&
                  SHPACK_LAYOUT_ANGULAR == static_cast<int>(shpack::Layout::Angular) &&
                  SHPACK_LAYOUT_MIRRORBALL == static_cast<int>(shpack::Layout::MirrorBall) &&
                  SHPACK_LAYOUT_FACES == static_cast<int>(shpack::Layout::Faces),
              "SHPACK_LAYOUT_* are the values of shpack::Layout");
static_assert(SHPACK_CUBE_FRAME_UNITY == static_cast<int>(shpack::CubeFrame::Unity) &&
                  SHPACK_CUBE_FRAME_GL == static_cast<int>(shpack::CubeFrame::Gl) &&
                  SHPACK_CUBE_FRAME_THREEJS == static_cast<int>(shpack::CubeFrame::ThreeJs),
              "SHPACK_CUBE_FRAME_* are the values of shpack::CubeFrame");

// The pipeline's options of a shpack_convert_options, as `convert` sets them from its flags
// (cli/convert_command.cpp): the intensity times 2^exposure is the one linear factor.
Status to_convert_options(const shpack_convert_options& options, shpack::ConvertOptions& out) {
  shpack::ConvertOptions result;
  if (Status st = shpack::c_api::to_policies(options.nonfinite, options.negative, result); !st.ok()) return st;
  const char* method = options.method != nullptr ? options.method : "exact";
  if (Status st = shpack::parse_method(method, result.method); !st.ok()) return st;
  if (options.window != nullptr) {
    if (Status st = shpack::parse_window(options.window, result.finish.window); !st.ok()) return st;
  }
  if ((options.extract_sun != 0 && options.extract_sun != 1) || (options.l1 != 0 && options.l1 != 1))
    return Status::error(Errc::InvalidArgument, "extract_sun and l1 must be 0 or 1");
  if (options.extract_lights > SHPACK_MAX_EXTRACTED_LIGHTS)
    return Status::error(Errc::InvalidArgument, "extract_lights must be 0 to SHPACK_MAX_EXTRACTED_LIGHTS");
  const double factor = options.intensity * std::exp2(options.exposure_ev);
  if (!std::isfinite(factor))
    return Status::error(Errc::InvalidArgument, "intensity times 2^exposure_ev is not a finite number");
  result.threads = options.threads;
  result.extract_sun = options.extract_sun == 1;
  result.extract_lights = options.extract_lights;
  result.finish.intensity = factor;
  result.finish.rotate_deg = options.rotate_deg;
  result.finish.l1 = options.l1 == 1;
  out = result;
  return Status::success();
}

// The layout of the map: named, or detected from the image's size (layout.h).
Status resolve_map_layout(const shpack_map& map, shpack::Layout& layout) {
  if (map.layout < SHPACK_LAYOUT_AUTO || map.layout > SHPACK_LAYOUT_FACES)
    return Status::error(Errc::InvalidArgument, "layout must be one of SHPACK_LAYOUT_*");
  layout = static_cast<shpack::Layout>(map.layout);
  if (layout == shpack::Layout::Faces) return Status::success();
  layout = shpack::resolve_layout(layout, map.image.width, map.image.height);
  if (layout == shpack::Layout::Auto)
    return Status::error(Errc::InvalidArgument,
                         "the layout cannot be detected from the image's size (square, or no layout fits); name it");
  return Status::success();
}

// Stage 1 for pixels the caller holds: the MapImage of a shpack_map. `copy` receives the
// writable pixels when a transform needs them.
Status to_map_image(const shpack_map& map, bool writable, shpack::MapImage& out, std::vector<float>& copy) {
  shpack::MapImage image;
  if (Status st = resolve_map_layout(map, image.layout); !st.ok()) return st;
  if (map.cube_frame < SHPACK_CUBE_FRAME_UNITY || map.cube_frame > SHPACK_CUBE_FRAME_THREEJS)
    return Status::error(Errc::InvalidArgument, "cube_frame must be one of SHPACK_CUBE_FRAME_*");
  image.cube_frame = static_cast<shpack::CubeFrame>(map.cube_frame);
  if (image.layout == shpack::Layout::Faces) {
    for (int f = 0; f < 6; ++f)
      if (Status st = shpack::c_api::to_view(map.faces[f], image.faces[f]); !st.ok()) return st;
  } else {
    if (Status st = shpack::c_api::to_view(map.image, image.image); !st.ok()) return st;
    if (writable) {
      if (Status st = shpack::make_writable(image, copy); !st.ok()) return st;
    }
  }
  out = image;
  return Status::success();
}

template <std::size_t N>
void copy_array(const std::array<double, N>& from, double (&to)[N]) {
  for (std::size_t k = 0; k < N; ++k) to[k] = from[k];
}

void copy_dir(const shpack::Dir3& from, double (&to)[3]) {
  to[0] = from.x;
  to[1] = from.y;
  to[2] = from.z;
}

shpack_light light_of(const shpack::FinishedLight& finished) {
  const shpack::SunLight& light = finished.light;
  const shpack::UnitySunLight& unity = finished.unity;
  shpack_light out{};
  copy_dir(light.direction, out.direction);
  copy_array(light.irradiance, out.irradiance);
  copy_array(light.sky, out.sky_level);
  out.angular_radius_deg = light.radius_deg;
  out.solid_angle_sr = light.solid_angle;
  out.texels = light.texels;
  copy_dir(unity.forward, out.forward);
  copy_array(unity.euler_deg, out.euler_deg);
  copy_array(unity.quaternion, out.quaternion);
  copy_array(unity.colour, out.color);
  copy_array(unity.colour_srgb, out.color_srgb);
  out.intensity = unity.intensity;
  return out;
}

// The sizes of the structs before members were appended (shpack_c.h): an older caller's.
constexpr uint32_t kFirstOptionsSize = offsetof(shpack_convert_options, extract_lights);
constexpr uint32_t kFirstConversionSize = offsetof(shpack_conversion, view_error);

bool sizes_match(const shpack_map& map, const shpack_convert_options& options, const shpack_conversion& out) {
  return map.struct_size == sizeof(shpack_map) &&
         (options.struct_size == sizeof(shpack_convert_options) || options.struct_size == kFirstOptionsSize) &&
         (out.struct_size == sizeof(shpack_conversion) || out.struct_size == kFirstConversionSize);
}

// The caller's options, the members its struct_size does not hold read as 0.
shpack_convert_options options_of(const shpack_convert_options& caller) {
  shpack_convert_options options{};
  std::memcpy(&options, &caller, caller.struct_size);
  return options;
}

// The result for a caller whose struct ends at `size`: the members past it are not written.
void write_conversion(const shpack::Conversion& conversion, uint32_t size, shpack_conversion& out) {
  shpack_conversion result{};
  result.struct_size = size;
  result.sh = shpack::c_api::result_of(conversion);
  result.has_sun = conversion.sun.has_value() ? 1 : 0;
  if (conversion.sun) result.sun = light_of(*conversion.sun);
  result.view_error = shpack::c_api::view_error_of(conversion);
  const shpack::WindowResult& window = conversion.sh.window;
  for (int c = 0; c < 3; ++c) {
    result.window_rms_change[c] = window.rms_change[c];
    result.window_planes[c] = window.planes[c];
    if (window.impossible[c]) result.window_impossible |= 1 << c;
  }
  result.light_count = static_cast<uint32_t>(conversion.lights.size());
  result.light_candidates = static_cast<uint32_t>(conversion.light_candidates);
  for (std::size_t k = 0; k < conversion.lights.size(); ++k) {
    const shpack::ExtractedLight& light = conversion.lights[k];
    result.lights[k] = {light_of(light.light), light.error_before_pct, light.error_after_pct};
  }
  std::memcpy(&out, &result, size);
}

}  // namespace

extern "C" {

void shpack_default_convert_options(shpack_convert_options* options) {
  if (options != nullptr)
    *options = {sizeof(shpack_convert_options), SHPACK_NONFINITE_ERROR, SHPACK_NEGATIVE_KEEP, 0, 1.0, 0.0, 0.0,
                nullptr, nullptr, 0, 0, 0, 0};
}

int32_t shpack_convert(const shpack_map* map, const shpack_convert_options* options, shpack_conversion* out,
                       shpack_error* error) {
  if (map == nullptr || options == nullptr || out == nullptr)
    return invalid("map, options and out must not be NULL", error);
  if (!sizes_match(*map, *options, *out))
    return invalid("struct_size must be the sizeof of shpack_map, shpack_convert_options and shpack_conversion",
                   error);
  shpack::ConvertOptions convert;
  if (Status st = to_convert_options(options_of(*options), convert); !st.ok()) return report(st, error);
  shpack::MapImage image;
  std::vector<float> copy;
  if (Status st = to_map_image(*map, shpack::needs_transform(convert), image, copy); !st.ok())
    return report(st, error);
  shpack::Conversion conversion;
  if (Status st = shpack::convert_map(image, convert, conversion); !st.ok()) return report(st, error);
  write_conversion(conversion, out->struct_size, *out);
  return report(Status::success(), error);
}

}  // extern "C"
