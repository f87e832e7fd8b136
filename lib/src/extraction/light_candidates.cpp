#include "shpack/light_candidates.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <new>
#include <numbers>
#include <optional>
#include <utility>

#include "common/accumulate.h"
#include "extraction/equirect_texels.h"
#include "extraction/free_texels.h"
#include "extraction/removed_flux.h"
#include "extraction/texel_basis.h"

namespace shpack {
namespace {

using detail::EquirectTexels;
using detail::FreeTexels;

// sum_t Y_t Omega_t / 4 pi, the map's mean luminance (step 1's floor).
double mean_luminance(const EquirectTexels& texels) {
  detail::NeumaierSum total;
  for (std::uint32_t y = 0; y < texels.height(); ++y) {
    double row = 0;
    for (std::uint32_t x = 0; x < texels.width(); ++x) row += texels.luminance(x, y);
    total.add(row * texels.row(y).solid * (2 * std::numbers::pi / texels.width()));
  }
  return total.value() / (4 * std::numbers::pi);
}

// Calls f on the 8 neighbours of t on the sphere (light_candidates.h, step 2).
template <class F>
void for_each_neighbour(const EquirectTexels& texels, LightTexel t, F f) {
  const std::int64_t w = texels.width(), h = texels.height();
  for (std::int64_t dy = -1; dy <= 1; ++dy) {
    std::int64_t y = t.y + dy, turn = 0;
    if (y < 0 || y >= h) y = t.y, turn = w / 2;  // over the pole
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      std::int64_t x = t.x + turn + dx;  // in [-1, 3w/2]: one wrap at most
      x += x < 0 ? w : x >= w ? -w : 0;
      f(LightTexel{static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)});
    }
  }
}

// The region's centre c and radius r (step 3).
struct Extent {
  Dir3 centre;
  double radius;
};
Extent region_extent(const EquirectTexels& texels, const std::vector<LightTexel>& region) {
  Dir3 sum{};
  for (const LightTexel& t : region) {
    const Dir3 w = detail::direction_integral(texels.row(t.y), texels.column(t.x));
    sum = {sum.x + w.x, sum.y + w.y, sum.z + w.z};
  }
  const double length = std::sqrt(detail::dot(sum, sum));
  const Dir3 centre = {sum.x / length, sum.y / length, sum.z / length};
  double radius = 0;
  for (const LightTexel& t : region)
    radius = std::max(radius, detail::angle_of(detail::dot(texels.centre(t.x, t.y), centre)));
  return {centre, texels.padded_radius(centre, radius)};
}

// The light, and the SH of its removal (light_candidates.h), from the region's texels in
// row-major order, each row's basis integrals formed once.
void measure_removal(const EquirectTexels& texels, const SunSearch& search, const Dir3& centre,
                     LightCandidate& candidate) {
  detail::RemovedFlux flux;
  detail::NeumaierSum sh[kChannelCount][kShCount];
  std::optional<detail::RowBasis> row;
  for (std::size_t k = 0; k < candidate.texels.size(); ++k) {
    const LightTexel t = candidate.texels[k];
    if (k == 0 || t.y != candidate.texels[k - 1].y) row.emplace(t.y, texels.width(), texels.height());
    const std::array<double, 3> v = texels.rgb(t.x, t.y);
    const std::array<double, 3> e = {v[0] - candidate.light.sky[0], v[1] - candidate.light.sky[1],
                                     v[2] - candidate.light.sky[2]};
    flux.add(texels.row(t.y), texels.column(t.x), e);
    const std::array<double, kShCount> basis = row->texel(t.x);
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) sh[c][i].add(e[c] * basis[i]);
  }
  flux.finish(search.luminance, centre, candidate.light);
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) candidate.removed.c[c][i] = sh[c][i].value();
}

// What the searches of one map at every scale share: its texels, its mean luminance, and the
// free texels before any is taken (each search takes from a copy). May throw std::bad_alloc.
struct SharedSearch {
  SharedSearch(const ImageView& image, const SunSearch& search)
      : texels(image, search), mean(mean_luminance(texels)), fresh(texels) {}
  SharedSearch(const SharedSearch&) = delete;
  SharedSearch& operator=(const SharedSearch&) = delete;
  EquirectTexels texels;
  double mean;
  FreeTexels fresh;  // refers to texels
};

