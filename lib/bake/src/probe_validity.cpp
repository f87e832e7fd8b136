#include "probe_validity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include "nearest_probes.h"
#include "sampling.h"

namespace shpack::bake {
namespace {

using Directions = std::array<Vec3d, kValidityRays>;
using scene::InvalidProbes;

// The stream of the validity rays: an id apart from the effects' (Effect, 0..5).
constexpr std::uint64_t kValidityStream = 100;
// Ray offset off a surface point x, as the passes use it: 1e-4 (1 + max|x_k|) clears
// Embree's float rounding.
double surface_epsilon(const Vec3d& x) noexcept {
  return 1e-4 * (1.0 + std::max({std::fabs(x.x), std::fabs(x.y), std::fabs(x.z)}));
}

// Probe k's directions (probe_validity.h): the spherical Fibonacci set, point i at height
// 1 - (2i + 1) / n and azimuth i times the golden angle, turned by the rotation of a uniform
// unit quaternion (Shoemake 1992).
Directions validity_directions(std::uint64_t seed, std::uint64_t probe) {
  Rng rng = stream(seed, kValidityStream, probe, 0);
  const double u1 = rng.uniform(), u2 = 2 * std::numbers::pi * rng.uniform(), u3 = 2 * std::numbers::pi * rng.uniform();
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double x = a * std::sin(u2), y = a * std::cos(u2), z = b * std::sin(u3), w = b * std::cos(u3);
  const Vec3d r0{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)};
  const Vec3d r1{2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)};
  const Vec3d r2{2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
  const double golden_angle = std::numbers::pi * (3 - std::sqrt(5.0));
  Directions out;
  for (int i = 0; i < kValidityRays; ++i) {
    const double h = 1 - (2 * i + 1) / static_cast<double>(kValidityRays);
    const double s = std::sqrt(std::fmax(0.0, 1 - h * h)), phi = golden_angle * i;
    const Vec3d d{s * std::cos(phi), s * std::sin(phi), h};
    out[static_cast<std::size_t>(i)] = {dot(r0, d), dot(r1, d), dot(r2, d)};
  }
  return out;
}

struct BackHit {
  double t = 0;  // distance along the ray
  int ray = 0;
};

struct Measure {
  double fraction = 0;
  std::optional<std::uint32_t> shape;  // the one most back-face hits are on (lowest index on ties)
  std::vector<BackHit> back;           // kept only when asked (offset candidates)
};

// A back face that counts: planes are open sheets, both of whose sides face out.
bool counts_as_back(const scene::Scene& scene, const Hit& hit) {
  return hit.hit && hit.backface && scene.geometry[hit.shape].type != scene::ShapeType::Plane;
}

std::optional<std::uint32_t> most_common(std::vector<std::uint32_t> shapes) {
  if (shapes.empty()) return std::nullopt;
  std::sort(shapes.begin(), shapes.end());
  std::uint32_t best = shapes.front();
  std::size_t best_count = 0;
  for (std::size_t j = 0; j < shapes.size();) {
    std::size_t end = j;
    while (end < shapes.size() && shapes[end] == shapes[j]) ++end;
    if (end - j > best_count) {
      best = shapes[j];
      best_count = end - j;
    }
    j = end;
  }
  return best;
}

Measure measure(const Tracer& tracer, const scene::Scene& scene, const Vec3d& p, const Directions& dirs,
                bool keep_hits, std::uint64_t& rays) {
  Measure m;
  std::vector<std::uint32_t> shapes;
  for (int i = 0; i < kValidityRays; ++i) {
    const Hit hit = tracer.intersect(p, dirs[static_cast<std::size_t>(i)], 0.0);
    ++rays;
    if (!counts_as_back(scene, hit)) continue;
    shapes.push_back(hit.shape);
    if (keep_hits) m.back.push_back({hit.t, i});
  }
  m.fraction = static_cast<double>(shapes.size()) / kValidityRays;
  m.shape = most_common(std::move(shapes));
  return m;
}

struct Offset {
  Vec3d position;
  double fraction = 0;
};

// The nearest valid candidate point (probe_validity.h, "Offset") within max_offset of p.
std::optional<Offset> find_offset(const Tracer& tracer, const scene::Scene& scene, const Vec3d& p,
                                  const Directions& dirs, std::vector<BackHit> back, std::uint64_t& rays) {
  const double threshold = scene.settings.validity_threshold, reach = scene.settings.max_offset;
  std::sort(back.begin(), back.end(), [](const BackHit& a, const BackHit& b) {
    return a.t < b.t || (a.t == b.t && a.ray < b.ray);
  });
  int tried = 0;
  for (const BackHit& exit : back) {
    if (tried == kOffsetCandidates || !(exit.t < reach)) break;  // the rest are farther
    const Vec3d d = dirs[static_cast<std::size_t>(exit.ray)];
    const Vec3d x = p + exit.t * d;
    const double eps = surface_epsilon(x);
    const Hit next = tracer.intersect(x, d, eps);  // the free gap beyond the surface
    ++rays;
    const double gap = next.hit ? next.t : std::numeric_limits<double>::infinity();
    const double push = std::min({kOffsetBias, 0.5 * gap, reach - exit.t});
    if (!(push > eps)) continue;
    ++tried;
    const Vec3d q = x + push * d;
    const Measure m = measure(tracer, scene, q, dirs, false, rays);
    if (m.fraction <= threshold) return Offset{q, m.fraction};
  }
  return std::nullopt;
}

bool left_to_dilate(const ProbeValidity& v) { return !v.valid && !v.offset_position; }
bool dilation_source(const ProbeValidity& v) { return v.valid || v.offset_position; }

// "probes[3] (0, 1, 0) is inside geometry[0] 'wall': 200 of its 256 rays hit back faces,
// more than settings.validity_threshold 0.25".
std::string describe_invalid(const scene::Scene& scene, std::size_t k, const ProbeValidity& v) {
  std::ostringstream os;
  os << scene::probe_label(scene, k) << " is inside "
     << (v.backface_shape ? scene.geometry[*v.backface_shape].label : std::string("geometry")) << ": "
     << std::lround(v.backface_fraction * kValidityRays) << " of its " << kValidityRays
     << " rays hit back faces, more than settings.validity_threshold " << scene.settings.validity_threshold;
  return os.str();
}

// value(id): the SH of the probe of that id.
template <class Value>
ShL2 weighted_mean(const std::vector<NearProbe>& near, const Value& value) {
  // Squared-distance weights; probes at the very same position outweigh all others.
  const bool coincident = near.front().distance2 == 0;
  ShL2 sum;
  double total = 0;
  for (const NearProbe& n : near) {
    const double w = coincident ? (n.distance2 == 0 ? 1.0 : 0.0) : 1.0 / n.distance2;
    if (w == 0) continue;
    total += w;
    const ShL2 x = value(n.id);
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) sum.c[c][i] += w * x.c[c][i];
  }
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) sum.c[c][i] /= total;
  return sum;
}

