// json_reader.h - the coefficients of an output document, read back (shpack eval, preview).
//
// Only the keys a consumer of the numbers needs are read and checked: schema_version,
// radiance_sh, sphericalHarmonicsL2 and shader (of the document, or of one probe of a bake
// document), and if present options.intensity and options.rotate_deg, the Unity lights of
// "sun" and "lights", and source.sha256. Errors name the file and the JSON pointer
// of the offending value ("out.json: /shader/unity_SHAr/3: expected a number").
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shpack/io/io_status.h"
#include "shpack/sh_basis.h"
#include "shpack/unity_light.h"
#include "shpack/unity_pack.h"

namespace shpack::io {

struct ShJsonContent {
  ShL2 radiance;                        // radiance_sh
  UnitySphericalHarmonicsL2 unity_sh;   // sphericalHarmonicsL2
  UnityShaderVectors shader;            // shader
  // options.intensity and options.rotate_deg when present (else 1 and 0): how the radiance
  // was scaled and turned, so a brute-force reference (shpack preview --input) can match.
  double intensity = 1.0;
  double rotate_deg = 0.0;
  // The directional lights Unity adds (--extract-sun's sun, --extract-lights' lights): what
  // Unity shows is shade_sh9 plus colour * intensity * max(0, n . -forward) of each.
  std::vector<UnitySunLight> lights;
  std::vector<std::string> sha256;  // source.sha256: the digests of the files it came from
};

// `probe`: the probe of a bake document (bake_json.h) whose coefficients to read; a bake
// document without one, or one given for a convert document, is BadDocument.
IoStatus read_sh_json(const std::filesystem::path& path, ShJsonContent& out,
                      std::optional<std::size_t> probe = std::nullopt);

}  // namespace shpack::io
