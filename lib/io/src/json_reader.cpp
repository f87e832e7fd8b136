#include "shpack/io/json_reader.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shpack/io/file_checks.h"
#include "shpack/io/sh_record_json.h"

namespace shpack::io {
namespace {

using Json = nlohmann::json;

// A value that is not what the format says; thrown inside this file only.
struct BadValue {
  std::string pointer, problem;
};

const Json& member(const Json& object, const std::string& pointer, const char* key) {
  if (!object.is_object()) throw BadValue{pointer.empty() ? "/" : pointer, "expected an object"};
  const auto it = object.find(key);
  if (it == object.end()) throw BadValue{pointer.empty() ? "/" : pointer, std::string("missing key \"") + key + "\""};
  return *it;
}

double number(const Json& value, const std::string& pointer) {
  if (!value.is_number()) throw BadValue{pointer, "expected a number"};
  const double v = value.get<double>();
  if (!std::isfinite(v)) throw BadValue{pointer, "expected a finite number"};
  return v;
}

float float32(const Json& value, const std::string& pointer) {
  const auto v = static_cast<float>(number(value, pointer));
  if (!std::isfinite(v)) throw BadValue{pointer, "out of float32 range"};
  return v;
}

// An array of exactly N elements, each read by `read(element, pointer)`.
template <std::size_t N, class Read>
auto elements(const Json& value, const std::string& pointer, Read read) {
  if (!value.is_array() || value.size() != N)
    throw BadValue{pointer, "expected an array of " + std::to_string(N) + " elements"};
  std::array<decltype(read(value[0], pointer)), N> out;
  for (std::size_t i = 0; i < N; ++i) out[i] = read(value[i], pointer + "/" + std::to_string(i));
  return out;
}

// radiance_sh, sphericalHarmonicsL2 and shader of `record` (pointer `at`).
void read_coefficients(const Json& record, const std::string& at, ShJsonContent& out) {
  const auto doubles = [](const Json& v, const std::string& p) { return elements<kShCount>(v, p, number); };
  const auto floats = [](const Json& v, const std::string& p) { return elements<kShCount>(v, p, float32); };
  out.radiance.c = elements<kChannelCount>(member(record, at, "radiance_sh"), at + "/radiance_sh", doubles);
  out.unity_sh =
      elements<kChannelCount>(member(record, at, "sphericalHarmonicsL2"), at + "/sphericalHarmonicsL2", floats);
  const Json& shader = member(record, at, "shader");
  for (const auto& [key, vector] : kShaderVectorKeys) {
    const std::string pointer = at + "/shader/" + key;
    out.shader.*vector = elements<4>(member(shader, at + "/shader", key), pointer, float32);
  }
}

// The Unity light of a "sun" or "lights" record (docs/json-format.md) at `at`.
UnitySunLight light_of(const Json& record, const std::string& at) {
  const std::string u = at + "/unity_light";
  const Json& unity = member(record, at, "unity_light");
  UnitySunLight light;
  const std::array<double, 3> forward = elements<3>(member(unity, u, "forward"), u + "/forward", number);
  light.forward = {forward[0], forward[1], forward[2]};
  light.colour = elements<3>(member(unity, u, "color"), u + "/color", number);
  light.intensity = number(member(unity, u, "intensity"), u + "/intensity");
  return light;
}

// Every light Unity adds to the SH: the sun (unless null) and the lights.
void read_lights(const Json& doc, std::vector<UnitySunLight>& lights) {
  if (const auto sun = doc.find("sun"); sun != doc.end() && !sun->is_null()) lights.push_back(light_of(*sun, "/sun"));
  if (const auto list = doc.find("lights"); list != doc.end()) {
    if (!list->is_array()) throw BadValue{"/lights", "expected an array"};
    for (std::size_t k = 0; k < list->size(); ++k) lights.push_back(light_of((*list)[k], "/lights/" + std::to_string(k)));
  }
}

ShJsonContent content_of(const Json& doc, std::optional<std::size_t> probe) {
  const Json& version = member(doc, "", "schema_version");
  if (!version.is_number_integer() || version.get<std::int64_t>() != kSchemaVersion) {
    // A primitive is quoted (cut short), a structure named: a nested one is never dumped.
    std::string shown = version.is_primitive() ? version.dump() : std::string(version.type_name());
    if (shown.size() > 40) shown = shown.substr(0, 40) + "...";
    throw BadValue{"/schema_version", "unsupported schema version " + shown +
                                          " (this shpack reads " +
                                          std::to_string(kSchemaVersion) + ")"};
  }
  ShJsonContent out;
  const auto probes = doc.find("probes");
  const bool bake = probes != doc.end() && probes->is_array();
  if (bake && !probe)
    throw BadValue{"/probes", "a bake document of " + std::to_string(probes->size()) +
                                  " probes: choose one (preview --probe N)"};
  if (!bake && probe) throw BadValue{"/", "not a bake document: it has no probes to choose from"};
  if (bake && *probe >= probes->size())
    throw BadValue{"/probes", "no probe " + std::to_string(*probe) + " (it has " + std::to_string(probes->size()) + ")"};
  // The coefficients: the document's, or the chosen probe's (bake_json.h: the same keys).
  const std::string at = bake ? "/probes/" + std::to_string(*probe) : "";
  const Json& record = bake ? (*probes)[*probe] : doc;
  read_coefficients(record, at, out);
  if (const auto options = doc.find("options"); options != doc.end() && options->is_object()) {
    if (options->contains("intensity")) out.intensity = number((*options)["intensity"], "/options/intensity");
    if (options->contains("rotate_deg")) out.rotate_deg = number((*options)["rotate_deg"], "/options/rotate_deg");
  }
  read_lights(doc, out.lights);
  if (const auto source = doc.find("source"); source != doc.end() && source->is_object()) {
    if (const auto digests = source->find("sha256"); digests != source->end() && digests->is_array())
      for (const Json& d : *digests)
        if (d.is_string()) out.sha256.push_back(d.get<std::string>());
  }
  return out;
}

// nlohmann's messages start with "[json.exception.parse_error.101] "; the rest is the news.
std::string parse_problem(const Json::parse_error& e) {
  const std::string what = e.what();
  const std::size_t end = what.find("] ");
  return end == std::string::npos ? what : what.substr(end + 2);
}

}  // namespace

IoStatus read_sh_json(const std::filesystem::path& path, ShJsonContent& out, std::optional<std::size_t> probe) {
  try {
    // One checked read: a regular file (or this process's stdin pipe) of at most
    // kMaxDocumentBytes; devices, FIFOs and larger files are refused before reading.
    std::string text;
    if (IoStatus st = detail::read_text_file(path, detail::kMaxDocumentBytes, text); !st.ok()) return st;
    out = content_of(Json::parse(text), probe);
    return IoStatus::success();
  } catch (const Json::parse_error& e) {
    return IoStatus::error(IoErrc::Unreadable, path, "not valid JSON: " + parse_problem(e));
  } catch (const BadValue& bad) {
    return IoStatus::error(IoErrc::BadDocument, path, bad.pointer + ": " + bad.problem);
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Unreadable, path, e.what());
  }
}

}  // namespace shpack::io
