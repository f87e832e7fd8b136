#include "environment.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shpack/convolution.h"
#include "shpack/io/env_map.h"
#include "shpack/lights.h"
#include "shpack/sky.h"

namespace shpack::bake {

io::IoStatus EnvironmentSource::load(const io::Scene& scene, bool need_lookup, unsigned threads) {
  env_ = scene.environment;
  sh_ = {};
  if (env_.type == io::EnvironmentType::Gradient) {
    if (Status st = add_gradient_sky(env_.zenith, env_.horizon, env_.ground, sh_); !st.ok())
      return io::IoStatus::error(io::IoErrc::InvalidArgument, scene.file, std::string("environment: ") + st.what);
    return io::IoStatus::success();
  }
  if (env_.type == io::EnvironmentType::Preetham) {
    if (Status st = add_preetham_sky(env_.preetham, sh_); !st.ok())
      return io::IoStatus::error(io::IoErrc::InvalidArgument, scene.file, std::string("environment: ") + st.what);
    return io::IoStatus::success();
  }
  if (env_.type != io::EnvironmentType::Map) return io::IoStatus::success();
  io::EnvMapOptions options;
  options.layout = env_.layout;
  options.project.threads = threads;
  io::EnvMapProjection projection;
  if (io::IoStatus st = io::project_env_map(env_.path, options, projection); !st.ok())
    return io::IoStatus::error(st.code, scene.file, "environment.path: " + st.message);
  sh_ = rotate_about_y(scaled(projection.radiance, env_.intensity), env_.rotation_deg);
  rotation_ = rotation_about_y(env_.rotation_deg);
  if (need_lookup) {
    if (io::IoStatus st = io::read_image_file(env_.path, image_); !st.ok())
      return io::IoStatus::error(st.code, scene.file, "environment.path: " + st.message);
  }
  return io::IoStatus::success();
}

Rgb EnvironmentSource::radiance(const Vec3d& d) const noexcept {
  if (env_.type == io::EnvironmentType::Gradient) {
    if (d.y < 0) return env_.ground;
    Rgb out;
    for (int c = 0; c < 3; ++c) out[c] = env_.horizon[c] + (env_.zenith[c] - env_.horizon[c]) * d.y;
    return out;
  }
  if (env_.type == io::EnvironmentType::Preetham) {
    Rgb out{0, 0, 0};
    return preetham_radiance(env_.preetham, {d.x, d.y, d.z}, out).ok() ? out : Rgb{0, 0, 0};  // checked in load()
  }
  if (env_.type != io::EnvironmentType::Map || image_.pixels.empty()) return {0, 0, 0};
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
