#include <string>

#include "format_common.h"
#include "shpack/io/output_format.h"
#include "shpack/unity_pack.h"

namespace shpack::io {

// Unity serialises a SphericalHarmonicsL2 as 27 fields named "sh[ 0]" .. "sh[26]" (the index
// right-aligned in two characters), channel-major: sh[9c + i] = sh[c, i]. The names are
// those of Unity's type tree, as read by asset tools: AssetRipper's SphericalHarmonicsL2
// exporter (Sh0Name = "sh[ 0]", ..., Sh10Name = "sh[10]"), the SerializedProperty paths
// FindPropertyRelative("sh[ 0]") of editor scripts that edit LightingDataAsset, and
// RenderSettings' m_AmbientProbe read with sh[ 0], sh[ 9], sh[18] as the R, G, B L0 terms.
// Such fields appear under m_AmbientProbe (RenderSettings), m_BakedAmbientProbeInLinear
// (LightingDataAsset) and as the elements of m_BakedCoefficients (LightProbes). The values
// are written as Unity writes floats in YAML, with up to 9 significant digits.
std::string to_unity_yaml(const ShDocument& doc) {
  std::string out;
  for (const std::string& line : detail::provenance_lines(doc)) out += "# " + line + "\n";
  out +=
      "# A UnityEngine.Rendering.SphericalHarmonicsL2 as Unity serialises it: sh[9c + i] = sh[c, i]\n"
      "# (c = 0 red, 1 green, 2 blue). Paste these lines, indented, under m_AmbientProbe\n"
      "# (RenderSettings) or m_BakedAmbientProbeInLinear (LightingData.asset), or as one element\n"
      "# \"- sh[ 0]: ...\" of a LightProbes asset's m_BakedCoefficients.\n";
  const UnitySphericalHarmonicsL2& sh = doc.sh.unity_sh;
  for (int c = 0; c < kChannelCount; ++c) {
    for (int i = 0; i < kShCount; ++i) {
      const int flat = kShCount * c + i;
      out += std::string("sh[") + (flat < 10 ? " " : "") + std::to_string(flat) + "]: " +
             detail::float_general(sh[c][i]) + "\n";
    }
  }
  return out;
}

}  // namespace shpack::io
