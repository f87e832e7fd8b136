#include "shpack/io/json_writer.h"

#include <nlohmann/json.hpp>

#include <string>

#include "json_keys.h"
#include "shpack/io/version.h"
#include "shpack/unity_pack.h"

namespace shpack::io {
namespace {

using Json = nlohmann::ordered_json;  // keeps keys in insertion order

Json dir_json(const Dir3& d) { return Json::array({d.x, d.y, d.z}); }

// float -> double is exact, and nlohmann prints the double's shortest round-trip form.
template <std::size_t N>
Json floats_json(const std::array<float, N>& values) {
  Json out = Json::array();
  for (const float v : values) out.push_back(static_cast<double>(v));
  return out;
}

Json sh_json(const ShL2& sh) {
  Json out = Json::array();
  for (const auto& channel : sh.c) out.push_back(channel);
  return out;
}

}  // namespace

std::string to_json(const ShDocument& doc) {
  Json j;
  j["schema_version"] = detail::kSchemaVersion;
  j["generator"] = std::string("shpack ") + shpack_version();
  j["source"] = {{"files", doc.source.files},
                 {"sha256", doc.source.sha256},
                 {"layout", layout_name(doc.source.layout)},
                 {"width", doc.source.width},
                 {"height", doc.source.height}};
  j["options"] = {{"method", method_name(doc.method)},
                  {"window", window_name(doc.window).text},
                  {"rotate_deg", doc.rotate_deg},
                  {"intensity", doc.intensity}};
  j["frame"] = "unity: left-handed, +Y up, +Z forward";
  j["radiance_sh"] = sh_json(doc.radiance);

  Json unity_sh = Json::array();
  for (const auto& channel : to_unity_sh(doc.unity_form)) unity_sh.push_back(floats_json(channel));
  j["sphericalHarmonicsL2"] = std::move(unity_sh);

  const UnityShaderVectors vectors = to_shader_vectors(doc.unity_form);
  Json shader = Json::object();
  for (const auto& [key, member] : detail::kShaderVectorKeys) shader[key] = floats_json(vectors.*member);
  j["shader"] = std::move(shader);

  const ShDiagnostics& diag = doc.diagnostics;
  Json min_values = Json::array(), min_directions = Json::array();
  for (const SphereMinimum& min : diag.min_e_over_pi) {
    min_values.push_back(min.value);
    min_directions.push_back(dir_json(min.direction));
  }
  j["diagnostics"] = {{"nonfinite_texels", diag.nonfinite_texels},
                      {"negative_texels", diag.negative_texels},
                      {"ignored_channels", diag.ignored_channels},
                      {"min_e_over_pi", std::move(min_values)},
                      {"min_e_over_pi_direction", std::move(min_directions)},
                      {"window_factors", diag.window_factors},
                      {"window_impossible", diag.window_impossible}};
  // A file name need not be UTF-8 on Linux: replace bad bytes rather than fail.
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace shpack::io
