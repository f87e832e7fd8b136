#include "shpack/light_extraction.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>
#include <numbers>
#include <vector>

#include "projection/equirect_integrals.h"

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

double dot(const Dir3& a, const Dir3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// The texels of one equirect image, read as RGB whatever the channel count, with the
// projector's value policies (light_extraction.h).
class Texels {
 public:
  Texels(const ImageView& image, float* pixels, const SunSearch& search)
      : image_(image), pixels_(pixels), search_(search) {}

  std::uint32_t width() const { return image_.width; }
  std::uint32_t height() const { return image_.height; }
  std::array<double, 3> rgb(std::uint32_t x, std::uint32_t y) const {
    std::array<double, 3> out;
    for (int c = 0; c < 3; ++c) {
      float v;
      std::memcpy(&v, image_.pixel(x, y) + 4 * (image_.channels >= 3 ? c : 0), sizeof v);
      out[c] = !std::isfinite(v) || (v < 0 && search_.negative == Negative::Clamp) ? 0.0 : v;
    }
    return out;
  }
  double luminance(std::uint32_t x, std::uint32_t y) const {
    const std::array<double, 3> v = rgb(x, y);
    return luminance(v);
  }
  double luminance(const std::array<double, 3>& v) const {
    return search_.luminance[0] * v[0] + search_.luminance[1] * v[1] + search_.luminance[2] * v[2];
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
  SunSearch search_;
};

// The five steps of light_extraction.h; may throw std::bad_alloc (the disc's texel list).
std::optional<SunLight> find_and_remove_sun(const ImageView& image, float* pixels, const SunSearch& search) {
  Texels texels(image, pixels, search);
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
  const double sky_luminance = texels.luminance(sun.sky);
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
    m = {m.x + search.luminance[c] * flux[c].x, m.y + search.luminance[c] * flux[c].y,
         m.z + search.luminance[c] * flux[c].z};
  const double length = std::sqrt(dot(m, m));
  sun.direction = length > 0 ? Dir3{m.x / length, m.y / length, m.z / length} : centre;
  for (int c = 0; c < 3; ++c) sun.irradiance[c] = dot(sun.direction, flux[c]);
  sun.radius_deg = radius / kDegree;
  sun.texels = disc.size();
  return sun;
}

}  // namespace

Status extract_sun(const ImageView& image, float* pixels, const SunSearch& search,
                   std::optional<SunLight>& sun) noexcept {
  ImageView view = image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  const std::int64_t texel = 4 * std::int64_t{view.channels};
  const bool packed = view.pixel_stride == texel && view.row_stride == texel * view.width &&
                      view.data == reinterpret_cast<const std::byte*>(pixels);
  if (view.type != PixelType::F32 || pixels == nullptr || !packed)
    return Status::error(Errc::InvalidArgument, "sun extraction needs the writable packed float texels the view shows");
  try {
    sun = find_and_remove_sun(view, pixels, search);
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the sun's texel list");
  }
}

}  // namespace shpack
