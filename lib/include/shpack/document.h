// document.h - stage 5 of the pipeline (pipeline.h): the record of one conversion, what was
// read, which options were applied and what came out, before any writer formats it.
//
// docs/json-format.md describes every key the JSON writer makes of it. Everything in it is
// computed by the stages before; the writers (lib/io) format and compute nothing.
//
// L1 (FinishOptions::l1, `--l1`): what Unity's Light Probe Proxy Volume wants. A proxy
// volume stores, per cell, the three float4 vectors SHAr, SHAg, SHAb, and UnityCG.cginc's
// SHEvalLinearL0L1_SampleProbeVolume returns dot(SHA, (n, 1)) per channel [Unity built-in
// shaders, CGIncludes/UnityCG.cginc]; in quality mode Low nothing else is added (mode Normal
// adds SHEvalLinearL2 with per-renderer L2 vectors) [Unity Scripting API,
// LightProbeProxyVolume.QualityMode]. With band 2 removed Unity's own packing (unity_pack.h)
// gives SHA = (sh3, sh1, sh2, sh0): w = sh0, not sh0 - sh6, so dot(SHA, (n, 1)) = sh0 + sh1 y
// + sh2 z + sh3 x is exactly the L1 truncation of E/pi: the best L1 fit to E/pi on the
// sphere (least squares), with the same mean.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shpack/colorspace.h"
#include "shpack/conventions.h"
#include "shpack/engine_frame.h"
#include "shpack/layout.h"
#include "shpack/pipeline.h"
#include "shpack/rotate.h"
#include "shpack/sampling_methods.h"
#include "shpack/window.h"

namespace shpack {

struct ShSource {
  std::vector<std::string> files;   // file names, without folders
  std::vector<std::string> sha256;  // lower-case hex digest of each file
  Layout layout = Layout::Equirect;
  std::uint32_t width = 0, height = 0;
};

// How the source was read, beyond its layout (docs/json-format.md, "source").
struct ShReading {
  std::string layer;                        // the part or layer chosen (--layer); "" for the default
  CubeFrame cube_frame = CubeFrame::Unity;  // the world its cube faces were made in (cube layouts)
  std::string colorspace = "linear-rec709"; // its RGB primaries (colorspace.h), or "file" for
                                            // chromaticities that match no named space
  std::uint32_t ignored_channels = 0;       // channels of the file that were not projected
};

// What the projector saw (project.h ProjectStats).
struct ShTexelCounts {
  std::uint64_t nonfinite_texels = 0;  // NaN/Inf texels replaced by 0 (NonFinite::Zero)
  std::uint64_t negative_texels = 0;   // texels with a negative channel (kept or clamped)
};

struct ShDocument {
  ShSource source;
  ShReading reading;
  // The options applied, each by its stage (pipeline.h).
  MethodSpec method;
  double intensity = 1.0;   // linear factor applied to the radiance (intensity * 2^exposure)
  double rotate_deg = 0.0;  // yaw applied (rotate.h)
  Window window;            // deringing applied (window.h)
  bool l1 = false;          // band 2 removed (above)
  std::optional<Matrix3> colour_matrix;  // applied to the input's RGB, if it was not Rec. 709
  bool sun_extraction = false;           // --extract-sun was asked for (light_extraction.h)
  unsigned light_extraction = 0;         // --extract-lights N was asked for (light_choice.h)
  // The frame the JSON document's radiance_sh is written in (--frame, engine_frame.h);
  // everything else stays in Unity's frame.
  EngineFrame radiance_frame = EngineFrame::Unity;
  // The result.
  FinishedSh sh;
  ShTexelCounts texels;
  std::optional<FinishedLight> sun;  // the sun found, if any
  std::vector<ExtractedLight> lights;  // --extract-lights: those chosen, in the order chosen
  std::size_t light_candidates = 0;    // --extract-lights: how many it chose from
  std::optional<ViewError> view_error;  // what Unity shows against the input (view_error.h)
};

// The document of a conversion of `source`, read as `reading`, with `options`.
ShDocument make_document(ShSource source, ShReading reading, const ConvertOptions& options,
                         const Conversion& conversion);

}  // namespace shpack
