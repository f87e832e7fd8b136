// The JSON Schema check of scene files, in its own translation unit because of two pragmas.
//
// GCC 12 at -O2 reports two false positives inside the standard library as valijson uses it,
// which -Werror would turn into build failures:
//  - -Wmaybe-uninitialized in libstdc++'s <regex> (std::function moved in
//    _NFA::_M_insert_subexpr_end), instantiated by valijson's "pattern" constraint;
//  - -Wrestrict in std::string::replace (GCC bug 105329), reached from valijson's
//    json_pointer::replaceAllInPlace.
// The pragmas come before every include so that they cover those headers; they apply to this
// file only, and nothing of shpack's own is in it but the error selection below.
#if defined(__GNUC__) && !defined(__clang__)  // clang has neither warning (the fuzz build)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

#include "scene_validate.h"

#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validator.hpp>

#include <string>
#include <utility>
#include <vector>

#include "generated/scene_schema.h"

namespace shpack::scene::detail {
namespace {

using Json = nlohmann::json;

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

// Parsed once (thread-safe static initialisation); valijson's Schema cannot be copied.
struct ParsedSchema {
  valijson::Schema schema;
  ParsedSchema() {
    const Json text = Json::parse(detail::kSceneSchemaText);
    valijson::SchemaParser parser(valijson::SchemaParser::kDraft7);
    parser.populateSchema(valijson::adapters::NlohmannJsonAdapter(text), schema);
  }
};

const valijson::Schema& scene_schema() {
  static const ParsedSchema parsed;
  return parsed.schema;
}

// valijson's context ["<root>", "[lights]", "[2]", "[radius]"] -> "lights[2].radius".
std::string json_path(const std::vector<std::string>& context) {
  std::string path;
  for (const std::string& part : context) {
    if (part.size() < 2 || part.front() != '[' || part.back() != ']') continue;  // "<root>"
    const std::string inner = part.substr(1, part.size() - 2);
    const bool is_index = !inner.empty() && inner.find_first_not_of("0123456789") == std::string::npos;
    path = is_index ? path + part : join(path, inner);
  }
  return path;
}

// "1.000000" -> "1", "0.500000" -> "0.5" (valijson prints limits with std::to_string).
std::string trim_number(std::string n) {
  if (n.find('.') == std::string::npos) return n;
  while (!n.empty() && n.back() == '0') n.pop_back();
  if (!n.empty() && n.back() == '.') n.pop_back();
  return n;
}

// The text between `open` and the next `close` after it in `message`, or "" (valijson quotes
// names as 'name').
std::string quoted_after(const std::string& message, const std::string& open, char close = '\'') {
  const std::size_t at = message.find(open);
  if (at == std::string::npos) return "";
  const std::size_t from = at + open.size(), to = message.find(close, from);
  return to == std::string::npos ? "" : message.substr(from, to - from);
}

// valijson's sentences -> the short form of our messages. (Plain string matching: <regex>
// trips GCC 12's -Wmaybe-uninitialized under -O2 and the sanitizers.)
std::string rephrase(const std::string& path, const std::string& message) {
  static const std::pair<const char*, const char*> kBounds[] = {
      {"Expected number greater than or equal to ", "must be >= "},
      {"Expected number greater than ", "must be > "},
      {"Expected number less than or equal to ", "must be <= "},
      {"Expected number less than ", "must be < "},
  };
  for (const auto& [prefix, text] : kBounds)
    if (message.rfind(prefix, 0) == 0) return text + trim_number(message.substr(std::string(prefix).size()));
  if (const std::string key = quoted_after(message, "Missing required property '"); !key.empty())
    return "missing '" + key + "'";
  if (const std::string key = quoted_after(message, "additionalProperties' constraints: '"); !key.empty())
    return "unknown key '" + key + "'";
  if (message.find("'type' constraint") != std::string::npos) return "has the wrong type";
  if (message.find("enum values") != std::string::npos || message.find("'const' constraint") != std::string::npos)
    return "is not one of the allowed values";
  if (message.find("'pattern' constraint") != std::string::npos && path.rfind("effects", 0) == 0)
    return "is not an effect (direct, environment, shadows, sky_occlusion, emission, bounce:N)";
  if (message.find("exactly one child schema") != std::string::npos || message.find("oneOf") != std::string::npos)
    return "needs exactly one of 'intensity' and 'power'";  // the schema's only oneOf
  if (message.find("unique") != std::string::npos) return "lists the same item twice";
  return message;
}

}  // namespace

bool validate_scene_json(const nlohmann::json& doc, std::string& path_out, std::string& problem) {
  valijson::Validator validator;
  valijson::ValidationResults results;
  if (validator.validate(scene_schema(), valijson::adapters::NlohmannJsonAdapter(doc), &results)) return true;
  // The deepest error is the specific one; the others are its enclosing "allOf", "items"
  // and "if-then" failures. Among equally deep ones, the first.
  valijson::ValidationResults::Error error, best;
  std::size_t best_depth = 0;
  bool have = false;
  const auto is_one_of = [](const std::string& d) { return d.find("oneOf") != std::string::npos ||
                                                           d.find("exactly one child schema") != std::string::npos; };
  while (results.popError(error)) {
    // At equal depth the "exactly one of" failure says more than its children's "missing".
    if (!have || error.context.size() > best_depth ||
        (error.context.size() == best_depth && is_one_of(error.description) && !is_one_of(best.description))) {
      best = error;
      best_depth = error.context.size();
      have = true;
    }
  }
  const std::string path = json_path(best.context);
  path_out = path.empty() ? "(root)" : path;
  problem = rephrase(path, best.description);
  return false;
}


}  // namespace shpack::scene::detail
