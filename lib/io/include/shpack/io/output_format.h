// output_format.h - the forms an output document can take besides JSON (`convert --format`).
//
// Every form carries the same float32 numbers as the JSON document (json_writer.h), each
// written so that it reads back to the same bits (format_common.h says why 9 significant
// digits are enough even for a parser that goes through double):
//
//  - OutputFormat::CSharp (format_csharp.cpp): a C# file with one static class whose method
//    returns the UnityEngine.Rendering.SphericalHarmonicsL2, as 27 `sh[c, i] = ...f;`
//    assignments (the indexer of UnityCsReference's SphericalHarmonicsL2.bindings.cs).
//  - OutputFormat::Hlsl (format_hlsl.cpp): an HLSL include defining the seven float4 shader
//    vectors (the values of unity_SHAr..unity_SHC) and a function that evaluates them as
//    UnityCG.cginc's SHEvalLinearL0L1 + SHEvalLinearL2 do.
//  - OutputFormat::UnityYaml (format_unity_yaml.cpp): the 27 lines `sh[ 0]: ...`..`sh[26]: ...`
//    of a SphericalHarmonicsL2 as Unity serialises it in its YAML assets.
// Each starts with comments naming the generator, the input and the options.
#pragma once

#include <cstdint>
#include <string>

#include "shpack/document.h"

namespace shpack::io {

enum class OutputFormat : std::uint8_t { Json, CSharp, Hlsl, UnityYaml };

// "json", "csharp", "hlsl", "unity-yaml": the names of --format.
const char* format_name(OutputFormat format) noexcept;

// ".json", ".cs", ".hlsl", ".yaml": the extension of `convert --out-dir` outputs.
const char* format_extension(OutputFormat format) noexcept;

std::string to_csharp(const ShDocument& doc);
std::string to_hlsl(const ShDocument& doc);
std::string to_unity_yaml(const ShDocument& doc);

// The document in `format` (to_json for OutputFormat::Json).
std::string format_document(const ShDocument& doc, OutputFormat format);

}  // namespace shpack::io
