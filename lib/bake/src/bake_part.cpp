#include "shpack/bake/bake_part.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <tuple>
#include <utility>

#include "probe_validity.h"
#include "scene_lights.h"
#include "shpack/io/version.h"

namespace shpack::bake {
namespace {

// One tracer built per part: the scene's counts, the times summed.
void add_geometry(GeometryCost& into, const GeometryCost& from) {
  if (!from.built) return;
  into.built = true;
  into.time_ms += from.time_ms;
  into.triangles = from.triangles;
  into.spheres = from.spheres;
}

// Where each shard's items start: shard k (from 1) holds items [first[k - 1], first[k]).
// Item i is shard floor(N m_i / C) + 1, m_i the running cost at its midpoint and C the total:
// a monotone function of i, so every shard is one run of items, and the runs tile them.
std::vector<std::size_t> shard_starts(const scene::Scene& scene, const std::vector<std::uint32_t>& texel_points,
                                      std::uint32_t n) {
  const double per = estimated_rays(scene);
  const std::size_t probes = scene.probes.size(), count = probes + texel_points.size();
  const auto cost = [&](std::size_t i) { return i < probes ? per : per * texel_points[i - probes]; };
  double total = 0;
  for (std::size_t i = 0; i < count; ++i) total += cost(i);
  std::vector<std::size_t> first(std::size_t{n} + 1, count);
  first[0] = 0;
  double before = 0;
  std::uint32_t next = 1;  // the next shard whose start is not yet known
  for (std::size_t i = 0; i < count; ++i) {
    const double c = cost(i);
    const double at = std::floor(static_cast<double>(n) * (before + c / 2) / total);
    const auto k = static_cast<std::uint32_t>(std::clamp(at, 0.0, static_cast<double>(n - 1)));  // 0-based
    before += c;
    for (; next <= k; ++next) first[next] = i;  // shards next..k start here (those before k empty)
  }
  return first;
}

std::pair<ItemRange, ItemRange> ranges_of(std::size_t probes, std::size_t first, std::size_t last) {
  return {{std::min(first, probes), std::min(last, probes) - std::min(first, probes)},
          {std::max(first, probes) - probes, std::max(last, probes) - std::max(first, probes)}};
}

}  // namespace

bool parse_shard(std::string_view text, ShardSpec& out, std::string& error) {
  const std::size_t slash = text.find('/');
  std::uint64_t k = 0, n = 0;
  const auto number = [](std::string_view t, std::uint64_t& v) {
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    return !t.empty() && ec == std::errc() && end == t.data() + t.size();
  };
  if (slash == std::string_view::npos || !number(text.substr(0, slash), k) || !number(text.substr(slash + 1), n)) {
    error = "a shard is K/N, e.g. 2/8";
    return false;
  }
  if (n < 1 || n > 1000000 || k < 1 || k > n) {
    error = "a shard K/N needs 1 <= K <= N <= 1000000";
    return false;
  }
  out = {static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(n)};
  return true;
}

double estimated_rays(const scene::Scene& scene) {
  const scene::SceneSettings& s = scene.settings;
  const scene::SceneEffects& fx = scene.effects;
  const bool geometry = !scene.geometry.empty();
  double rays = geometry ? kValidityRays : 0;
  for (const scene::SceneLight& light : scene.lights)
    rays += 1 + (fx.shadows && geometry ? (is_delta(light) ? 1.0 : s.shadow_samples) : 0.0);
  if (geometry) {
    if (fx.sky_occlusion) rays += s.sky_samples;
    if (fx.emission) rays += s.sky_samples;
    if (fx.bounces > 0) rays += 2.0 * s.bounce_samples * (fx.bounces + 1);
  }
  return std::max(1.0, rays);
}

void plan_shard(const scene::Scene& scene, const std::vector<std::uint32_t>& texel_points, ShardSpec shard,
                ItemRange& probes, ItemRange& texels) {
  const std::vector<std::size_t> first = shard_starts(scene, texel_points, shard.count);
  std::tie(probes, texels) = ranges_of(scene.probes.size(), first[shard.index - 1], first[shard.index]);
}

io::IoStatus bake_part(const scene::Scene& scene, const BakeOptions& options, ShardSpec shard, BakePart& out) {
  BakePart part;
  std::vector<std::uint32_t> texel_points;
  if (io::IoStatus st = lightmap_texel_points(scene, texel_points); !st.ok()) return st;
  plan_shard(scene, texel_points, shard, part.probes, part.texels);
  part.scene_file = std::filesystem::absolute(scene.file).lexically_normal().string();
  part.scene_sha256 = scene.sha256;
  part.version = io::shpack_version();
  part.settings = settings_record(scene.settings);
  part.shard = shard;
  part.probes_total = scene.probes.size();
  part.texels_total = texel_points.size();
  if (part.probes.count > 0)
    if (io::IoStatus st = bake_probe_range(scene, options, part.probes.first, part.probes.count, part.probe_result);
        !st.ok())
      return st;
  if (part.texels.count > 0) {
    BakeOptions texel_options = options;
    texel_options.keep_effects = false;  // a part holds what the outputs need
    if (io::IoStatus st =
            bake_lightmap_texels(scene, texel_options, part.texels.first, part.texels.count, part.texel_result);
        !st.ok())
      return st;
  }
  out = std::move(part);
  return io::IoStatus::success();
}

io::IoStatus merge_parts(const scene::Scene& scene, std::vector<BakePart>& parts, const std::vector<std::string>& names,
                         BakeResult& probes, LightmapBakeResult& lightmaps) {
  const auto refuse = [&](std::size_t i, const std::string& why) {
    return io::IoStatus::error(io::IoErrc::BadDocument, names[i], why);
  };
  if (parts.empty()) return io::IoStatus::error(io::IoErrc::BadDocument, scene.file, "no parts to merge");
  std::vector<std::uint32_t> texel_points;
  if (io::IoStatus st = lightmap_texel_points(scene, texel_points); !st.ok()) return st;
  const std::uint32_t n = parts[0].shard.count;
  std::vector<std::size_t> of_shard(n, parts.size());
  const std::vector<std::size_t> first = shard_starts(scene, texel_points, n);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const BakePart& p = parts[i];
    if (p.version != io::shpack_version())
      return refuse(i, "made by shpack " + p.version + ", not by this shpack " + io::shpack_version());
    if (const std::string d = settings_difference(p.settings, settings_record(scene.settings)); !d.empty())
      return refuse(i, "baked with other settings: " + d);
    if (p.scene_sha256 != scene.sha256 || p.probes_total != scene.probes.size() ||
        p.texels_total != texel_points.size())
      return refuse(i, "a part of another scene (SHA-256 " + p.scene_sha256.substr(0, 12) + "..., not " +
                           scene.sha256.substr(0, 12) + "... of " + scene.file.string() + ")");
    if (p.shard.count != n || p.shard.index < 1 || p.shard.index > n)
      return refuse(i, "shard " + shard_text(p.shard) + " is not one of " + std::to_string(n));
    if (of_shard[p.shard.index - 1] != parts.size())
      return refuse(i, "shard " + shard_text(p.shard) + " twice (also " + names[of_shard[p.shard.index - 1]] + ")");
    for (const ProbeValidity& v : p.probe_result.validity)
      if (v.backface_shape && *v.backface_shape >= scene.geometry.size())
        return refuse(i, "a probe's backface shape is not one of the scene's shapes");
    const auto [want_probes, want_texels] =
        ranges_of(scene.probes.size(), first[p.shard.index - 1], first[p.shard.index]);
    if (p.probes != want_probes || p.texels != want_texels)
      return refuse(i, "its items are not shard " + shard_text(p.shard) + "'s of this scene");
    of_shard[p.shard.index - 1] = i;
  }
  for (std::uint32_t k = 0; k < n; ++k)
    if (of_shard[k] == parts.size())
      return io::IoStatus::error(io::IoErrc::BadDocument, scene.file,
                                 "shard " + shard_text({k + 1, n}) + " is missing from the parts to merge");
  BakeResult all;
  LightmapTexelPart texels;
  for (const std::size_t i : of_shard) {
    BakePart& p = parts[i];
    BakeResult& r = p.probe_result;
    std::move(r.radiance.begin(), r.radiance.end(), std::back_inserter(all.radiance));
    std::move(r.sampling.begin(), r.sampling.end(), std::back_inserter(all.sampling));
    std::move(r.validity.begin(), r.validity.end(), std::back_inserter(all.validity));
    for (std::size_t e = 0; e < kEffectCount; ++e) add_cost(all.costs[e], r.costs[e]);
    add_geometry(all.geometry, r.geometry);
    add_cost(all.validity_cost, r.validity_cost);
    LightmapTexelPart& t = p.texel_result;
    texels.texels.insert(texels.texels.end(), t.texels.begin(), t.texels.end());
    std::move(t.radiance.begin(), t.radiance.end(), std::back_inserter(texels.radiance));
    texels.error_pct.insert(texels.error_pct.end(), t.error_pct.begin(), t.error_pct.end());
    texels.backface.insert(texels.backface.end(), t.backface.begin(), t.backface.end());
    texels.invalid.insert(texels.invalid.end(), t.invalid.begin(), t.invalid.end());
    for (std::size_t e = 0; e < kEffectCount; ++e) add_cost(texels.costs[e], t.costs[e]);
    add_geometry(texels.geometry, t.geometry);
    add_cost(texels.validity_cost, t.validity_cost);
    texels.time_ms += t.time_ms;
  }
  if (io::IoStatus st = finish_probes(scene, all); !st.ok()) return st;
  LightmapBakeResult maps;
  if (!scene.lightmaps.empty())
    if (io::IoStatus st = finish_lightmaps(scene, texels, maps); !st.ok()) return st;
  probes = std::move(all);
  lightmaps = std::move(maps);
  return io::IoStatus::success();
}

}  // namespace shpack::bake
