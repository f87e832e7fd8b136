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

// Cells of the sampling grid: a map's texels, or blocks of them for a map larger than
// kMaxCells x kMaxCells / 2 (the grid stays a few MB); an analytic sky's 128 x 64 cells.
constexpr std::uint32_t kMaxCells = 1024;

void EnvironmentSource::build_distribution() {
  const Matrix3 identity = rotation_about_y(0.0);
  if (env_.type == scene::EnvironmentType::Gradient || env_.type == scene::EnvironmentType::Preetham) {
    constexpr std::uint32_t cols = 128, rows = 64;
    distribution_ = DirectionDistribution(cols, rows, [&](std::uint32_t i, std::uint32_t j) {
      const double theta = std::numbers::pi * (j + 0.5) / rows, lon = 2.0 * std::numbers::pi * (0.5 - (i + 0.5) / cols);
      const Rgb l = radiance({std::sin(theta) * std::cos(lon), std::cos(theta), std::sin(theta) * std::sin(lon)});
      const double omega = 2.0 * std::numbers::pi / cols *
                           (std::cos(std::numbers::pi * j / rows) - std::cos(std::numbers::pi * (j + 1) / rows));
      return (l[0] + l[1] + l[2]) / 3.0 * omega;
    }, identity);
    return;
  }
  if (env_.type != scene::EnvironmentType::Map || image_.pixels.empty()) return;
  // Each texel's radiance times its solid angle, added to the cell holding its centre.
  const std::uint32_t w = image_.width, h = image_.height;
  const std::uint32_t cols = std::min(w, kMaxCells), rows = std::min(h, kMaxCells / 2);
  std::vector<double> cells(static_cast<std::size_t>(cols) * rows, 0.0);
  const std::size_t ch = image_.channels;
  for (std::uint32_t y = 0; y < h; ++y) {
    const double omega = 2.0 * std::numbers::pi / w *
                         (std::cos(std::numbers::pi * y / h) - std::cos(std::numbers::pi * (y + 1) / h));
    const std::size_t row = (static_cast<std::size_t>(y) * rows + rows / 2) / h;
    for (std::uint32_t x = 0; x < w; ++x) {
      const float* t = image_.pixels.data() + (static_cast<std::size_t>(y) * w + x) * ch;
      const double mean = ch >= 3 ? (static_cast<double>(t[0]) + t[1] + t[2]) / 3.0 : t[0];
      const std::size_t col = (static_cast<std::size_t>(x) * cols + cols / 2) / w;
      if (mean > 0 && std::isfinite(mean))
        cells[std::min<std::size_t>(row, rows - 1) * cols + std::min<std::size_t>(col, cols - 1)] += mean * omega;
    }
  }
  distribution_ = DirectionDistribution(cols, rows, [&](std::uint32_t i, std::uint32_t j) {
    return cells[static_cast<std::size_t>(j) * cols + i];
  }, rotation_);
}

io::IoStatus EnvironmentSource::load(const scene::Scene& scene, bool need_lookup, unsigned threads) {
  env_ = scene.environment;
  sh_ = {};
  distribution_ = {};
  if (env_.type == scene::EnvironmentType::Gradient) {
    if (Status st = add_gradient_sky(env_.zenith, env_.horizon, env_.ground, sh_); !st.ok())
      return io::IoStatus::error(io::IoErrc::InvalidArgument, scene.file, std::string("environment: ") + st.what);
    if (need_lookup) build_distribution();
    return io::IoStatus::success();
  }
  if (env_.type == scene::EnvironmentType::Preetham) {
    if (Status st = add_preetham_sky(env_.preetham, sh_); !st.ok())
      return io::IoStatus::error(io::IoErrc::InvalidArgument, scene.file, std::string("environment: ") + st.what);
    if (need_lookup) build_distribution();
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
    build_distribution();
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
