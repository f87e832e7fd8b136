#include "shpack/bake/lightmap_output.h"

#include <nlohmann/json.hpp>

#include <algorithm>

#include "shpack/convolution.h"
#include "shpack/io/version.h"
#include "shpack/unity_pack.h"

namespace shpack::bake {
namespace {

using OrderedJson = nlohmann::ordered_json;
using Member = UnityShaderVectors::Float4 UnityShaderVectors::*;

struct Group {
  const char* name;
  Member member;
  int channels;
};
constexpr Group kL1Groups[] = {{"SHAr", &UnityShaderVectors::SHAr, 4},
                               {"SHAg", &UnityShaderVectors::SHAg, 4},
                               {"SHAb", &UnityShaderVectors::SHAb, 4}};
constexpr Group kL2Groups[] = {{"SHBr", &UnityShaderVectors::SHBr, 4},
                               {"SHBg", &UnityShaderVectors::SHBg, 4},
                               {"SHBb", &UnityShaderVectors::SHBb, 4},
                               {"SHC", &UnityShaderVectors::SHC, 3}};

std::vector<std::string> channel_names(int n) {
  std::vector<std::string> names{"R", "G", "B", "A"};
  names.resize(static_cast<std::size_t>(n));
  return names;
}

std::vector<const Group*> groups_of(bool l2) {
  std::vector<const Group*> out;
  for (const Group& g : kL1Groups) out.push_back(&g);
  if (l2)
    for (const Group& g : kL2Groups) out.push_back(&g);
  return out;
}

// The p-th quantile (nearest rank) of the baked texels' error estimates.
double quantile(std::vector<float> v, double p) {
  if (v.empty()) return 0;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

}  // namespace

bool lightmap_images(const scene::LightmapTarget& target, const LightmapTexels& map,
                     std::vector<LightmapImage>& out, std::string& error) {
  const std::vector<const Group*> groups = groups_of(target.l2);
  const std::size_t texels = static_cast<std::size_t>(map.width) * map.height;
  out.clear();
  for (const Group* g : groups)
    out.push_back({g->name, channel_names(g->channels), std::vector<float>(texels * g->channels, 0.0f)});
  for (std::size_t t = 0; t < texels; ++t) {
    if (map.state[t] == TexelState::Unused) continue;
    ShL2 unity_form = radiance_to_unity_form(map.radiance[t]);
    if (!target.l2)  // L1: band 2 is not stored, so SHAr.w holds L0 alone (no L2 constant folded in)
      for (auto& channel : unity_form.c)
        for (int i = 4; i < kShCount; ++i) channel[i] = 0;
    if (!fits_unity_float32(unity_form)) {
      error = target.label + "'s lightmap texel (" + std::to_string(t % map.width) + ", " +
              std::to_string(t / map.width) + ") is too bright for float32 coefficients";
      return false;
    }
    const UnityShaderVectors v = to_shader_vectors(unity_form);
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const int n = groups[g]->channels;
      for (int c = 0; c < n; ++c) out[g].pixels[t * n + c] = (v.*(groups[g]->member))[c];
    }
  }
  LightmapImage texel_image{"texels", channel_names(4), std::vector<float>(texels * 4, 0.0f)};
  for (std::size_t t = 0; t < texels; ++t) {
    texel_image.pixels[4 * t] = map.coverage[t];
    texel_image.pixels[4 * t + 1] = static_cast<float>(map.state[t]);
    texel_image.pixels[4 * t + 2] = map.error_pct[t];
    texel_image.pixels[4 * t + 3] = map.backface[t];
  }
  out.push_back(std::move(texel_image));
  return true;
}

std::string lightmap_hlsl() {
  return
      "// ShpackLightmap.hlsl - E(n)/pi at a texel of a shpack SH lightmap, for a unit world-space\n"
      "// normal n (Unity's frame). Each texture holds, per texel, one of Unity's SH shader vectors\n"
      "// (unity_SHAr, ...): they are sampled with bilinear filtering at the lightmap UV (uv2 in\n"
      "// Unity) and evaluated as UnityCG.cginc's SHEvalLinearL0L1 (+ SHEvalLinearL2) does for a\n"
      "// probe. For an L2 lightmap, #define SHPACK_LIGHTMAP_L2 1 before including this file.\n"
      "#ifndef SHPACK_LIGHTMAP_INCLUDED\n"
      "#define SHPACK_LIGHTMAP_INCLUDED\n"
      "\n"
      "Texture2D<float4> _ShpackSHAr, _ShpackSHAg, _ShpackSHAb;\n"
      "#if SHPACK_LIGHTMAP_L2\n"
      "Texture2D<float4> _ShpackSHBr, _ShpackSHBg, _ShpackSHBb, _ShpackSHC;\n"
      "#endif\n"
      "SamplerState sampler_linear_clamp;\n"
      "\n"
      "float3 ShpackLightmapSH(float2 lightmapUV, float3 n)\n"
      "{\n"
      "    float4 n1 = float4(n, 1.0f);\n"
      "    float4 ar = _ShpackSHAr.SampleLevel(sampler_linear_clamp, lightmapUV, 0);\n"
      "    float4 ag = _ShpackSHAg.SampleLevel(sampler_linear_clamp, lightmapUV, 0);\n"
      "    float4 ab = _ShpackSHAb.SampleLevel(sampler_linear_clamp, lightmapUV, 0);\n"
      "    float3 e = float3(dot(ar, n1), dot(ag, n1), dot(ab, n1));\n"
      "#if SHPACK_LIGHTMAP_L2\n"
      "    float4 q = n.xyzz * n.yzzx;\n"
      "    e += float3(dot(_ShpackSHBr.SampleLevel(sampler_linear_clamp, lightmapUV, 0), q),\n"
      "                dot(_ShpackSHBg.SampleLevel(sampler_linear_clamp, lightmapUV, 0), q),\n"
      "                dot(_ShpackSHBb.SampleLevel(sampler_linear_clamp, lightmapUV, 0), q));\n"
      "    e += _ShpackSHC.SampleLevel(sampler_linear_clamp, lightmapUV, 0).rgb * (n.x * n.x - n.y * n.y);\n"
      "#endif\n"
      "    return e;  // E(n)/pi: times the albedo, the diffuse light\n"
      "}\n"
      "\n"
      "#endif  // SHPACK_LIGHTMAP_INCLUDED\n";
}

std::string lightmap_sidecar(const scene::Scene& scene, const scene::LightmapTarget& target,
                             const LightmapTexels& map, const LightmapBakeResult& result) {
  OrderedJson j;
  j["schema_version"] = 1;
  j["generator"] = std::string("shpack ") + io::shpack_version();
  j["kind"] = "shpack-sh-lightmap";
  j["scene"] = {{"file", scene.file.filename().string()}, {"sha256", scene.sha256}, {"seed", scene.settings.seed}};
  j["name"] = target.name;
  j["shape"] = target.label;
  j["width"] = map.width;
  j["height"] = map.height;
  j["bands"] = target.l2 ? "L2" : "L1";
  j["frame"] = "world: Unity's, left-handed, +Y up, +Z forward";
  j["basis"] = "real SH, the probes' (docs/conventions.md), per channel of linear Rec. 709 RGB";
  j["normalisation"] =
      "each texel is a probe's unity_SH vectors for the radiance arriving over the hemisphere about the surface "
      "(zero below it): dot(SHA, (n, 1)) [+ the L2 terms] = E(n)/pi, the irradiance over pi";
  j["uv"] = "the lightmap UV set (glTF TEXCOORD_1, OBJ vt, a plane's own), (0, 0) at the image's bottom left; "
            "row 0 of each image is its top";
  OrderedJson files = OrderedJson::object();
  for (const char* g : {"SHAr", "SHAg", "SHAb"}) files[g] = target.name + "." + std::string(g) + ".exr";
  if (target.l2)
    for (const char* g : {"SHBr", "SHBg", "SHBb", "SHC"}) files[g] = target.name + "." + std::string(g) + ".exr";
  files["texels"] = target.name + ".texels.exr";
  j["files"] = files;
  j["texels_channels"] = {{"R", "the share of the texel its chart covers"},
                          {"G", "state: 0 unused, 1 baked, 2 dilated, 3 padding"},
                          {"B", "error estimate, % of the texel's mean E/pi (about 95 % confidence)"},
                          {"A", "backface fraction of its points"}};
  std::vector<float> errors;
  for (std::size_t t = 0; t < map.state.size(); ++t)
    if (map.state[t] == TexelState::Baked) errors.push_back(map.error_pct[t]);
  j["texels"] = {{"used", map.used},       {"dilated", map.dilated},   {"padding", map.padded},
                 {"invalid_kept", map.invalid_kept}, {"points", map.points}, {"degenerate_triangles", map.degenerate},
                 {"shared_by_charts", map.shared}};
  j["error_estimate_pct"] = {{"max", quantile(errors, 1.0)}, {"p99", quantile(errors, 0.99)},
                             {"p95", quantile(errors, 0.95)}, {"median", quantile(errors, 0.5)},
                             {"target", scene.settings.target_error_pct}};
  j["time_ms"] = result.time_ms;
  j["hlsl_defines"] = target.l2 ? "#define SHPACK_LIGHTMAP_L2 1" : "";
  j["hlsl"] = lightmap_hlsl();
  return j.dump(2) + "\n";
}

}  // namespace shpack::bake
