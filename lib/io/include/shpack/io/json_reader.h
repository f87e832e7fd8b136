// json_reader.h - the coefficients of an output document, read back (shpack eval, preview).
//
// Only the keys a consumer of the numbers needs are read and checked: schema_version,
// radiance_sh, sphericalHarmonicsL2 and shader, and options.intensity and options.rotate_deg
// if present. Errors name the file and the JSON pointer
// of the offending value ("out.json: /shader/unity_SHAr/3: expected a number").
#pragma once

#include <filesystem>

#include "shpack/io/io_status.h"
#include "shpack/sh_basis.h"
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
};

IoStatus read_sh_json(const std::filesystem::path& path, ShJsonContent& out);

}  // namespace shpack::io
