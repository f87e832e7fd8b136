// convert_pixels.cpp - stage 1 for pixels in memory (convert_pixels.h): the caller's views
// resolved as a file's source resolves its image, then the stages of a file read whole.
#include "shpack/io/convert_pixels.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "convert_errors.h"

namespace shpack::io {
namespace {

using detail::core_error;

// What the source stage resolves for a file (SourceInfo), for pixels.
struct PixelSource {
  MapImage map;
  ColourResolution colour;
  std::uint32_t ignored_channels = 0;
  std::uint32_t width = 0, height = 0;  // the image's, or one face's
};

// Channels that are not projected (image_view.h): alpha after grey, any after R, G, B.
std::uint32_t ignored_channels(const ImageView& view) {
  return view.channels >= 3 ? view.channels - 3 : view.channels - 1;
}

// "array[2]": the name of face `face` of six.
std::string face_name(const std::string& name, std::uint32_t face) {
  return std::string(name).append("[").append(std::to_string(face)).append("]");
}

std::string size_text(const ImageView& view) {
  return std::to_string(view.width).append("x").append(std::to_string(view.height));
}

IoStatus resolve_common(const std::string& name, const ConvertSettings& settings, PixelSource& source) {
  if (!settings.source.layer.empty())
    return IoStatus::error(IoErrc::InvalidArgument, name, "--layer names a part of a file; pixels in memory have none");
  std::string problem;
  if (!resolve_colorspace(settings.source.colorspace, std::nullopt, source.colour, problem))
    return IoStatus::error(IoErrc::Unsupported, name, problem);
  source.map.cube_frame = settings.source.cube_frame;
  return IoStatus::success();
}

// The stages after the source, as for a file read whole, and the document.
IoStatus run_stages(PixelSource& source, const std::string& name, const ConvertSettings& settings,
                    ShDocument& out) {
  ConvertOptions options = settings.convert;
  options.finish.colour_matrix = source.colour.matrix;
  if (Status st = check_convert_options(options, source.map.layout, source.map.cube_frame); !st.ok())
    return core_error(name, st);
  std::vector<float> copy;
  if (needs_transform(options)) {
    if (Status st = make_writable(source.map, copy); !st.ok()) return core_error(name, st);
  }
  Conversion conversion;
  ProjectStats seen;
  if (Status st = convert_map(source.map, options, conversion, &seen); !st.ok()) {
    if (st.code != Errc::NonFiniteTexel) return core_error(name, st);
    const bool faces = source.map.layout == Layout::Faces;
    return detail::nonfinite_error(faces ? face_name(name, seen.first_nonfinite_face) : name, seen, options.method);
  }
  ShSource files{{}, {}, source.map.layout, source.width, source.height};
  ShReading reading{"", settings.source.cube_frame, source.colour.name, source.ignored_channels};
  out = make_document(std::move(files), std::move(reading), options, conversion);
  return IoStatus::success();
}

}  // namespace

IoStatus convert_pixels(const ImageView& image, const std::string& name, const ConvertSettings& settings,
                        ShDocument& out) {
  if (IoStatus st = detail::check_settings(name, settings); !st.ok()) return st;
  PixelSource source;
  if (IoStatus st = resolve_common(name, settings, source); !st.ok()) return st;
  source.map.image = image;
  if (Status st = resolve_view(source.map.image); !st.ok()) return core_error(name, st);
  const ImageView& view = source.map.image;
  const Layout requested = settings.source.layout;
  if (requested == Layout::Faces)
    return IoStatus::error(IoErrc::InvalidArgument, name, "the faces layout takes six faces, not one image");
  if (const std::string problem = layout_shape_problem(requested, view.width, view.height); !problem.empty())
    return IoStatus::error(IoErrc::UnknownLayout, name, problem);
  source.map.layout = resolve_layout(requested, view.width, view.height);
  source.ignored_channels = ignored_channels(view);
  source.width = view.width;
  source.height = view.height;
  return run_stages(source, name, settings, out);
}

IoStatus convert_pixel_faces(const std::array<ImageView, kCubeFaceCount>& faces, const std::string& name,
                             const ConvertSettings& settings, ShDocument& out) {
  if (IoStatus st = detail::check_settings(name, settings); !st.ok()) return st;
  PixelSource source;
  if (IoStatus st = resolve_common(name, settings, source); !st.ok()) return st;
  source.map.layout = Layout::Faces;
  for (std::uint32_t f = 0; f < kCubeFaceCount; ++f) {
    ImageView& face = source.map.faces[f];
    face = faces[f];
    if (Status st = resolve_view(face); !st.ok()) return core_error(face_name(name, f), st);
    if (face.width != face.height) {
      return IoStatus::error(IoErrc::Unsupported, face_name(name, f),
                             std::string("the face is ").append(size_text(face)).append(", not square"));
    }
    if (face.width != source.map.faces[0].width) {
      return IoStatus::error(IoErrc::Unsupported, face_name(name, f),
                             std::string("the face is ")
                                 .append(size_text(face))
                                 .append(" but ")
                                 .append(face_name(name, 0))
                                 .append(" is ")
                                 .append(size_text(source.map.faces[0])));
    }
    source.ignored_channels += ignored_channels(face);
  }
  source.width = source.height = source.map.faces[0].width;
  return run_stages(source, name, settings, out);
}

}  // namespace shpack::io
