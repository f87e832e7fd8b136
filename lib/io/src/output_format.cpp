#include "shpack/io/output_format.h"

#include <array>

#include "shpack/io/json_writer.h"

namespace shpack::io {

const char* format_name(OutputFormat format) noexcept {
  switch (format) {
    case OutputFormat::Json: return "json";
    case OutputFormat::CSharp: return "csharp";
    case OutputFormat::Hlsl: return "hlsl";
    case OutputFormat::UnityYaml: return "unity-yaml";
    case OutputFormat::ThreeJs: return "threejs";
    case OutputFormat::Filament: return "filament";
    case OutputFormat::Gltf: return "gltf";
  }
  return "unknown";
}

const char* format_extension(OutputFormat format) noexcept {
  switch (format) {
    case OutputFormat::Json: return ".json";
    case OutputFormat::CSharp: return ".cs";
    case OutputFormat::Hlsl: return ".hlsl";
    case OutputFormat::UnityYaml: return ".yaml";
    case OutputFormat::ThreeJs: return ".json";
    case OutputFormat::Filament: return ".txt";  // cmgen's name: sh.txt
    case OutputFormat::Gltf: return ".gltf";
  }
  return "";
}

std::optional<OutputFormat> format_of_extension(const std::string& extension) noexcept {
  constexpr std::array<OutputFormat, 5> kNamedByExtension = {OutputFormat::Json, OutputFormat::CSharp, OutputFormat::Hlsl,
                                                             OutputFormat::UnityYaml, OutputFormat::Gltf};
  for (const OutputFormat format : kNamedByExtension)
    if (extension == format_extension(format)) return format;
  return std::nullopt;
}

std::string format_document(const ShDocument& doc, OutputFormat format) {
  switch (format) {
    case OutputFormat::Json: return to_json(doc);
    case OutputFormat::CSharp: return to_csharp(doc);
    case OutputFormat::Hlsl: return to_hlsl(doc);
    case OutputFormat::UnityYaml: return to_unity_yaml(doc);
    case OutputFormat::ThreeJs: return to_threejs(doc);
    case OutputFormat::Filament: return to_filament(doc);
    case OutputFormat::Gltf: return to_gltf(doc);
  }
  return to_json(doc);
}

}  // namespace shpack::io
