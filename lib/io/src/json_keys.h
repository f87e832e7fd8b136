// json_keys.h (private) - the names shared by the JSON writer and reader.
#pragma once

#include <array>
#include <utility>

#include "shpack/unity_pack.h"

namespace shpack::io::detail {

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

}  // namespace shpack::io::detail
