// scene_validate.h (private) - a scene document against docs/scene.schema.json (valijson).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace shpack::scene::detail {

// True if `doc` satisfies the built-in schema. Otherwise false, with the JSON path of the most
// specific error ("lights[2].radius", "(root)") and the problem in shpack's words
// ("must be > 0", "unknown key 'radious'").
bool validate_scene_json(const nlohmann::json& doc, std::string& path, std::string& problem);

}  // namespace shpack::scene::detail
