// sh_record_json.h - the keys of one finished SH (shpack/pipeline.h FinishedSh) in a JSON
// document, written once for `convert`'s document and for every probe of `bake`
// (docs/json-format.md), and read back by json_reader.h.
//
// The functions are templates over the JSON value type (nlohmann::ordered_json in the
// writers), so that this header names no JSON library: only the libraries that write JSON
// link one. They copy numbers; they compute nothing.
//
// Numbers: doubles are written in the shortest form that reads back to the same double;
// each float32 of sphericalHarmonicsL2 and shader as the double of equal value, so any
// reader gets the exact float back.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "shpack/pipeline.h"
#include "shpack/unity_pack.h"

namespace shpack::io {

inline constexpr int kSchemaVersion = 1;

// The "shader" object: key and vector, in the order Unity's shader declares them.
inline constexpr std::array<std::pair<const char*, UnityShaderVectors::Float4 UnityShaderVectors::*>, 7>
    kShaderVectorKeys = {{{"unity_SHAr", &UnityShaderVectors::SHAr},
                          {"unity_SHAg", &UnityShaderVectors::SHAg},
                          {"unity_SHAb", &UnityShaderVectors::SHAb},
                          {"unity_SHBr", &UnityShaderVectors::SHBr},
                          {"unity_SHBg", &UnityShaderVectors::SHBg},
                          {"unity_SHBb", &UnityShaderVectors::SHBb},
                          {"unity_SHC", &UnityShaderVectors::SHC}}};

template <class Json>
Json dir_json(const Dir3& d) {
  return Json::array({d.x, d.y, d.z});
}

template <class Json, std::size_t N>
Json floats_json(const std::array<float, N>& values) {
  Json out = Json::array();
  for (const float v : values) out.push_back(static_cast<double>(v));
  return out;
}

// "radiance_sh", "sphericalHarmonicsL2" and "shader", in that order.
template <class Json>
void put_sh_values(const FinishedSh& sh, Json& out) {
  Json radiance = Json::array();
  for (const auto& channel : sh.radiance.c) radiance.push_back(channel);
  out["radiance_sh"] = std::move(radiance);
  Json unity_sh = Json::array();
  for (const auto& channel : sh.unity_sh) unity_sh.push_back(floats_json<Json>(channel));
  out["sphericalHarmonicsL2"] = std::move(unity_sh);
  Json shader = Json::object();
  for (const auto& [key, member] : kShaderVectorKeys) shader[key] = floats_json<Json>(sh.shader.*member);
  out["shader"] = std::move(shader);
}

// "min_e_over_pi", "min_e_over_pi_direction" and "window_factors" of a "diagnostics" object.
template <class Json>
void put_sh_diagnostics(const FinishedSh& sh, Json& diagnostics) {
  Json values = Json::array(), directions = Json::array();
  for (const SphereMinimum& min : sh.min_e_over_pi) {
    values.push_back(min.value);
    directions.push_back(dir_json<Json>(min.direction));
  }
  diagnostics["min_e_over_pi"] = std::move(values);
  diagnostics["min_e_over_pi_direction"] = std::move(directions);
  diagnostics["window_factors"] = sh.window.factors;
}

}  // namespace shpack::io