// One search over a map (light_candidates.h); may throw std::bad_alloc.
class CandidateSearch {
 public:
  CandidateSearch(const SharedSearch& shared, const SunSearch& search, const LightScale& scale)
      : texels_(shared.texels), search_(search), scale_(scale), mean_(shared.mean), free_(shared.fresh) {}
  CandidateSearch(const CandidateSearch&) = delete;
  CandidateSearch& operator=(const CandidateSearch&) = delete;

  std::vector<LightCandidate> run(std::size_t max_candidates) {
    std::vector<LightCandidate> candidates;
    for (std::size_t seeds = 0; candidates.size() < max_candidates && seeds < kLightMaxSeeds; ++seeds) {
      const std::optional<FreeTexels::Seed> seed = free_.brightest();
      if (!seed || !(seed->luminance > mean_)) break;
      std::optional<std::vector<LightTexel>> region = grow(*seed);
      if (!region) continue;
      const std::optional<Judged> judged = judge(*seed, *region);
      if (!judged) continue;
      std::optional<LightCandidate> candidate = make_candidate(*seed, *judged, std::move(*region));
      if (!candidate) continue;
      // The region's surroundings out to its ring's outer edge are taken.
      texels_.within(judged->extent.centre, ring_outer(judged->extent), [&](std::uint32_t x, std::uint32_t y, double) {
        if (free_.free({x, y})) free_.take({x, y});
      });
      candidates.push_back(std::move(*candidate));
    }
    return candidates;
  }

 private:
  static double ring_inner(const Extent& e) { return e.radius + kSunRingGapDeg * kDegree; }
  static double ring_outer(const Extent& e) { return ring_inner(e) + kSunRingWidthDeg * kDegree; }

  // Step 2 (and 3's bound on the growth): the region of `seed`, or none when it reaches further
  // than twice the largest radius from the seed. Every texel it reaches is taken.
  std::optional<std::vector<LightTexel>> grow(const FreeTexels::Seed& seed) {
    const Dir3 from = texels_.centre(seed.texel.x, seed.texel.y);
    const double cos_reach = std::cos(2 * scale_.max_radius_deg * kDegree);
    const double threshold = scale_.threshold * seed.luminance;
    std::vector<LightTexel> region = {seed.texel};
    free_.take(seed.texel);
    bool far = false;
    for (std::size_t next = 0; next < region.size() && !far; ++next)
      for_each_neighbour(texels_, region[next], [&](LightTexel n) {
        if (far || !free_.free(n) || texels_.luminance(n.x, n.y) < threshold) return;
        free_.take(n);
        region.push_back(n);
        far = detail::dot(texels_.centre(n.x, n.y), from) < cos_reach;
      });
    if (far) return std::nullopt;
    return region;
  }

  // A region that passed steps 3 to 6: its extent and its ring's level.
  struct Judged {
    Extent extent;
    detail::RingLevel ring;
  };

  // Steps 3 to 6 on a grown region, step 4 adding to it.
  std::optional<Judged> judge(const FreeTexels::Seed& seed, std::vector<LightTexel>& region) {
    const double largest = scale_.max_radius_deg * kDegree;
    Extent extent = region_extent(texels_, region);
    if (extent.radius > largest) return std::nullopt;
    const double threshold = scale_.threshold * seed.luminance;
    texels_.within(extent.centre, ring_inner(extent), [&](std::uint32_t x, std::uint32_t y, double) {
      if (!free_.free({x, y}) || texels_.luminance(x, y) < threshold) return;
      free_.take({x, y});
      region.push_back({x, y});
    });
    extent = region_extent(texels_, region);
    if (extent.radius > largest) return std::nullopt;
    const detail::RingLevel ring = detail::ring_level(texels_, extent.centre, ring_inner(extent), ring_outer(extent));
    // Step 6, with the contrast 1 / threshold.
    if (!(ring.solid > 0) || seed.luminance * scale_.threshold < texels_.luminance(ring.level)) return std::nullopt;
    return Judged{extent, ring};
  }

