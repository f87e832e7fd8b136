#include "shpack/bake/bake_part.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <span>

#include <nlohmann/json.hpp>

#include "probe_validity.h"
#include "shpack/io/sha256.h"
#include "shpack/io/version.h"

namespace shpack::bake {
namespace {

using Json = nlohmann::json;
static_assert(std::endian::native == std::endian::little, "part files are little-endian");

constexpr std::string_view kMagic = "SHPACKPART 1\n";
constexpr std::size_t kDigestBytes = 32;
constexpr std::size_t kMaxHeader = 1 << 20;

// ---- Binary records: fixed-size fields, little-endian, no padding ----
class Writer {
 public:
  template <class T>
  void put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    bytes.append(b, sizeof(T));
  }
  void put_sh(const ShL2& sh) {
    for (const auto& channel : sh.c)
      for (const double v : channel) put(v);
  }
  std::string bytes;
};

class Reader {
 public:
  explicit Reader(std::string_view b) : rest(b) {}
  template <class T>
  T get() {
    T v{};
    std::memcpy(&v, rest.data(), sizeof(T));  // the caller checked the size of every record
    rest.remove_prefix(sizeof(T));
    return v;
  }
  ShL2 get_sh() {
    ShL2 sh;
    for (auto& channel : sh.c)
      for (double& v : channel) v = get<double>();
    return sh;
  }
  std::string_view rest;
};

// Per probe: radiance; per effect samples, capped, error; validity.
constexpr std::size_t kShBytes = 8 * kShCount * kChannelCount;
constexpr std::size_t kSamplingBytes = 8 + 1 + 3 * 8;
constexpr std::size_t kValidityBytes = 8 + 1 + 8 + 1 + 3 * 8 + 8;
constexpr std::size_t kProbeBytes = kShBytes + kEffectCount * kSamplingBytes + kValidityBytes;
// Per texel: map, texel, radiance, error_pct, backface, invalid.
constexpr std::size_t kTexelBytes = 4 + 4 + kShBytes + 4 + 4 + 1;

void put_probe(Writer& w, const BakeResult& r, std::size_t k) {
  w.put_sh(r.radiance[k]);
  for (const EffectSampling& s : r.sampling[k]) {
    w.put<std::uint64_t>(s.samples);
    w.put<std::uint8_t>(s.capped ? 1 : 0);
    for (const double e : s.error) w.put(e);
  }
  const ProbeValidity& v = r.validity[k];
  w.put(v.backface_fraction);
  w.put<std::uint8_t>(v.valid ? 1 : 0);
  w.put<std::int64_t>(v.backface_shape ? static_cast<std::int64_t>(*v.backface_shape) : -1);
  w.put<std::uint8_t>(v.offset_position ? 1 : 0);
  const Point3 p = v.offset_position.value_or(Point3{});
  for (const double x : {p.x, p.y, p.z}) w.put(x);
  w.put(v.offset_backface_fraction);
}

void get_probe(Reader& r, BakeResult& out) {
  out.radiance.push_back(r.get_sh());
  std::array<EffectSampling, kEffectCount> sampling{};
  for (EffectSampling& s : sampling) {
    s.samples = r.get<std::uint64_t>();
    s.capped = r.get<std::uint8_t>() != 0;
    for (double& e : s.error) e = r.get<double>();
  }
  out.sampling.push_back(sampling);
  ProbeValidity v;
  v.backface_fraction = r.get<double>();
  v.valid = r.get<std::uint8_t>() != 0;
  const auto shape = r.get<std::int64_t>();
  if (shape >= 0) v.backface_shape = static_cast<std::uint32_t>(shape);
  const bool moved = r.get<std::uint8_t>() != 0;
  Point3 p;
  p.x = r.get<double>();
  p.y = r.get<double>();
  p.z = r.get<double>();
  if (moved) v.offset_position = p;
  v.offset_backface_fraction = r.get<double>();
  out.validity.push_back(v);
}

void put_texel(Writer& w, const LightmapTexelPart& t, std::size_t u) {
  w.put(t.texels[u].map);
  w.put(t.texels[u].texel);
  w.put_sh(t.radiance[u]);
  w.put(t.error_pct[u]);
  w.put(t.backface[u]);
  w.put(t.invalid[u]);
}

void get_texel(Reader& r, LightmapTexelPart& out) {
  TexelRef ref;
  ref.map = r.get<std::uint32_t>();
  ref.texel = r.get<std::uint32_t>();
  out.texels.push_back(ref);
  out.radiance.push_back(r.get_sh());
  out.error_pct.push_back(r.get<float>());
  out.backface.push_back(r.get<float>());
  out.invalid.push_back(r.get<std::uint8_t>());
}

// ---- Costs in the header: integers and doubles, both exact in JSON ----
Json cost_json(const EffectCost& c) {
  return {c.enabled, c.time_ms, c.cpu_ms, c.rays, c.samples, c.analytic};
}
EffectCost cost_of(const Json& j) {
  return {j.at(0).get<bool>(),          j.at(1).get<double>(),        j.at(2).get<double>(),
          j.at(3).get<std::uint64_t>(), j.at(4).get<std::uint64_t>(), j.at(5).get<std::uint64_t>()};
}
Json costs_json(const std::array<EffectCost, kEffectCount>& costs, const GeometryCost& g, const EffectCost& validity) {
  Json effects = Json::array();
  for (const EffectCost& c : costs) effects.push_back(cost_json(c));
  return {{"effects", effects},
          {"geometry", {g.built, g.time_ms, g.triangles, g.spheres}},
          {"validity", cost_json(validity)}};
}
void costs_of(const Json& j, std::array<EffectCost, kEffectCount>& costs, GeometryCost& g, EffectCost& validity) {
  for (std::size_t e = 0; e < kEffectCount; ++e) costs[e] = cost_of(j.at("effects").at(e));
  const Json& geometry = j.at("geometry");
  g = {geometry.at(0).get<bool>(), geometry.at(1).get<double>(), geometry.at(2).get<std::uint64_t>(),
       geometry.at(3).get<std::uint64_t>()};
  validity = cost_of(j.at("validity"));
}

void add_cost(EffectCost& into, const EffectCost& from) {
  into.enabled = into.enabled || from.enabled;
  into.time_ms += from.time_ms;
  into.cpu_ms += from.cpu_ms;
  into.rays += from.rays;
  into.samples += from.samples;
  into.analytic += from.analytic;
}

// One tracer built per part: the scene's counts, the times summed.
void add_geometry(GeometryCost& into, const GeometryCost& from) {
  if (!from.built) return;
  into.built = true;
  into.time_ms += from.time_ms;
  into.triangles = from.triangles;
  into.spheres = from.spheres;
}

bool is_delta(const scene::SceneLight& light) {
  using scene::LightType;
  return light.type == LightType::Point || light.type == LightType::Spot ||
         (light.type == LightType::Directional && light.angular_diameter == 0);
}

std::string shard_text(ShardSpec s) { return std::to_string(s.index) + "/" + std::to_string(s.count); }

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
  const double per = estimated_rays(scene);
  const std::size_t count = scene.probes.size() + texel_points.size();
  const auto cost = [&](std::size_t i) {
    return i < scene.probes.size() ? per : per * texel_points[i - scene.probes.size()];
  };
  double total = 0;
  for (std::size_t i = 0; i < count; ++i) total += cost(i);
  // Item i is shard floor(N midpoint_i / C) + 1: a monotone function of i, so every shard is
  // one run of items, and the runs tile them.
  const auto shard_of = [&](double midpoint) {
    const double at = std::floor(static_cast<double>(shard.count) * midpoint / total);
    return static_cast<std::uint32_t>(std::min<double>(shard.count - 1, std::max(0.0, at))) + 1;
  };
  std::size_t first = count, last = count;
  double before = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const double c = cost(i);
    const std::uint32_t k = shard_of(before + c / 2);
    before += c;
    if (k == shard.index && first == count) first = i;
    if (k == shard.index) last = i + 1;
    if (k > shard.index) break;
  }
  if (first == count) last = count;
  const std::size_t p = scene.probes.size();
  probes = {std::min(first, p), std::min(last, p) - std::min(first, p)};
  texels = {std::max(first, p) - p, std::max(last, p) - std::max(first, p)};
}

