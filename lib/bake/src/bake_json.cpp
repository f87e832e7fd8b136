#include "shpack/bake/bake_json.h"

#include <nlohmann/json.hpp>

#include <cmath>

#include "shpack/io/sh_record_json.h"
#include "shpack/io/version.h"
#include "shpack/pipeline.h"

namespace shpack::bake {
namespace {

using Json = nlohmann::ordered_json;

// The inside of a JSON array, "a,b,c", of the values given (nlohmann's shortest forms).
std::string array_items(const Json& array) {
  const std::string text = array.dump();
  return text.substr(1, text.size() - 2);
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
        Json position = Json::array(), sh = Json::array();
        for (const double v : {p.x, p.y, p.z}) position.push_back(static_cast<double>(static_cast<float>(v)));
        for (const auto& channel : unity_sh)
          for (const float v : channel) sh.push_back(static_cast<double>(v));
        positions.append(separator).append(array_items(position));
        flat.append(separator).append(array_items(sh));
        continue;
      }
      Json probe;
      probe["position"] = {p.x, p.y, p.z};
      io::put_sh_values(sh, probe);
      Json diagnostics = Json::object();
      io::put_sh_diagnostics(sh, diagnostics);
      probe["diagnostics"] = std::move(diagnostics);
      probes.append(separator).append("\n    ").append(probe.dump(-1, ' ', false, Json::error_handler_t::replace));
    }
    if (options.format == BakeFormat::UnityProbes) {
      json = "{\"schema_version\":1,\"format\":\"unity-probes\",\"count\":" + std::to_string(result.radiance.size()) +
             ",\"positions\":[" + positions + "],\"sphericalHarmonicsL2\":[" + flat + "]}\n";
      return io::IoStatus::success();
    }
    Json j;
    j["schema_version"] = 1;
    j["generator"] = std::string("shpack ") + io::shpack_version();
    j["scene"] = {{"file", scene.file.filename().string()}, {"sha256", scene.sha256},
                  {"probes", scene.probes.size()}, {"lights", scene.lights.size()},
                  {"shapes", scene.geometry.size()}, {"seed", scene.settings.seed}};
    j["frame"] = "unity: left-handed, +Y up, +Z forward";
    j["options"] = {{"window", window_name(options.window).text}};
    j["probes"] = nullptr;  // replaced by the probes' text below
    Json effects = Json::object();
    for (std::size_t e = 0; e < kEffectCount; ++e) {
      const EffectCost& c = result.costs[e];
      if (!c.enabled) continue;
      effects[effect_name(static_cast<Effect>(e))] = {{"time_ms", c.time_ms}, {"cpu_ms", c.cpu_ms},
                                                      {"rays", c.rays},       {"samples", c.samples},
                                                      {"analytic", c.analytic}};
    }
    j["effects"] = std::move(effects);
    j["geometry"] = {{"built", result.geometry.built}, {"time_ms", result.geometry.time_ms},
                     {"triangles", result.geometry.triangles}, {"spheres", result.geometry.spheres}};
    // One probe per line inside the indented document. The only top-level "probes": null is
    // the placeholder ("scene" holds "probes" too, as a number).
    json = j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
    const std::string placeholder = "\n  \"probes\": null,";
    const std::size_t at = json.find(placeholder);
    json.replace(at, placeholder.size(), "\n  \"probes\": [" + probes + "\n  ],");
    return io::IoStatus::success();
  } catch (const std::exception& e) {
    return io::IoStatus::error(io::IoErrc::Core, scene.file, std::string("cannot write the JSON: ") + e.what());
  }
}

}  // namespace shpack::bake
