#include <nlohmann/json.hpp>

#include <numbers>
#include <string>

#include "format_common.h"
#include "shpack/engine_frame.h"
#include "shpack/io/output_format.h"
#include "shpack/io/version.h"

namespace shpack::io {

// A glTF 2.0 document with one EXT_lights_image_based light, referenced by its only scene
// (extension README: root "lights", scene "light"). irradianceCoefficients is a 9x3 array of
// irradiance coefficients E_i = A_l L_i (Ramamoorthi and Hanrahan, which the README cites),
// in glTF's frame, with the Condon-Shortley signs of Babylon.js, the extension's reference
// reader (SphericalHarmonics.FromArray, SH3ylmBasisConstants); E_i = pi u_i / k_i from the
// Unity form. The light has no specularImages or specularImageSize, which the schema
// requires: shpack makes no prefiltered cube map (docs/formats.md).
std::string to_gltf(const ShDocument& doc) {
  using Json = nlohmann::ordered_json;
  ShL2 sh = unity_form_to_engine_frame(EngineFrame::Gltf, doc.sh.unity_form);
  Json coefficients = Json::array();
  for (int i = 0; i < kShCount; ++i) {
    Json rgb = Json::array();
    for (int c = 0; c < kChannelCount; ++c) {
      const double irradiance = std::numbers::pi * sh.c[c][i] / kBasisScale[i] * kCondonShortleySign[i];
      rgb.push_back(static_cast<double>(static_cast<float>(irradiance)));
    }
    coefficients.push_back(std::move(rgb));
  }
  Json provenance = Json::array();
  for (const std::string& line : detail::provenance_lines(doc)) provenance.push_back(line);
  provenance.push_back(std::string("irradianceCoefficients: E_i = A_l L_i, Condon-Shortley signs, ") +
                       engine_frame_spec(EngineFrame::Gltf).description);
  const Json light = {{"name", detail::stem_words(doc).front()},
                      {"rotation", {0.0, 0.0, 0.0, 1.0}},
                      {"intensity", 1.0},
                      {"irradianceCoefficients", std::move(coefficients)}};
  const Json out = {
      {"asset", {{"version", "2.0"}, {"generator", std::string("shpack ") + shpack_version()},
                 {"extras", {{"shpack", std::move(provenance)}}}}},
      {"extensionsUsed", {"EXT_lights_image_based"}},
      {"extensions", {{"EXT_lights_image_based", {{"lights", Json::array({light})}}}}},
      {"scene", 0},
      {"scenes", Json::array({{{"extensions", {{"EXT_lights_image_based", {{"light", 0}}}}}}})}};
  return out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace shpack::io
