// lightmap_preview.h - a picture of an SH lightmap (`shpack preview NAME.lightmap.json`), to
// see seams and leaks: three panels of the texels side by side, each texel a square of
// `zoom` pixels (the largest that keeps a panel within `size` pixels, at least 1):
//
//   "L0"     the L0 term, E/pi averaged over the sphere of normals (SHA.w per channel: the
//            constant of Unity's SH vectors), tone mapped as preview.h's panels (Reinhard
//            with k = 1 / mean luminance, then sRGB)
//   "L1"     the dominant direction of the light, normalize(sum_c lum_c SHA_c.xyz) in
//            Unity's world frame, as false colour 0.5 + 0.5 d (x red, y green, z blue)
//   "texels" state: baked grey by coverage, dilated blue, padding green
//
// Unused texels are a grey checkerboard in every panel. Errors name the sidecar or the image.
#pragma once

#include <filesystem>

#include "shpack/io/io_status.h"
#include "shpack/io/preview.h"

namespace shpack::io {

IoStatus render_lightmap_preview(const std::filesystem::path& sidecar, std::uint32_t size, Rgb8Image& out);

}  // namespace shpack::io
