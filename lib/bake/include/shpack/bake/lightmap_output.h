// lightmap_output.h - what `shpack bake` writes of a lightmap (docs/lightmaps.md, "Format"):
// float images, one per coefficient group, and the sidecar JSON that says how to read them.
//
// Per texel the radiance SH (Unity's frame, the probes' basis) is convolved to Unity form and
// packed exactly as a probe's shader vectors (unity_pack.h): image "SHAr" holds unity_SHAr's
// (x, y, z, w) as (R, G, B, A), and so on, so that a shader evaluates a texel with the
// probes' own SHEvalLinearL0L1 (+ SHEvalLinearL2 with "l2"), getting E(n)/pi. "texels" holds
// (coverage, state, error estimate %, backface fraction): state 0 is unused (no triangle
// covers it; its SH is 0, not a black measurement), 1 baked, 2 dilated, 3 padding.
#pragma once

#include <string>
#include <vector>

#include "shpack/bake/lightmap_bake.h"
#include "shpack/scene/scene.h"

namespace shpack::bake {

struct LightmapImage {
  std::string group;                  // "SHAr", ..., "texels": the file is <name>.<group>.exr
  std::vector<std::string> channels;  // "R", "G", "B"[, "A"]
  std::vector<float> pixels;          // interleaved, row 0 at the top
};

// The images of one lightmap. False, with `error` naming the texel, if a coefficient does not
// fit in float32.
bool lightmap_images(const scene::LightmapTarget& target, const LightmapTexels& map,
                     std::vector<LightmapImage>& out, std::string& error);

// The sidecar document of one lightmap (JSON text): its files, frame, basis, normalisation,
// the HLSL that evaluates a texel, and its statistics (texels, error distribution, cost).
std::string lightmap_sidecar(const scene::Scene& scene, const scene::LightmapTarget& target,
                             const LightmapTexels& map, const LightmapBakeResult& result);

// The HLSL include that evaluates a texel (docs/lightmaps.md; the Unity package ships it as
// Runtime/ShpackLightmap.hlsl): L1, or L2 with SHPACK_LIGHTMAP_L2 defined to 1.
std::string lightmap_hlsl();

}  // namespace shpack::bake
