// part_file.cpp - the part file of a sharded bake (bake_part.h): encode_part, decode_part.
// Its own file, with no dependency past lib/io, so that the fuzz target reads parts alone.
#include <bit>
#include <cmath>
#include <cstring>
#include <span>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "shpack/bake/bake_part.h"
#include "shpack/io/sha256.h"

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
    if constexpr (std::is_floating_point_v<T>) sound = sound && !std::isnan(v);
    return v;
  }
  ShL2 get_sh() {
    ShL2 sh;
    for (auto& channel : sh.c)
      for (double& v : channel) {
        v = get<double>();
        sound = sound && std::isfinite(v);
      }
    return sh;
  }
  std::string_view rest;
  // No NaN read so far, and no infinite coefficient: a bake writes none (an error estimate
  // is infinite where a point got no light but some noise).
  bool sound = true;
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
// A header's whole number: nlohmann's get<> of a float or a negative number into an unsigned
// type is undefined (a float beyond its range), so the kind is checked first.
std::uint64_t count_at(const Json& j) {
  if (!j.is_number_unsigned()) throw std::runtime_error("not a count");
  return j.get<std::uint64_t>();
}
std::uint32_t count32_at(const Json& j) {
  const std::uint64_t v = count_at(j);
  if (v > 0xffffffffu) throw std::runtime_error("not a 32-bit count");
  return static_cast<std::uint32_t>(v);
}
double number_at(const Json& j) {
  if (!j.is_number()) throw std::runtime_error("not a number");
  return j.get<double>();
}
Json cost_json(const EffectCost& c) {
  return {c.enabled, c.time_ms, c.cpu_ms, c.rays, c.samples, c.analytic};
}
EffectCost cost_of(const Json& j) {
  return {j.at(0).get<bool>(),          number_at(j.at(1)),        number_at(j.at(2)),
          count_at(j.at(3)), count_at(j.at(4)), count_at(j.at(5))};
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
  g = {geometry.at(0).get<bool>(), number_at(geometry.at(1)), count_at(geometry.at(2)),
       count_at(geometry.at(3))};
  validity = cost_of(j.at("validity"));
}

}  // namespace

std::string shard_text(ShardSpec s) { return std::to_string(s.index) + "/" + std::to_string(s.count); }

std::string settings_record(const scene::SceneSettings& s) {
  static constexpr const char* kPolicies[] = {"dilate", "keep", "error", "offset"};
  return Json{{"seed", s.seed},
              {"shadow_samples", s.shadow_samples},
              {"sky_samples", s.sky_samples},
              {"bounce_samples", s.bounce_samples},
              {"target_error_pct", s.target_error_pct},
              {"max_samples", s.max_samples},
              {"validity_threshold", s.validity_threshold},
              {"invalid_probes", kPolicies[static_cast<int>(s.invalid_probes)]},
              {"max_offset", s.max_offset}}
      .dump();
}

std::string settings_difference(const std::string& part, const std::string& scene) {
  const Json a = Json::parse(part, nullptr, false), b = Json::parse(scene, nullptr, false);
  if (!a.is_object() || !b.is_object()) return "settings that are not an object";
  for (const auto& [key, value] : b.items()) {
    const auto found = a.find(key);
    if (found == a.end()) return "no " + key + " (the scene's " + value.dump() + ")";
    if (*found != value) return key + " " + found->dump() + ", not the scene's " + value.dump();
  }
  for (const auto& [key, value] : a.items())
    if (!b.contains(key)) return key + " " + value.dump() + ", which the scene's settings do not have";
  return {};
}

std::string encode_part(const BakePart& part) {
  const BakeResult& p = part.probe_result;
  const LightmapTexelPart& t = part.texel_result;
  const Json header = {
      {"kind", "shpack-bake-part"},
      {"scene", part.scene_file},
      {"scene_sha256", part.scene_sha256},
      {"version", part.version},
      {"settings", Json::parse(part.settings)},
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
    if (!h.at("settings").is_object()) throw std::runtime_error("settings");
    part.settings = h.at("settings").dump();
    part.shard = {count32_at(h.at("shard").at(0)), count32_at(h.at("shard").at(1))};
    const Json& probes = h.at("probes");
    const Json& texels = h.at("texels");
    part.probes = {count_at(probes.at(0)), count_at(probes.at(1))};
    part.probes_total = count_at(probes.at(2));
    part.texels = {count_at(texels.at(0)), count_at(texels.at(1))};
    part.texels_total = count_at(texels.at(2));
    costs_of(h.at("probe_costs"), part.probe_result.costs, part.probe_result.geometry, part.probe_result.validity_cost);
    costs_of(h.at("texel_costs"), part.texel_result.costs, part.texel_result.geometry, part.texel_result.validity_cost);
    part.texel_result.time_ms = number_at(h.at("texel_time_ms"));
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
  if (!r.sound) {
    error = "its records hold a NaN or an infinite coefficient";
    return false;
  }
  out = std::move(part);
  return true;
}

}  // namespace shpack::bake
