#include "shpack/io/json_writer.h"

#include <nlohmann/json.hpp>

#include <string>

#include "json_keys.h"
#include "shpack/io/sun.h"
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

// The sun of --extract-sun (sun.h): what was removed, and the Unity light that replaces it.
Json sun_json(const SunLight& sun) {
  const UnitySunLight light = unity_sun_light(sun);
  return {{"direction", dir_json(sun.direction)},
          {"irradiance", sun.irradiance},
          {"sky_level", sun.sky},
          {"angular_radius_deg", sun.radius_deg},
          {"solid_angle_sr", sun.solid_angle},
          {"texels", sun.texels},
          {"unity_light",
           {{"forward", dir_json(light.forward)},
            {"euler_deg", light.euler_deg},
            {"quaternion", light.quaternion},
            {"color", light.colour},
            {"color_srgb", light.colour_srgb},
            {"intensity", light.intensity}}}};
}

const char* cube_frame_name(CubeFrame frame) {
  return frame == CubeFrame::Gl ? "gl" : frame == CubeFrame::ThreeJs ? "threejs" : "unity";
}

// "layer" when one was chosen, "cube_frame" for cube layouts, "colorspace" always, and the
// colour matrix when one was applied.
void add_reading(const ShDocument& doc, Json& source) {
  if (!doc.reading.layer.empty()) source["layer"] = doc.reading.layer;
  if (is_cube_layout(doc.source.layout)) source["cube_frame"] = cube_frame_name(doc.reading.cube_frame);
  source["colorspace"] = doc.reading.colorspace;
  if (doc.colour_matrix) source["rgb_to_rec709"] = *doc.colour_matrix;
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
  add_reading(doc, j["source"]);
  j["options"] = {{"method", std::string(method_name(doc.method).view())},
                  {"window", window_name(doc.window).text},
                  {"rotate_deg", doc.rotate_deg},
                  {"intensity", doc.intensity}};
  if (doc.l1) j["options"]["l1"] = true;  // --l1 (output_format.h): only when given
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
  if (doc.sun_extraction) j["sun"] = doc.sun ? sun_json(*doc.sun) : Json(nullptr);  // null: no sun found
  // A file name need not be UTF-8 on Linux: replace bad bytes rather than fail.
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace shpack::io
