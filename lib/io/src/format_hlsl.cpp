#include <cctype>
#include <string>

#include "format_common.h"
#include "shpack/io/sh_record_json.h"
#include "shpack/io/output_format.h"
#include "shpack/unity_pack.h"

namespace shpack::io {

// Seven `static const float4` named after the input (shpack_courtyard_SHAr, ...), holding the
// values of Unity's unity_SHAr..unity_SHC (the JSON document's "shader", bit for bit), and
// shpack_courtyard_ShadeSH9(n): the arithmetic of UnityCG.cginc's SHEvalLinearL0L1 +
// SHEvalLinearL2 on them. Unity's own names are not reused: UnityShaderVariables.cginc
// declares those as shader constants, and a second definition would not compile.
std::string to_hlsl(const ShDocument& doc) {
  std::string prefix = "shpack", guard = "SHPACK";
  for (const std::string& word : detail::stem_words(doc)) {
    prefix += "_";
    guard += "_";
    for (const char ch : word) {
      prefix += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      guard += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    }
  }
  guard += "_HLSL_INCLUDED";
  const auto name = [&](const char* unity_key) {  // "unity_SHAr" -> "shpack_courtyard_SHAr"
    return prefix + (unity_key + 5);
  };

  std::string out;
  for (const std::string& line : detail::provenance_lines(doc)) out += "// " + line + "\n";
  out +=
      "// The values of Unity's SH shader constants unity_SHAr..unity_SHC (UnityCG.cginc), and\n"
      "// " + prefix + "_ShadeSH9(n) = SHEvalLinearL0L1 + SHEvalLinearL2 on them = E(n)/pi for a\n"
      "// unit world-space normal n.\n"
      "#ifndef " + guard + "\n"
      "#define " + guard + "\n\n";
  const UnityShaderVectors& vectors = doc.sh.shader;
  for (const auto& [key, member] : kShaderVectorKeys) {
    const UnityShaderVectors::Float4& v = vectors.*member;
    out += "static const float4 " + name(key) + " = float4(";
    for (int k = 0; k < 4; ++k) out += detail::float_scientific(v[k]) + (k < 3 ? "f, " : "f);\n");
  }
  const std::string a = prefix + "_SHA", b = prefix + "_SHB";
  out +=
      "\n"
      "float3 " + prefix + "_ShadeSH9(float3 n)\n"
      "{\n"
      "    float4 n1 = float4(n, 1.0f);\n"
      "    float3 l0l1 = float3(dot(" + a + "r, n1), dot(" + a + "g, n1), dot(" + a + "b, n1));\n"
      "    float4 q = n.xyzz * n.yzzx;\n"
      "    float3 l2 = float3(dot(" + b + "r, q), dot(" + b + "g, q), dot(" + b + "b, q));\n"
      "    l2 += " + prefix + "_SHC.rgb * (n.x * n.x - n.y * n.y);\n"
      "    return l0l1 + l2;\n"
      "}\n\n"
      "#endif  // " + guard + "\n";
  return out;
}

}  // namespace shpack::io
