#include "shpack/io/convert.h"

#include <cmath>
#include <string>
#include <utility>

#include "shpack/convolution.h"
#include "shpack/io/sha256.h"
#include "shpack/rotate.h"
#include "shpack/sh_minimum.h"
#include "shpack/unity_pack.h"

namespace shpack::io {
namespace {

bool fits_in_float(const ShL2& unity_form) noexcept {
  for (const auto& channel : to_unity_sh(unity_form))
    for (const float v : channel)
      if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

IoStatus convert_env_map(const std::filesystem::path& path, const ConvertSettings& settings,
                         ShDocument& out) {
  if (!std::isfinite(settings.intensity) || settings.intensity < 0)
    return IoStatus::error(IoErrc::InvalidArgument, path, "intensity must be finite and >= 0");
  if (!std::isfinite(settings.rotate_deg))
    return IoStatus::error(IoErrc::InvalidArgument, path, "rotation must be a finite number of degrees");
  EnvMapProjection projection;
  if (IoStatus st = project_env_map(path, settings.env_map, projection); !st.ok()) return st;
  std::string digest;
  if (IoStatus st = sha256_file(path, digest); !st.ok()) return st;

  ShDocument doc;
  doc.source = {{path.filename().string()}, {digest}, projection.info.layout,
                projection.info.width, projection.info.height};
  doc.method = settings.env_map.project.method;
  doc.intensity = settings.intensity;
  doc.rotate_deg = settings.rotate_deg;
  doc.window = settings.window;
  const ShL2 radiance = rotate_about_y(scaled(projection.radiance, settings.intensity), settings.rotate_deg);
  WindowResult windowed;
  if (Status st = apply_window(radiance_to_unity_form(radiance), settings.window, doc.unity_form, &windowed);
      !st.ok())
    return IoStatus::error(IoErrc::InvalidArgument, path, st.what);
  doc.radiance = apply_band_factors(radiance, windowed.factors);
  if (!fits_in_float(doc.unity_form)) {
    return IoStatus::error(IoErrc::Unsupported, path,
                           "the lighting is too bright for Unity's float32 coefficients");
  }
  doc.diagnostics = {projection.stats.nonfinite_texels, projection.stats.negative_texels,
                     projection.info.ignored_channels, {}, windowed.factors, windowed.impossible};
  for (int c = 0; c < kChannelCount; ++c)
    doc.diagnostics.min_e_over_pi[c] = minimum_on_sphere(doc.unity_form, c);
  out = std::move(doc);
  return IoStatus::success();
}

}  // namespace shpack::io
