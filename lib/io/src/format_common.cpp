#include "format_common.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cctype>
#include <charconv>
#include <filesystem>

#include "shpack/io/json_writer.h"

namespace shpack::io::detail {
namespace {

std::string float_text(float value, std::chars_format format, int precision) {
  std::array<char, 32> buffer;
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, format, precision);
  return error == std::errc() ? std::string(buffer.data(), end) : std::string("nan");  // 32 chars always fit
}

// A file name may hold any byte but '/' and NUL; a line break would end the comment.
std::string one_line(const std::string& text) {
  std::string out = text;
  for (char& ch : out)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ch = '?';
  return out;
}

}  // namespace

std::string float_scientific(float value) { return float_text(value, std::chars_format::scientific, 8); }

std::string float_general(float value) { return float_text(value, std::chars_format::general, 9); }

std::vector<std::string> provenance_lines(const ShDocument& doc) {
  // The options as the JSON document states them, so every form names them the same way.
  const nlohmann::ordered_json json = nlohmann::ordered_json::parse(to_json(doc));
  std::string files, digests;
  for (std::size_t i = 0; i < doc.source.files.size(); ++i) {
    files += (i ? ", " : "") + doc.source.files[i];
    if (i < doc.source.sha256.size()) digests += (i ? ", " : "") + doc.source.sha256[i];
  }
  std::vector<std::string> lines = {
      json["generator"].get<std::string>(),
      "input: " + one_line(files) + " (sha256 " + digests + ")",
      "options: " + json["options"].dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace),
      "frame: " + json["frame"].get<std::string>() + "; values are linear"};
  if (doc.l1) lines.push_back("L1 only (--l1): band 2 (coefficients 4..8) removed, for Light Probe Proxy Volumes");
  if (doc.sun_extraction) {  // the sun's light is in the JSON document only (light_extraction.h)
    lines.push_back(doc.sun ? "sun removed (--extract-sun): " + json["sun"]["direction"].dump() +
                                  " towards it; its Unity directional light is in the JSON form"
                            : "--extract-sun: no sun found, the map is whole");
  }
  if (doc.light_extraction > 0) {  // the lights are in the JSON document only (light_choice.h)
    std::string line = "lights removed (--extract-lights ";
    line.append(std::to_string(doc.light_extraction)).append("): ").append(std::to_string(doc.lights.size()));
    line.append(" of ").append(std::to_string(doc.light_candidates));
    lines.push_back(line.append(" candidates; their Unity directional lights are in the JSON form"));
  }
  return lines;
}

std::vector<std::string> stem_words(const ShDocument& doc) {
  std::vector<std::string> words;
  const std::string stem =
      doc.source.files.empty() ? std::string() : std::filesystem::path(doc.source.files[0]).stem().string();
  std::string word;
  for (const char ch : stem + ' ') {
    if (std::isalnum(static_cast<unsigned char>(ch)) && static_cast<unsigned char>(ch) < 0x80) {
      word += ch;
    } else if (!word.empty()) {
      words.push_back(word);
      word.clear();
    }
  }
  if (words.empty()) words.push_back("probe");
  return words;
}

}  // namespace shpack::io::detail
