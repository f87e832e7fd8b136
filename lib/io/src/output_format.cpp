#include "shpack/io/output_format.h"

#include "shpack/io/json_writer.h"

namespace shpack::io {

const char* format_name(OutputFormat format) noexcept {
  switch (format) {
    case OutputFormat::Json: return "json";
    case OutputFormat::CSharp: return "csharp";
    case OutputFormat::Hlsl: return "hlsl";
    case OutputFormat::UnityYaml: return "unity-yaml";
  }
  return "unknown";
}

const char* format_extension(OutputFormat format) noexcept {
  switch (format) {
    case OutputFormat::Json: return ".json";
    case OutputFormat::CSharp: return ".cs";
    case OutputFormat::Hlsl: return ".hlsl";
    case OutputFormat::UnityYaml: return ".yaml";
  }
  return "";
}

std::string format_document(const ShDocument& doc, OutputFormat format) {
  switch (format) {
    case OutputFormat::Json: return to_json(doc);
    case OutputFormat::CSharp: return to_csharp(doc);
    case OutputFormat::Hlsl: return to_hlsl(doc);
    case OutputFormat::UnityYaml: return to_unity_yaml(doc);
  }
  return to_json(doc);
}

}  // namespace shpack::io
