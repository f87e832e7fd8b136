#include <cctype>
#include <string>

#include "format_common.h"
#include "shpack/io/output_format.h"
#include "shpack/unity_pack.h"

namespace shpack::io {

// A class named after the input ("ShpackCourtyard") with a method Probe() that builds the
// SphericalHarmonicsL2 through its indexer, sh[channel, coefficient] (UnityCsReference,
// Runtime/Export/Math/SphericalHarmonicsL2.bindings.cs): the 27 floats of the JSON
// document's sphericalHarmonicsL2, bit for bit.
std::string to_csharp(const ShDocument& doc) {
  std::string name = "Shpack";
  for (std::string word : detail::stem_words(doc)) {
    word[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(word[0])));
    name += word;
  }
  std::string out;
  for (const std::string& line : detail::provenance_lines(doc)) out += "// " + line + "\n";
  out +=
      "// Unity's SphericalHarmonicsL2: for a unit normal n, sum_i sh[c, i] P_i(n) = E_c(n)/pi\n"
      "// (docs/json-format.md). For example, in the Editor or at run time:\n"
      "//   RenderSettings.ambientMode = UnityEngine.Rendering.AmbientMode.Custom;\n"
      "//   RenderSettings.ambientProbe = " + name + ".Probe();\n"
      "public static class " + name + "\n"
      "{\n"
      "    public static UnityEngine.Rendering.SphericalHarmonicsL2 Probe()\n"
      "    {\n"
      "        var sh = new UnityEngine.Rendering.SphericalHarmonicsL2();\n";
  const UnitySphericalHarmonicsL2& sh = doc.sh.unity_sh;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i)
      out += "        sh[" + std::to_string(c) + ", " + std::to_string(i) + "] = " +
             detail::float_scientific(sh[c][i]) + "f;\n";
  out +=
      "        return sh;\n"
      "    }\n"
      "}\n";
  return out;
}

}  // namespace shpack::io
