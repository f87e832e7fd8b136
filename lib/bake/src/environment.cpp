#include "environment.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shpack/convolution.h"
#include "shpack/io/convert.h"
#include "shpack/lights.h"
#include "shpack/sky.h"

namespace shpack::bake {
namespace {

// The lookup texels in the SH's primaries (colorspace.h): each RGB texel times `m`.
void to_rec709(const Matrix3& m, io::ImageFile& image) {
  if (image.channels < 3) return;  // grey stays grey: the matrix keeps white white
  for (std::size_t t = 0; t < image.pixels.size(); t += image.channels) {
    float* rgb = &image.pixels[t];
    const double r = rgb[0], g = rgb[1], b = rgb[2];
    for (int c = 0; c < 3; ++c) rgb[c] = static_cast<float>(m[c][0] * r + m[c][1] * g + m[c][2] * b);
  }
}

}  // namespace

io::IoStatus EnvironmentSource::load(const scene::Scene& scene, bool need_lookup, unsigned threads) {
  env_ = scene.environment;
  sh_ = {};
  if (env_.type == scene::EnvironmentType::Gradient) {
    if (Status st = add_gradient_sky(env_.zenith, env_.horizon, env_.ground, sh_); !st.ok())
      return io::IoStatus::error(io::IoErrc::InvalidArgument, scene.file, std::string("environment: ") + st.what);
    return io::IoStatus::success();
  }
  if (env_.type == scene::EnvironmentType::Preetham) {
    if (Status st = add_preetham_sky(env_.preetham, sh_); !st.ok())
      return io::IoStatus::error(io::IoErrc::InvalidArgument, scene.file, std::string("environment: ") + st.what);
    return io::IoStatus::success();
  }
  if (env_.type != scene::EnvironmentType::Map) return io::IoStatus::success();
  // The map through the one pipeline (io/convert.h), as `shpack convert` reads it: its
  // colour space, intensity and rotation applied by the finish stage.
  io::ConvertSettings settings;
  settings.source.layout = env_.layout;
  settings.convert.threads = threads;
  settings.convert.finish.intensity = env_.intensity;
  settings.convert.finish.rotate_deg = env_.rotation_deg;
  Conversion conversion;
  io::SourceInfo info;
  if (io::IoStatus st = io::convert_file(env_.path, settings, conversion, &info); !st.ok())
    return io::IoStatus::error(st.code, scene.file, "environment.path: " + st.message);
  sh_ = conversion.sh.radiance;
  rotation_ = rotation_about_y(env_.rotation_deg);
  if (need_lookup) {
    if (io::IoStatus st = io::read_image_file(env_.path, image_); !st.ok())
      return io::IoStatus::error(st.code, scene.file, "environment.path: " + st.message);
    if (info.colour.matrix) to_rec709(*info.colour.matrix, image_);
  }
  return io::IoStatus::success();
}

Rgb EnvironmentSource::radiance(const Vec3d& d) const noexcept {
  if (env_.type == scene::EnvironmentType::Gradient) {
    if (d.y < 0) return env_.ground;
    Rgb out;
    for (int c = 0; c < 3; ++c) out[c] = env_.horizon[c] + (env_.zenith[c] - env_.horizon[c]) * d.y;
    return out;
  }
  if (env_.type == scene::EnvironmentType::Preetham) {
    Rgb out{0, 0, 0};
    return preetham_radiance(env_.preetham, {d.x, d.y, d.z}, out).ok() ? out : Rgb{0, 0, 0};  // checked in load()
  }
  if (env_.type != scene::EnvironmentType::Map || image_.pixels.empty()) return {0, 0, 0};
  // The turned environment shows at d what the map holds at v = R^T d (rotate.h); then
  // conventions.h inverted: theta = acos(v.y), lon = atan2(v.z, v.x), u = 0.5 - lon / 2 pi.
  const Matrix3& r = rotation_;
  const double vx = r[0][0] * d.x + r[1][0] * d.y + r[2][0] * d.z;
  const double vy = r[0][1] * d.x + r[1][1] * d.y + r[2][1] * d.z;
  const double vz = r[0][2] * d.x + r[1][2] * d.y + r[2][2] * d.z;
  const double theta = std::acos(std::clamp(vy, -1.0, 1.0));
  double u = 0.5 - std::atan2(vz, vx) / (2.0 * std::numbers::pi);
  u -= std::floor(u);
  const auto w = image_.width, h = image_.height;
  const auto i = std::min<std::uint32_t>(w - 1, static_cast<std::uint32_t>(u * w));
  const auto j = std::min<std::uint32_t>(h - 1, static_cast<std::uint32_t>(theta / std::numbers::pi * h));
  const float* texel = image_.pixels.data() + (static_cast<std::size_t>(j) * w + i) * image_.channels;
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = env_.intensity * texel[image_.channels == 1 ? 0 : c];
  return out;
}

}  // namespace shpack::bake
