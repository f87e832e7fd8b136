#include "shpack/io/sun.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "equirect_integrals.h"
#include "shpack/io/image_file.h"
#include "shpack/io/layout.h"
#include "shpack/io/sha256.h"
#include "shpack/io/srgb.h"
#include "shpack/pipeline.h"
#include "shpack/rotate.h"

namespace shpack::io {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;
// Unity's LinearRgbToLuminance (UnityCG.cginc), as preview.h.
constexpr std::array<double, 3> kLuminance = {0.2126729, 0.7151522, 0.0721750};

double dot(const Dir3& a, const Dir3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The texels of one equirect image, read as RGB whatever the channel count.
class Texels {
 public:
  Texels(const ImageView& image, float* pixels) : image_(image), pixels_(pixels) {}

  std::uint32_t width() const { return image_.width; }
  std::uint32_t height() const { return image_.height; }
  std::array<double, 3> rgb(std::uint32_t x, std::uint32_t y) const {
    std::array<double, 3> out;
    for (int c = 0; c < 3; ++c) {
      float v;
      std::memcpy(&v, image_.pixel(x, y) + 4 * (image_.channels >= 3 ? c : 0), sizeof v);
      out[c] = v;
    }
    return out;
  }
  double luminance(std::uint32_t x, std::uint32_t y) const {
    const std::array<double, 3> v = rgb(x, y);
    return kLuminance[0] * v[0] + kLuminance[1] * v[1] + kLuminance[2] * v[2];
  }
  void set(std::uint32_t x, std::uint32_t y, const std::array<double, 3>& value) {
    // The writable memory at the view's offset (the view is packed float, image_file.h).
    float* texel = pixels_ + (std::size_t{y} * image_.width + x) * image_.channels;
    for (std::uint32_t c = 0; c < std::min(image_.channels, 3u); ++c) texel[c] = static_cast<float>(value[c]);
  }
  Dir3 centre(std::uint32_t x, std::uint32_t y) const {
    return equirect_direction((x + 0.5) / image_.width, (y + 0.5) / image_.height);
  }
  detail::ThetaIntegrals row(std::uint32_t y) const {
    return detail::theta_integrals(kPi * y / image_.height, kPi * (y + 1) / image_.height);
  }
  detail::LonIntegrals column(std::uint32_t x) const {
    return detail::lon_integrals((0.5 - static_cast<double>(x + 1) / image_.width) * 2 * kPi,
                                 (0.5 - static_cast<double>(x) / image_.width) * 2 * kPi);
  }
  // Calls f(x, y, angle) for every texel whose centre is within `radius` (radians) of `d`,
  // scanning only the rows that can hold one.
  template <class F>
  void within(const Dir3& d, double radius, F f) const {
    const double theta = std::acos(std::clamp(d.y, -1.0, 1.0));
    const auto first = static_cast<std::uint32_t>(std::max(0.0, std::floor((theta - radius) / kPi * image_.height)));
    const auto last = static_cast<std::uint32_t>(
        std::min<double>(image_.height, std::ceil((theta + radius) / kPi * image_.height) + 1));
    const double cos_radius = std::cos(radius);
    for (std::uint32_t y = first; y < last; ++y)
      for (std::uint32_t x = 0; x < image_.width; ++x) {
        const double c = dot(centre(x, y), d);
        if (c >= cos_radius) f(x, y, std::acos(std::min(c, 1.0)));
      }
  }

 private:
  ImageView image_;
  float* pixels_;
};

}  // namespace

std::optional<SunLight> extract_sun(const ImageView& image, float* pixels) {
  Texels texels(image, pixels);
  std::uint32_t px = 0, py = 0;
  double peak = 0;
  for (std::uint32_t y = 0; y < texels.height(); ++y)
    for (std::uint32_t x = 0; x < texels.width(); ++x)
      if (const double l = texels.luminance(x, y); l > peak) peak = l, px = x, py = y;
  if (!(peak > 0)) return std::nullopt;
  const Dir3 centre = texels.centre(px, py);
  const double threshold = kSunThreshold * peak;

  // Steps 2 and 3: the disc, and nothing as bright just outside it.
  struct Texel {
    std::uint32_t x, y;
  };
  std::vector<Texel> disc;
  double radius = 0;
  bool compact = true;
  texels.within(centre, (kSunMaxRadiusDeg + kSunGuardDeg) * kDegree, [&](std::uint32_t x, std::uint32_t y, double angle) {
    if (texels.luminance(x, y) < threshold) return;
    if (angle > kSunMaxRadiusDeg * kDegree) {
      compact = false;
      return;
    }
    disc.push_back({x, y});
    radius = std::max(radius, angle);
  });
  if (!compact) return std::nullopt;
  // Half a texel diagonal at the widest row of the disc, so the ring starts clear of it.
  const double row_sin = std::min(1.0, std::sin(std::acos(std::clamp(centre.y, -1.0, 1.0))) + std::sin(radius));
  radius += 0.5 * std::hypot(kPi / texels.height(), 2 * kPi / texels.width() * row_sin);

  // Step 4: the sky level, over the ring.
  const double inner = radius + kSunRingGapDeg * kDegree, outer = inner + kSunRingWidthDeg * kDegree;
  std::array<double, 3> sky_sum{};
  double ring_solid = 0;
  texels.within(centre, outer, [&](std::uint32_t x, std::uint32_t y, double angle) {
    if (angle < inner) return;
    const double solid = texels.row(y).solid * texels.column(x).length;
    const std::array<double, 3> v = texels.rgb(x, y);
    for (int c = 0; c < 3; ++c) sky_sum[c] += v[c] * solid;
    ring_solid += solid;
  });
  if (!(ring_solid > 0)) return std::nullopt;
  SunLight sun;
  for (int c = 0; c < 3; ++c) sun.sky[c] = sky_sum[c] / ring_solid;
  // Step 5: a sun stands out of its sky.
  const double sky_luminance = kLuminance[0] * sun.sky[0] + kLuminance[1] * sun.sky[1] + kLuminance[2] * sun.sky[2];
  if (peak < kSunMinContrast * sky_luminance) return std::nullopt;

  // What is removed, as flux vectors, then the texels set to the sky.
  std::array<Dir3, 3> flux{};
  for (const Texel& t : disc) {
    const detail::ThetaIntegrals row = texels.row(t.y);
    const detail::LonIntegrals column = texels.column(t.x);
    const Dir3 w = detail::direction_integral(row, column);
    const std::array<double, 3> v = texels.rgb(t.x, t.y);
    for (int c = 0; c < 3; ++c) {
      const double excess = v[c] - sun.sky[c];
      flux[c] = {flux[c].x + excess * w.x, flux[c].y + excess * w.y, flux[c].z + excess * w.z};
    }
    sun.solid_angle += row.solid * column.length;
    texels.set(t.x, t.y, sun.sky);
  }
  Dir3 m{};
  for (int c = 0; c < 3; ++c)
    m = {m.x + kLuminance[c] * flux[c].x, m.y + kLuminance[c] * flux[c].y, m.z + kLuminance[c] * flux[c].z};
  const double length = std::sqrt(dot(m, m));
  sun.direction = length > 0 ? Dir3{m.x / length, m.y / length, m.z / length} : centre;
  for (int c = 0; c < 3; ++c) sun.irradiance[c] = dot(sun.direction, flux[c]);
  sun.radius_deg = radius / kDegree;
  sun.texels = disc.size();
  return sun;
}

IoStatus convert_env_map_extracting_sun(const std::filesystem::path& path, const ConvertSettings& settings,
                                        ShDocument& out) {
  ImageFile map;
  if (IoStatus st = read_image_file(path, map); !st.ok()) return st;
  const Layout layout = resolve_layout(settings.env_map.layout, map.width, map.height);
  if (layout == Layout::Auto) {
    return IoStatus::error(IoErrc::UnknownLayout, path,
                           "cannot tell the layout of a " + std::to_string(map.width) + "x" +
                               std::to_string(map.height) + " image");
  }
  if (layout != Layout::Equirect)
    return IoStatus::error(IoErrc::Unsupported, path, "--extract-sun reads equirect maps only");

  // NaN/Inf texels: counted first; an error, or zeroed before the sun is looked for.
  std::uint64_t nonfinite = 0;
  std::uint32_t first_x = 0, first_y = 0;
  for (std::uint32_t y = 0; y < map.height; ++y) {
    for (std::uint32_t x = 0; x < map.width; ++x) {
      bool bad = false;
      for (std::uint32_t c = 0; c < map.channels; ++c) {
        float& v = map.pixels[(std::size_t{y} * map.width + x) * map.channels + c];
        if (!std::isfinite(v)) bad = true, v = 0.0f;
      }
      if (bad && nonfinite++ == 0) first_x = x, first_y = y;
    }
  }
  if (nonfinite > 0 && settings.env_map.project.nonfinite == NonFinite::Error) {
    return IoStatus::error(IoErrc::NonFiniteTexel, path,
                           std::to_string(nonfinite) + " NaN/Inf texels (first at x=" + std::to_string(first_x) +
                               ", y=" + std::to_string(first_y) + ")");
  }

  ImageView view = map.view();
  if (Status st = resolve_view(view); !st.ok()) return IoStatus::error(IoErrc::Core, path, st.what);
  std::optional<SunLight> sun = extract_sun(view, map.pixels.data());
  ShL2 projected;
  ProjectStats stats;
  if (Status st = project_with_method(view, settings.method, settings.env_map.project, projected, &stats); !st.ok())
    return IoStatus::error(IoErrc::Core, path, st.what);
  std::string digest;
  if (IoStatus st = sha256_file(path, digest); !st.ok()) return st;
  FinishedSh finished;
  if (Status st = finish_projection(projected, {settings.intensity, settings.rotate_deg, settings.window}, finished);
      !st.ok())
    return IoStatus::error(IoErrc::InvalidArgument, path, st.what);

  ShDocument doc;
  doc.source = {{path.filename().string()}, {digest}, layout, map.width, map.height};
  doc.method = settings.method;
  doc.intensity = settings.intensity;
  doc.rotate_deg = settings.rotate_deg;
  doc.window = settings.window;
  doc.radiance = finished.radiance;
  doc.unity_form = finished.unity_form;
  doc.diagnostics = {nonfinite, stats.negative_texels, map.ignored_channels(), finished.min_e_over_pi,
                     finished.window.factors, finished.window.impossible};
  doc.sun_extraction = true;
  if (sun) {
    // The map's environment is turned by R (rotate.h): the sun's direction too.
    const Matrix3 r = rotation_about_y(settings.rotate_deg);
    const Dir3 d = sun->direction;
    sun->direction = {r[0][0] * d.x + r[0][1] * d.y + r[0][2] * d.z, r[1][0] * d.x + r[1][1] * d.y + r[1][2] * d.z,
                      r[2][0] * d.x + r[2][1] * d.y + r[2][2] * d.z};
    for (int c = 0; c < 3; ++c) {
      sun->irradiance[c] *= settings.intensity;
      sun->sky[c] *= settings.intensity;
    }
    doc.sun = sun;
  }
  out = std::move(doc);
  return IoStatus::success();
}

UnitySunLight unity_sun_light(const SunLight& sun) {
  UnitySunLight light;
  light.forward = {-sun.direction.x, -sun.direction.y, -sun.direction.z};
  const double pitch = std::asin(std::clamp(-light.forward.y, -1.0, 1.0));
  const double yaw = std::atan2(light.forward.x, light.forward.z);
  light.euler_deg = {pitch / kDegree, yaw / kDegree, 0.0};
  const double sx = std::sin(0.5 * pitch), cx = std::cos(0.5 * pitch);
  const double sy = std::sin(0.5 * yaw), cy = std::cos(0.5 * yaw);
  light.quaternion = {cy * sx, sy * cx, -sy * sx, cy * cx};
  std::array<double, 3> e_over_pi;
  for (int c = 0; c < 3; ++c) e_over_pi[c] = std::max(0.0, sun.irradiance[c]) / kPi;
  light.intensity = std::max({e_over_pi[0], e_over_pi[1], e_over_pi[2]});
  for (int c = 0; c < 3; ++c) {
    light.colour[c] = light.intensity > 0 ? e_over_pi[c] / light.intensity : 0.0;
    light.colour_srgb[c] = linear_to_srgb(light.colour[c]);
  }
  return light;
}

}  // namespace shpack::io