io::IoStatus bake_part(const scene::Scene& scene, const BakeOptions& options, ShardSpec shard, BakePart& out) {
  BakePart part;
  std::vector<std::uint32_t> texel_points;
  if (io::IoStatus st = lightmap_texel_points(scene, texel_points); !st.ok()) return st;
  plan_shard(scene, texel_points, shard, part.probes, part.texels);
  part.scene_file = std::filesystem::absolute(scene.file).lexically_normal().string();
  part.scene_sha256 = scene.sha256;
  part.version = io::shpack_version();
  part.seed = scene.settings.seed;
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

std::string encode_part(const BakePart& part) {
  const BakeResult& p = part.probe_result;
  const LightmapTexelPart& t = part.texel_result;
  const Json header = {
      {"kind", "shpack-bake-part"},
      {"scene", part.scene_file},
      {"scene_sha256", part.scene_sha256},
      {"version", part.version},
      {"seed", part.seed},
      {"shard", {part.shard.index, part.shard.count}},
      {"probes", {part.probes.first, part.probes.count, part.probes_total}},
      {"texels", {part.texels.first, part.texels.count, part.texels_total}},
      {"probe_costs", costs_json(p.costs, p.geometry, p.validity_cost)},
      {"texel_costs", costs_json(t.costs, t.geometry, t.validity_cost)},
      {"texel_time_ms", t.time_ms}};
  Writer w;
  w.bytes.append(kMagic);
  w.bytes.append(header.dump()).push_back('\n');
  for (std::size_t k = 0; k < part.probes.count; ++k) put_probe(w, p, k);
  for (std::size_t u = 0; u < part.texels.count; ++u) put_texel(w, t, u);
  io::Sha256 hash;
  hash.update(std::as_bytes(std::span(w.bytes.data(), w.bytes.size())));
  const io::Sha256Digest digest = hash.finish();
  w.bytes.append(reinterpret_cast<const char*>(digest.data()), digest.size());
  return std::move(w.bytes);
}

bool decode_part(std::string_view bytes, BakePart& out, std::string& error) {
  if (!bytes.starts_with(kMagic)) {
    error = "not a shpack bake part (shpack bake --shard K/N writes them)";
    return false;
  }
  if (bytes.size() < kMagic.size() + kDigestBytes) {
    error = "truncated: it ends before its hash";
    return false;
  }
  const std::string_view body = bytes.substr(0, bytes.size() - kDigestBytes);
  io::Sha256 hash;
  hash.update(std::as_bytes(std::span(body.data(), body.size())));
  const io::Sha256Digest digest = hash.finish();
  if (std::memcmp(digest.data(), bytes.data() + body.size(), kDigestBytes) != 0) {
    error = "truncated or altered: its SHA-256 does not match its bytes";
    return false;
  }
  const std::size_t eol = body.find('\n', kMagic.size());
  if (eol == std::string_view::npos || eol - kMagic.size() > kMaxHeader) {
    error = "its header is not one line of at most 1 MiB";
    return false;
  }
  BakePart part;
  try {
    const Json h = Json::parse(body.substr(kMagic.size(), eol - kMagic.size()));
    if (h.at("kind") != "shpack-bake-part") throw std::runtime_error("kind");
    part.scene_file = h.at("scene").get<std::string>();
    part.scene_sha256 = h.at("scene_sha256").get<std::string>();
    part.version = h.at("version").get<std::string>();
    part.seed = h.at("seed").get<std::uint64_t>();
    part.shard = {h.at("shard").at(0).get<std::uint32_t>(), h.at("shard").at(1).get<std::uint32_t>()};
    const Json& probes = h.at("probes");
    const Json& texels = h.at("texels");
    part.probes = {probes.at(0).get<std::uint64_t>(), probes.at(1).get<std::uint64_t>()};
    part.probes_total = probes.at(2).get<std::uint64_t>();
    part.texels = {texels.at(0).get<std::uint64_t>(), texels.at(1).get<std::uint64_t>()};
    part.texels_total = texels.at(2).get<std::uint64_t>();
    costs_of(h.at("probe_costs"), part.probe_result.costs, part.probe_result.geometry, part.probe_result.validity_cost);
    costs_of(h.at("texel_costs"), part.texel_result.costs, part.texel_result.geometry, part.texel_result.validity_cost);
    part.texel_result.time_ms = h.at("texel_time_ms").get<double>();
  } catch (const std::exception&) {
    error = "its header is not a part's (JSON with the keys shpack bake --shard writes)";
    return false;
  }
  // The counts against the bytes, before anything is allocated for them.
  if (part.shard.count < 1 || part.shard.count > 1000000 || part.shard.index < 1 ||
      part.shard.index > part.shard.count) {
    error = "its shard " + shard_text(part.shard) + " is not K/N with 1 <= K <= N <= 1000000";
    return false;
  }
  const std::uint64_t payload = body.size() - eol - 1;
  const std::uint64_t probe_bytes = part.probes.count <= payload / kProbeBytes ? part.probes.count * kProbeBytes : 0;
  const std::uint64_t rest = payload - probe_bytes;
  if (part.probes.count > payload / kProbeBytes || part.texels.count > rest / kTexelBytes ||
      part.texels.count * kTexelBytes != rest) {
    error = "its records do not hold the " + std::to_string(part.probes.count) + " probes and " +
            std::to_string(part.texels.count) + " texels its header says";
    return false;
  }
  Reader r(body.substr(eol + 1));
  for (std::uint64_t k = 0; k < part.probes.count; ++k) get_probe(r, part.probe_result);
  for (std::uint64_t u = 0; u < part.texels.count; ++u) get_texel(r, part.texel_result);
  out = std::move(part);
  return true;
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
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const BakePart& p = parts[i];
    if (p.version != io::shpack_version())
      return refuse(i, "made by shpack " + p.version + ", not by this shpack " + io::shpack_version());
    if (p.scene_sha256 != scene.sha256 || p.probes_total != scene.probes.size() ||
        p.texels_total != texel_points.size())
      return refuse(i, "a part of another scene (SHA-256 " + p.scene_sha256.substr(0, 12) + "..., not " +
                           scene.sha256.substr(0, 12) + "... of " + scene.file.string() + ")");
    if (p.seed != scene.settings.seed)
      return refuse(i, "baked with seed " + std::to_string(p.seed) + ", not the scene's " +
                           std::to_string(scene.settings.seed));
    if (p.shard.count != n || p.shard.index < 1 || p.shard.index > n)
      return refuse(i, "shard " + shard_text(p.shard) + " is not one of " + std::to_string(n));
    if (of_shard[p.shard.index - 1] != parts.size())
      return refuse(i, "shard " + shard_text(p.shard) + " twice (also " + names[of_shard[p.shard.index - 1]] + ")");
    for (const ProbeValidity& v : p.probe_result.validity)
      if (v.backface_shape && *v.backface_shape >= scene.geometry.size())
        return refuse(i, "a probe's backface shape is not one of the scene's shapes");
    ItemRange want_probes, want_texels;
    plan_shard(scene, texel_points, p.shard, want_probes, want_texels);
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