  // The candidate of a region that passed steps 3 to 6, if it passes step 7.
  std::optional<LightCandidate> make_candidate(const FreeTexels::Seed& seed, const Judged& judged,
                                               std::vector<LightTexel> region) const {
    LightCandidate candidate;
    candidate.light.sky = judged.ring.level;
    candidate.light.radius_deg = judged.extent.radius / kDegree;
    candidate.light.texels = region.size();
    candidate.peak = seed.luminance;
    std::sort(region.begin(), region.end(),
              [](const LightTexel& a, const LightTexel& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
    candidate.texels = std::move(region);
    measure_removal(texels_, search_, judged.extent.centre, candidate);
    // Step 7: int e dw = L00 / k0 (int_t Y_0 = k0 Omega_t), against the map's sum_t Y_t Omega_t.
    const std::array<double, 3> l00 = {candidate.removed.c[0][0], candidate.removed.c[1][0], candidate.removed.c[2][0]};
    if (texels_.luminance(l00) / kY0 < kLightMinFluxShare * 4 * std::numbers::pi * mean_) return std::nullopt;
    return candidate;
  }

  const EquirectTexels& texels_;
  SunSearch search_;
  LightScale scale_;
  double mean_;
  FreeTexels free_;  // refers to texels_ too
};

}  // namespace

Status find_light_candidates(const ImageView& image, const SunSearch& search, std::size_t max_candidates,
                             std::vector<LightCandidate>& candidates, const LightScale& scale) noexcept {
  return find_light_candidates_at_scales(image, search, max_candidates, {&scale, 1}, candidates);
}

Status find_light_candidates_at_scales(const ImageView& image, const SunSearch& search, std::size_t max_candidates,
                                       std::span<const LightScale> scales,
                                       std::vector<LightCandidate>& candidates) noexcept {
  ImageView view = image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  if (view.type != PixelType::F32)
    return Status::error(Errc::InvalidArgument, "the light search reads float texels");
  try {
    candidates.clear();
    if (max_candidates == 0 || scales.empty()) return Status::success();
    const SharedSearch shared(view, search);
    for (const LightScale& scale : scales) {
      std::vector<LightCandidate> found = CandidateSearch(shared, search, scale).run(max_candidates);
      candidates.insert(candidates.end(), std::make_move_iterator(found.begin()), std::make_move_iterator(found.end()));
    }
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the light search's texel marks or a region");
  }
}

bool share_a_texel(const LightCandidate& a, const LightCandidate& b) noexcept {
  const auto row_major = [](const LightTexel& s, const LightTexel& t) { return s.y != t.y ? s.y < t.y : s.x < t.x; };
  auto i = a.texels.begin(), j = b.texels.begin();
  while (i != a.texels.end() && j != b.texels.end()) {
    if (row_major(*i, *j)) {
      ++i;
    } else if (row_major(*j, *i)) {
      ++j;
    } else {
      return true;
    }
  }
  return false;
}

Status remove_light_candidates(const ImageView& image, float* pixels, std::span<const LightCandidate> candidates,
                               std::span<const std::size_t> chosen) noexcept {
  ImageView view = image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  if (!detail::writable_view(view, pixels))
    return Status::error(Errc::InvalidArgument,
                         "removing lights needs the writable packed float texels the view shows");
  for (std::size_t k : chosen) {
    if (k >= candidates.size()) return Status::error(Errc::InvalidArgument, "a chosen light is not a candidate");
    for (const LightTexel& t : candidates[k].texels)
      if (t.x >= view.width || t.y >= view.height)
        return Status::error(Errc::InvalidArgument, "a light's texel is outside the map", t.x, t.y);
  }
  for (std::size_t k : chosen)
    for (const LightTexel& t : candidates[k].texels) detail::write_texel(view, pixels, t, candidates[k].light.sky);
  return Status::success();
}

}  // namespace shpack
