#include <nlohmann/json.hpp>

#include <string>

#include "format_common.h"
#include "shpack/engine_frame.h"
#include "shpack/io/output_format.h"

namespace shpack::io {
namespace {

using OrderedJson = nlohmann::ordered_json;

// Object3D.toJSON keys every object by a uuid and ObjectLoader copies it unchecked. One
// derived from the input's SHA-256 keeps the output reproducible; the version nibble 8 and
// variant 10xx mark it as a name-based, non-random UUID (RFC 9562 section 5.8).
std::string uuid_of(const ShDocument& doc) {
  std::string hex = doc.source.sha256.empty() ? std::string() : doc.source.sha256[0];
  hex.resize(32, '0');
  hex[12] = '8';
  const int variant = 8 | (std::stoi(hex.substr(16, 1), nullptr, 16) & 3);
  hex[16] = "0123456789abcdef"[variant];
  return hex.substr(0, 8) + "-" + hex.substr(8, 4) + "-" + hex.substr(12, 4) + "-" + hex.substr(16, 4) + "-" +
         hex.substr(20, 12);
}

}  // namespace

// three.js's LightProbe as Object3D.toJSON writes it (src/lights/LightProbe.js, Light.js,
// core/Object3D.js), read back by ObjectLoader.parse: case 'LightProbe' builds
// new LightProbe(new SphericalHarmonics3().fromArray(data.sh), data.intensity).
// SphericalHarmonics3 holds radiance coefficients of the orthonormal basis without the
// Condon-Shortley phase (getBasisAt: 0.282095, 0.488603 y, ...), as radiance_sh, and
// toArray writes them coefficient-major: sh[3 i + c]. getIrradianceAt folds A_l in and
// returns E, so the shader's indirect diffuse is E * albedo / pi, Unity's E/pi.
std::string to_threejs(const ShDocument& doc) {
  const ShL2 sh = sh_to_engine_frame(EngineFrame::ThreeJs, doc.sh.radiance);
  OrderedJson coefficients = OrderedJson::array();
  for (int i = 0; i < kShCount; ++i)
    for (int c = 0; c < kChannelCount; ++c) coefficients.push_back(static_cast<double>(static_cast<float>(sh.c[c][i])));
  OrderedJson provenance = OrderedJson::array();
  for (const std::string& line : detail::provenance_lines(doc)) provenance.push_back(line);
  provenance.push_back(std::string("sh: three.js SphericalHarmonics3 (radiance), ") +
                       engine_frame_spec(EngineFrame::ThreeJs).description);
  const std::vector<std::string> name = detail::stem_words(doc);
  OrderedJson object = {{"uuid", uuid_of(doc)},
                 {"type", "LightProbe"},
                 {"name", name.front()},
                 {"layers", 1},
                 {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}},
                 {"up", {0, 1, 0}},
                 {"color", 0xffffff},
                 {"intensity", 1},
                 {"sh", std::move(coefficients)},
                 {"userData", {{"shpack", std::move(provenance)}}}};
  const OrderedJson out = {{"metadata", {{"version", 4.7}, {"type", "Object"}, {"generator", "Object3D.toJSON"}}},
                    {"object", std::move(object)}};
  return out.dump(2, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
}

}  // namespace shpack::io
