#include <array>
#include <cstdio>
#include <string>

#include "format_common.h"
#include "shpack/engine_frame.h"
#include "shpack/io/output_format.h"

namespace shpack::io {

// cmgen --sh-shader's sh.txt (filament tools/cmgen, CubemapSH::preprocessSHForShader): 9
// lines "(r, g, b); // L00, irradiance, pre-scaled base", each value the irradiance
// coefficient times Filament's signed basis constant A_i and 1/pi, so that the shader's
// plain polynomial sum sh0 + sh1 y + sh2 z + sh3 x + ... + sh8 (x^2 - y^2) is E/pi. The
// signs of A_i cancel Filament's Condon-Shortley phase: the values are Unity-form
// coefficients (unity_form) in Filament's frame. Printed as cmgen prints them ("% .15f"
// of the float): fixed 15 decimals, so values below 5e-16 read back as 0.
std::string to_filament(const ShDocument& doc) {
  constexpr std::array<const char*, kShCount> kNames = {"00", "1-1", "10", "11", "2-2", "2-1", "20", "21", "22"};
  const ShL2 sh = unity_form_to_engine_frame(EngineFrame::Filament, doc.sh.unity_form);
  std::string out;
  for (const std::string& line : detail::provenance_lines(doc)) out += "// " + line + "\n";
  out += std::string("// Filament IndirectLight::Builder::irradiance(3, sh): E/pi per channel, ") +
         engine_frame_spec(EngineFrame::Filament).description + "\n";
  for (int i = 0; i < kShCount; ++i) {
    std::array<char, 128> line;
    std::snprintf(line.data(), line.size(), "(% .15f, % .15f, % .15f); // L%s, irradiance, pre-scaled base\n",
                  static_cast<double>(static_cast<float>(sh.c[0][i])),
                  static_cast<double>(static_cast<float>(sh.c[1][i])),
                  static_cast<double>(static_cast<float>(sh.c[2][i])), kNames[i]);
    out += line.data();
  }
  return out;
}

}  // namespace shpack::io
