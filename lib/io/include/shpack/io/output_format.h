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
//  - OutputFormat::ThreeJs (format_threejs.cpp): the JSON of three.js's Object3D.toJSON for
//    a LightProbe, which ObjectLoader.parse reads as it is (as older releases'
//    LightProbe.fromJSON read its "object"): "sh", the 27 floats of SphericalHarmonics3.toArray (coefficient-major,
//    radiance of the orthonormal basis) in three.js's frame (engine_frame.h).
//  - OutputFormat::Filament (format_filament.cpp): the 9 lines cmgen --sh-shader writes, the
//    pre-scaled irradiance Filament's shader sums with the plain polynomials (E/pi), in the
//    frame of cmgen's default mirrored output.
//  - OutputFormat::Gltf (format_gltf.cpp): a glTF 2.0 document with one EXT_lights_image_based
//    light (irradianceCoefficients, rotation, intensity) in glTF's frame, referenced by its
//    scene; it has no specular cube map (docs/formats.md says what that means for loaders).
// Each starts with comments naming the generator, the input and the options (the JSON forms
// carry them in a field their readers keep: three.js's userData, glTF's extras).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "shpack/document.h"

namespace shpack::io {

enum class OutputFormat : std::uint8_t { Json, CSharp, Hlsl, UnityYaml, ThreeJs, Filament, Gltf };

// "json", "csharp", "hlsl", "unity-yaml", "threejs", "filament", "gltf": the names of --format.
const char* format_name(OutputFormat format) noexcept;

// ".json", ".cs", ".hlsl", ".yaml", ".json", ".txt", ".gltf": the extension of
// `convert --out-dir` outputs, and one that `-o` may have with that format.
const char* format_extension(OutputFormat format) noexcept;

// The format an output file's extension names (".json" json, ".cs" csharp, ".hlsl" hlsl,
// ".yaml" unity-yaml, ".gltf" gltf; case-sensitive), or nullopt for any other extension.
// threejs and filament files (.json, .txt) need --format: their extensions name another
// format or none.
std::optional<OutputFormat> format_of_extension(const std::string& extension) noexcept;

std::string to_csharp(const ShDocument& doc);
std::string to_hlsl(const ShDocument& doc);
std::string to_unity_yaml(const ShDocument& doc);
std::string to_threejs(const ShDocument& doc);
std::string to_filament(const ShDocument& doc);
std::string to_gltf(const ShDocument& doc);

// The document in `format` (to_json for OutputFormat::Json).
std::string format_document(const ShDocument& doc, OutputFormat format);

}  // namespace shpack::io
