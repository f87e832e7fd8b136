#include "shpack/io/convert.h"

#include <future>
#include <optional>
#include <string>
#include <utility>

#include "shpack/convolution.h"
#include "shpack/io/colorspace.h"
#include "shpack/io/method_projection.h"
#include "shpack/io/sha256.h"
#include "shpack/pipeline.h"

namespace shpack::io {
namespace {

// The colour space the input is taken as, and the matrix to linear Rec. 709 (identity for
// Rec. 709 itself): --colorspace if given, else the file's chromaticities, else Rec. 709.
IoStatus colour_matrix(const std::filesystem::path& path, const ConvertSettings& settings,
                       const std::optional<Chromaticities>& file, std::string& name, std::optional<Matrix3>& matrix) {
  Chromaticities chromaticities = colorspace_chromaticities(ColorSpace::LinearRec709);
  if (settings.colorspace != ColorSpace::Auto) {
    chromaticities = colorspace_chromaticities(settings.colorspace);
    name = colorspace_name(settings.colorspace);
  } else if (file.has_value()) {
    chromaticities = *file;
    const ColorSpace named = named_colorspace(*file);
    name = named == ColorSpace::Auto ? "file" : colorspace_name(named);
  } else {
    name = colorspace_name(ColorSpace::LinearRec709);
  }
  if (named_colorspace(chromaticities) == ColorSpace::LinearRec709) return IoStatus::success();
  Matrix3 m;
  std::string problem;
  if (!rgb_to_rec709_matrix(chromaticities, m, problem))
    return IoStatus::error(IoErrc::Unsupported, path, problem + "; --colorspace can name the primaries");
  matrix = m;
  return IoStatus::success();
}

FinishOptions finish_options(const ConvertSettings& settings) {
  return {settings.intensity, settings.rotate_deg, settings.window};
}

// The document of a projection: colour, intensity, rotation, window, Unity form, minimum.
// `path` names the input in errors.
IoStatus finish_document(const std::filesystem::path& path, const ConvertSettings& settings,
                         const EnvMapProjection& projection, ShDocument& doc) {
  if (IoStatus st = colour_matrix(path, settings, projection.info.chromaticities, doc.reading.colorspace,
                                  doc.colour_matrix);
      !st.ok())
    return st;
  doc.reading.layer = settings.env_map.layer;
  doc.reading.cube_frame = settings.env_map.cube_frame;
  doc.method = settings.method;
  doc.intensity = settings.intensity;
  doc.rotate_deg = settings.rotate_deg;
  doc.window = settings.window;
  const ShL2 linear = doc.colour_matrix ? mix_channels(projection.radiance, *doc.colour_matrix) : projection.radiance;
  FinishedSh finished;
  if (Status st = finish_projection(linear, finish_options(settings), finished);
      !st.ok())
    return IoStatus::error(st.code == Errc::OutOfRange ? IoErrc::Unsupported : IoErrc::InvalidArgument, path, st.what);
  doc.radiance = finished.radiance;
  doc.unity_form = finished.unity_form;
  doc.diagnostics = {projection.stats.nonfinite_texels, projection.stats.negative_texels,
                     projection.info.ignored_channels, finished.min_e_over_pi, finished.window.factors,
                     finished.window.impossible};
  return IoStatus::success();
}

// finish_projection's option checks, before any image is read.
IoStatus check_settings(const std::filesystem::path& path, const ConvertSettings& settings) {
  if (Status st = check_finish_options(finish_options(settings)); !st.ok())
    return IoStatus::error(IoErrc::InvalidArgument, path, st.what);
  return IoStatus::success();
}

}  // namespace

IoStatus convert_env_map(const std::filesystem::path& path, const ConvertSettings& settings,
                         ShDocument& out) {
  if (IoStatus st = check_settings(path, settings); !st.ok()) return st;
  // The file is hashed on its own thread while it is decoded and projected: hashing is a
  // second pass over the file (about 0.7 s of the 1.4 GB 16384x8192 map's 8 s), which
  // overlapped with the decoder's wait for the disk and page cache costs almost nothing.
  std::string digest;
  std::future<IoStatus> hashed = std::async(std::launch::async, [&] { return sha256_file(path, digest); });
  EnvMapProjection projection;
  if (IoStatus st = project_env_map_with_method(path, settings.env_map, settings.method, projection);
      !st.ok())
    return st;  // ~future waits for the hash
  if (IoStatus st = hashed.get(); !st.ok()) return st;

  ShDocument doc;
  doc.source = {{path.filename().string()}, {digest}, projection.info.layout,
                projection.info.width, projection.info.height};
  if (IoStatus st = finish_document(path, settings, projection, doc); !st.ok()) return st;
  out = std::move(doc);
  return IoStatus::success();
}

IoStatus convert_cube_faces(const std::array<std::filesystem::path, 6>& paths, const ConvertSettings& settings,
                            ShDocument& out) {
  if (IoStatus st = check_settings(paths[0], settings); !st.ok()) return st;
  if (!streams_file(settings.method.method)) {
    return IoStatus::error(IoErrc::Unsupported, paths[0],
                           std::string(method_name(settings.method).view()) +
                               " reads equirect maps only (faces given); use exact or center");
  }
  EnvMapOptions options = settings.env_map;
  options.project.method = settings.method.method == SamplingMethod::Exact ? Method::Exact : Method::Center;
  EnvMapProjection projection;
  if (IoStatus st = project_cube_faces(paths, options, projection); !st.ok()) return st;
  ShDocument doc;
  doc.source.layout = Layout::Faces;
  doc.source.width = projection.info.width;
  doc.source.height = projection.info.height;
  for (const std::filesystem::path& path : paths) {
    std::string digest;
    if (IoStatus st = sha256_file(path, digest); !st.ok()) return st;
    doc.source.files.push_back(path.filename().string());
    doc.source.sha256.push_back(std::move(digest));
  }
  if (IoStatus st = finish_document(paths[0], settings, projection, doc); !st.ok()) return st;
  out = std::move(doc);
  return IoStatus::success();
}

}  // namespace shpack::io
