#include "shpack/bake/bake_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "shpack/io/sh_record_json.h"
#include "shpack/io/version.h"
#include "shpack/pipeline.h"

namespace shpack::bake {
namespace {

using OrderedJson = nlohmann::ordered_json;

// The inside of a JSON array, "a,b,c", of the values given (nlohmann's shortest forms).
std::string array_items(const OrderedJson& array) {
  const std::string text = array.dump();
  return text.substr(1, text.size() - 2);
}

// Probe validity (docs/scenes.md, "Probe validity"): whether the probe is inside geometry, and
// what it got instead.
void put_validity(const scene::Scene& scene, const ProbeValidity& v, OrderedJson& diagnostics) {
  diagnostics["valid"] = v.valid;
  diagnostics["backface_fraction"] = v.backface_fraction;
  if (!v.valid && v.backface_shape) diagnostics["inside"] = scene.geometry[*v.backface_shape].label;
  if (v.offset_position) {
    diagnostics["offset_position"] = {v.offset_position->x, v.offset_position->y, v.offset_position->z};
    diagnostics["offset_backface_fraction"] = v.offset_backface_fraction;
  }
  diagnostics["dilated"] = v.dilated;
}

// The Monte Carlo effects' sampling of one probe (bake.h, EffectSampling): the estimated
// error of everything together and, per effect, the samples taken and the error.
void put_sampling(const BakeResult& result, std::size_t k, OrderedJson& diagnostics) {
  if (k >= result.error_estimate_pct.size()) return;
  diagnostics["error_estimate_pct"] = result.error_estimate_pct[k];
  OrderedJson samples = OrderedJson::object(), errors = OrderedJson::object(), capped = OrderedJson::array();
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    if (!result.costs[e].enabled) continue;
    const EffectSampling& s = result.sampling[k][e];
    if (s.samples == 0) continue;
    const char* name = effect_name(static_cast<Effect>(e));
    samples[name] = s.samples;
    errors[name] = s.error_pct;
    if (s.capped) capped.push_back(name);
  }
  diagnostics["effect_error_pct"] = std::move(errors);
  diagnostics["samples"] = std::move(samples);
  diagnostics["capped"] = std::move(capped);
}

// Per effect over the probes: the largest error estimate, the samples' range, the capped count.
void put_effect_sampling(const BakeResult& result, std::size_t e, OrderedJson& effect) {
  double worst = 0;
  std::uint64_t least = 0, most = 0, capped = 0;
  bool any = false;
  for (const auto& probe : result.sampling) {
    const EffectSampling& s = probe[e];
    if (s.samples == 0) continue;
    worst = std::max(worst, s.error_pct);
    least = any ? std::min(least, s.samples) : s.samples;
    most = std::max(most, s.samples);
    capped += s.capped ? 1 : 0;
    any = true;
  }
  if (!any) return;
  effect["error_estimate_pct_max"] = worst;
  effect["samples_per_probe"] = {least, most};
  effect["capped_probes"] = capped;
}

const char* policy_name(scene::InvalidProbes policy) {
  switch (policy) {
    case scene::InvalidProbes::Dilate: return "dilate";
    case scene::InvalidProbes::Keep: return "keep";
    case scene::InvalidProbes::Error: return "error";
    case scene::InvalidProbes::Offset: return "offset";
  }
  return "dilate";
}

}  // namespace