// A dilated probe's sampling: per effect, the same weighted mean of its neighbours' errors (a
// bound on the error of the weighted mean of their SH, by the triangle inequality), the most
// samples any of them took, and capped if any was.
EffectSampling dilated_sampling(const std::vector<NearProbe>& near,
                                const std::vector<std::array<EffectSampling, kEffectCount>>& sampling, std::size_t e) {
  EffectSampling out;
  const ShL2 error = weighted_mean(near, [&](std::size_t j) {
    ShL2 x;
    for (int c = 0; c < kChannelCount; ++c) x.c[c][0] = sampling[j][e].error[c];
    return x;
  });
  for (int c = 0; c < kChannelCount; ++c) out.error[c] = error.c[c][0];
  for (const NearProbe& n : near) {
    out.samples = std::max(out.samples, sampling[n.id][e].samples);
    out.capped = out.capped || sampling[n.id][e].capped;
  }
  return out;
}

}  // namespace

ProbeValidity check_probe(const Tracer& tracer, const scene::Scene& scene, std::size_t k, std::uint64_t stream_id,
                          std::uint64_t& rays) {
  const scene::SceneSettings& settings = scene.settings;
  const Directions dirs = validity_directions(settings.seed, stream_id);
  const Vec3d p = vec(scene.probes[k]);
  const bool offset = settings.invalid_probes == InvalidProbes::Offset;
  Measure m = measure(tracer, scene, p, dirs, offset, rays);
  ProbeValidity v;
  v.backface_fraction = m.fraction;
  v.backface_shape = m.shape;
  v.valid = m.fraction <= settings.validity_threshold;
  if (!v.valid && offset)
    if (const std::optional<Offset> moved = find_offset(tracer, scene, p, dirs, std::move(m.back), rays)) {
      v.offset_position = Point3{moved->position.x, moved->position.y, moved->position.z};
      v.offset_backface_fraction = moved->fraction;
    }
  return v;
}

