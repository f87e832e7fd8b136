// bake_json.h - the output of `shpack bake` as JSON (docs/scenes.md, "Output").
//
// Here, once per probe, the summed radiance is windowed (window.h, optional), convolved to
// Unity form (convolution.h) and packed (unity_pack.h): the only place the bake's doubles
// become float32.
//
//  - BakeFormat::Full: {"schema_version", "generator", "scene", "frame", "options", "probes":
//    [{"position", "radiance_sh", "sphericalHarmonicsL2", "shader", "diagnostics"}],
//    "effects": {name: {"time_ms", "rays", "samples", "analytic"}}, "geometry": {...}}; each
//    probe carries the keys of `shpack convert`'s document that describe coefficients.
//  - BakeFormat::UnityProbes: {"schema_version", "format": "unity-probes", "count",
//    "positions": [x0, y0, z0, x1, ...], "sphericalHarmonicsL2": [27 floats of probe 0 (sh[c, i]
//    at 9c + i), then probe 1, ...]}: flat arrays in one probe order, which Unity's JsonUtility
//    reads into float[] for a script that fills LightProbes.bakedProbes.
#pragma once

#include <string>

#include "shpack/bake/bake.h"
#include "shpack/bake/lightmap_bake.h"
#include "shpack/io/io_status.h"
#include "shpack/scene/scene.h"
#include "shpack/window.h"

namespace shpack::bake {

enum class BakeFormat : std::uint8_t { Full, UnityProbes };

struct BakeJsonOptions {
  BakeFormat format = BakeFormat::Full;
  Window window;  // deringing per probe, as `shpack convert --window`
  // The scene's lightmaps, when it has any: Full lists each ("lightmaps": name, size, its
  // sidecar file, texels, worst error estimate, texels/s); their data are in their own files.
  const LightmapBakeResult* lightmaps = nullptr;
};

// Fails (naming the scene file and the probe) when a probe's coefficients do not fit in
// float32, or the window cannot be applied.
io::IoStatus bake_to_json(const scene::Scene& scene, const BakeResult& result, const BakeJsonOptions& options,
                          std::string& json);

}  // namespace shpack::bake
