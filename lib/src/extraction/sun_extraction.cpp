#include "shpack/light_extraction.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

#include "extraction/equirect_texels.h"
#include "extraction/removed_flux.h"

namespace shpack {
namespace {

using detail::EquirectTexels;

// The five steps of light_extraction.h; may throw std::bad_alloc (the disc's texel list).
std::optional<SunLight> find_and_remove_sun(const ImageView& image, float* pixels, const SunSearch& search) {
  const EquirectTexels texels(image, search);
  std::uint32_t px = 0, py = 0;
  double peak = 0;
  for (std::uint32_t y = 0; y < texels.height(); ++y)
    for (std::uint32_t x = 0; x < texels.width(); ++x)
      if (const double l = texels.luminance(x, y); l > peak) peak = l, px = x, py = y;
  if (!(peak > 0)) return std::nullopt;
  const Dir3 centre = texels.centre(px, py);
  const double threshold = kSunThreshold * peak;

  // Steps 2 and 3: the disc, and nothing as bright just outside it.
  std::vector<LightTexel> disc;
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
  radius = texels.padded_radius(centre, radius);

  // Step 4: the sky level, over the ring.
  const double inner = radius + kSunRingGapDeg * kDegree, outer = inner + kSunRingWidthDeg * kDegree;
  const detail::RingLevel ring = detail::ring_level(texels, centre, inner, outer);
  if (!(ring.solid > 0)) return std::nullopt;
  SunLight sun;
  sun.sky = ring.level;
  // Step 5: a sun stands out of its sky.
  if (peak < kSunMinContrast * texels.luminance(sun.sky)) return std::nullopt;

  // What is removed, as flux vectors, then the texels set to the sky.
  detail::RemovedFlux flux;
  for (const LightTexel& t : disc) {
    const std::array<double, 3> v = texels.rgb(t.x, t.y);
    flux.add(texels.row(t.y), texels.column(t.x), {v[0] - sun.sky[0], v[1] - sun.sky[1], v[2] - sun.sky[2]});
  }
  flux.finish(search.luminance, centre, sun);
  for (const LightTexel& t : disc) detail::write_texel(image, pixels, t, sun.sky);
  sun.radius_deg = radius / kDegree;
  sun.texels = disc.size();
  return sun;
}

}  // namespace

Status extract_sun(const ImageView& image, float* pixels, const SunSearch& search,
                   std::optional<SunLight>& sun) noexcept {
  ImageView view = image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  if (!detail::writable_view(view, pixels))
    return Status::error(Errc::InvalidArgument, "sun extraction needs the writable packed float texels the view shows");
  try {
    sun = find_and_remove_sun(view, pixels, search);
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the sun's texel list");
  }
}

}  // namespace shpack