io::IoStatus bake_to_json(const scene::Scene& scene, const BakeResult& result, const BakeJsonOptions& options,
                          std::string& json) {
  try {
    // Probes are formatted one at a time and appended as text, so memory holds the output and
    // one probe's tree, not a tree of every number.
    std::string probes, positions, flat;
    for (std::size_t k = 0; k < result.radiance.size(); ++k) {
      // Each probe's SH through the finish stage (pipeline.h): the window, the float32 check,
      // the minimum and the packing, as `convert` finishes a map.
      FinishOptions finish;
      finish.window = options.window;
      FinishedSh sh;
      if (Status st = finish_projection(result.radiance[k], finish, sh); !st.ok()) {
        const std::string what = st.code == Errc::OutOfRange ? "too bright for Unity's float32 coefficients" : st.what;
        return io::IoStatus::error(st.code == Errc::OutOfRange ? io::IoErrc::Unsupported : io::IoErrc::InvalidArgument,
                                   scene.file, scene::probe_label(scene, k) + ": " + what);
      }
      const UnitySphericalHarmonicsL2& unity_sh = sh.unity_sh;
      const Point3& p = scene.probes[k];
      const char* separator = k == 0 ? "" : ",";
      if (options.format == BakeFormat::UnityProbes) {
        OrderedJson position = OrderedJson::array(), sh = OrderedJson::array();
        for (const double v : {p.x, p.y, p.z}) position.push_back(static_cast<double>(static_cast<float>(v)));
        for (const auto& channel : unity_sh)
          for (const float v : channel) sh.push_back(static_cast<double>(v));
        positions.append(separator).append(array_items(position));
        flat.append(separator).append(array_items(sh));
        continue;
      }
      OrderedJson probe;
      probe["position"] = {p.x, p.y, p.z};
      io::put_sh_values(sh, probe);
      OrderedJson diagnostics = OrderedJson::object();
      io::put_sh_diagnostics(sh, diagnostics);
      if (k < result.validity.size()) put_validity(scene, result.validity[k], diagnostics);
      put_sampling(result, k, diagnostics);
      probe["diagnostics"] = std::move(diagnostics);
      probes.append(separator).append("\n    ").append(probe.dump(-1, ' ', false, OrderedJson::error_handler_t::replace));
    }
    if (options.format == BakeFormat::UnityProbes) {
      json = "{\"schema_version\":1,\"format\":\"unity-probes\",\"count\":" + std::to_string(result.radiance.size()) +
             ",\"positions\":[" + positions + "],\"sphericalHarmonicsL2\":[" + flat + "]}\n";
      return io::IoStatus::success();
    }
    OrderedJson j;
    j["schema_version"] = 1;
    j["generator"] = std::string("shpack ") + io::shpack_version();
    j["scene"] = {{"file", scene.file.filename().string()}, {"sha256", scene.sha256},
                  {"probes", scene.probes.size()}, {"lights", scene.lights.size()},
                  {"shapes", scene.geometry.size()}, {"seed", scene.settings.seed}};
    j["frame"] = "unity: left-handed, +Y up, +Z forward";
    j["options"] = {{"window", window_name(options.window).text}};
    j["sampling"] = {{"target_error_pct", scene.settings.target_error_pct}, {"max_samples", scene.settings.max_samples}};
    j["probes"] = nullptr;  // replaced by the probes' text below
    OrderedJson effects = OrderedJson::object();
    for (std::size_t e = 0; e < kEffectCount; ++e) {
      const EffectCost& c = result.costs[e];
      if (!c.enabled) continue;
      OrderedJson effect = {{"time_ms", c.time_ms}, {"cpu_ms", c.cpu_ms}, {"rays", c.rays},
                     {"samples", c.samples}, {"analytic", c.analytic}};
      put_effect_sampling(result, e, effect);
      effects[effect_name(static_cast<Effect>(e))] = std::move(effect);
    }
    j["effects"] = std::move(effects);
    j["geometry"] = {{"built", result.geometry.built}, {"time_ms", result.geometry.time_ms},
                     {"triangles", result.geometry.triangles}, {"spheres", result.geometry.spheres}};
    const ValidityCounts& vc = result.validity_counts;
    j["validity"] = {{"measured", result.validity_cost.enabled}, {"threshold", scene.settings.validity_threshold},
                     {"invalid_probes", policy_name(scene.settings.invalid_probes)}, {"invalid", vc.invalid},
                     {"moved", vc.moved}, {"dilated", vc.dilated}, {"time_ms", result.validity_cost.time_ms},
                     {"rays", result.validity_cost.rays}};
    if (options.lightmaps) {
      OrderedJson maps = OrderedJson::array();
      for (std::size_t m = 0; m < options.lightmaps->maps.size(); ++m) {
        const LightmapTexels& map = options.lightmaps->maps[m];
        float worst = 0;
        for (std::size_t t = 0; t < map.state.size(); ++t)
          if (map.state[t] == TexelState::Baked) worst = std::max(worst, map.error_pct[t]);
        const double seconds = options.lightmaps->time_ms / 1000.0;
        maps.push_back({{"name", scene.lightmaps[m].name}, {"shape", scene.lightmaps[m].label},
                        {"width", map.width}, {"height", map.height},
                        {"sidecar", scene.lightmaps[m].name + ".lightmap.json"}, {"used", map.used},
                        {"error_estimate_max_pct", worst},
                        {"texels_per_s", seconds > 0 ? static_cast<double>(map.used) / seconds : 0.0}});
      }
      j["lightmaps"] = std::move(maps);
    }
    // One probe per line inside the indented document. The only top-level "probes": null is
    // the placeholder ("scene" holds "probes" too, as a number).
    json = j.dump(2, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
    const std::string placeholder = "\n  \"probes\": null,";
    const std::size_t at = json.find(placeholder);
    json.replace(at, placeholder.size(), "\n  \"probes\": [" + probes + "\n  ],");
    return io::IoStatus::success();
  } catch (const std::exception& e) {
    return io::IoStatus::error(io::IoErrc::Core, scene.file, std::string("cannot write the JSON: ") + e.what());
  }
}

}  // namespace shpack::bake