io::IoStatus check_invalid_probes(const scene::Scene& scene, const std::vector<ProbeValidity>& validity,
                                  std::size_t first_probe, bool whole) {
  const InvalidProbes policy = scene.settings.invalid_probes;
  if (policy == InvalidProbes::Keep) return io::IoStatus::success();
  const auto first = std::find_if(validity.begin(), validity.end(), [policy](const ProbeValidity& v) {
    return policy == InvalidProbes::Error ? !v.valid : left_to_dilate(v);
  });
  if (first == validity.end()) return io::IoStatus::success();
  const std::size_t k = first_probe + static_cast<std::size_t>(first - validity.begin());
  if (policy == InvalidProbes::Error)
    return io::IoStatus::error(io::IoErrc::BadDocument, scene.file,
                               describe_invalid(scene, k, *first) + " (settings.invalid_probes \"error\")");
  if (!whole || std::any_of(validity.begin(), validity.end(), dilation_source)) return io::IoStatus::success();
  return io::IoStatus::error(io::IoErrc::BadDocument, scene.file,
                             "no valid probe to dilate from (every probe is inside geometry); " +
                                 describe_invalid(scene, k, *first));
}

std::optional<scene::Scene> offset_scene(const scene::Scene& scene, const std::vector<ProbeValidity>& validity) {
  const auto moved = [](const ProbeValidity& v) { return v.offset_position.has_value(); };
  if (std::none_of(validity.begin(), validity.end(), moved)) return std::nullopt;
  std::optional<scene::Scene> offset(scene);
  for (std::size_t k = 0; k < validity.size(); ++k)
    if (validity[k].offset_position) offset->probes[k] = *validity[k].offset_position;
  return offset;
}

void dilate_invalid_probes(const scene::Scene& scene, std::vector<ProbeValidity>& validity,
                           std::vector<ShL2>& radiance, std::vector<std::array<ShL2, kEffectCount>>& effects,
                           std::vector<std::array<EffectSampling, kEffectCount>>& sampling) {
  const InvalidProbes policy = scene.settings.invalid_probes;
  if (policy != InvalidProbes::Dilate && policy != InvalidProbes::Offset) return;
  std::vector<Vec3d> points;
  std::vector<std::size_t> ids;
  for (std::size_t k = 0; k < validity.size(); ++k)
    if (dilation_source(validity[k])) {
      points.push_back(vec(scene.probes[k]));
      ids.push_back(k);
    }
  if (ids.empty()) return;  // check_invalid_probes refused the bake if any were left
  const NearestProbes tree(std::move(points), std::move(ids));
  for (std::size_t k = 0; k < validity.size(); ++k) {
    if (!left_to_dilate(validity[k])) continue;
    // Sources are never dilated, so the order of the dilated probes does not matter.
    const std::vector<NearProbe> near = tree.nearest(vec(scene.probes[k]), kDilationNeighbours);
    radiance[k] = weighted_mean(near, [&](std::size_t j) -> const ShL2& { return radiance[j]; });
    if (!effects.empty())
      for (std::size_t e = 0; e < kEffectCount; ++e)
        effects[k][e] = weighted_mean(near, [&](std::size_t j) -> const ShL2& { return effects[j][e]; });
    for (std::size_t e = 0; e < kEffectCount && !sampling.empty(); ++e) sampling[k][e] = dilated_sampling(near, sampling, e);
    validity[k].dilated = true;
  }
}

ValidityCounts count_validity(const std::vector<ProbeValidity>& validity) {
  ValidityCounts counts;
  for (const ProbeValidity& v : validity) {
    counts.invalid += !v.valid;
    counts.moved += v.offset_position.has_value();
    counts.dilated += v.dilated;
  }
  return counts;
}

}  // namespace shpack::bake
