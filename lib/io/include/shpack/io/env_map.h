// env_map.h - reading an environment map file and projecting it onto L2 SH.
//
// The file is read with OpenImageIO (OpenEXR, Radiance .hdr, PFM, TIFF, PNG, JPEG, and
// anything else it reads) in bands of whole projection tiles, converted to float, and
// streamed into the core's EquirectProjector, so memory stays bounded: a band holds
// kTileRows rows per worker thread, capped at kBandBudgetBytes (never fewer than kTileRows
// rows), whatever the image size.
//
// Pixels: half, float and 8/16/32-bit integer channels all arrive as float (integers as
// value / max). Float pixels (EXR, .hdr, PFM) are never transformed. Integer pixels are
// linearised with the exact sRGB EOTF (srgb.h) when OpenImageIO reports the colour space
// "sRGB", or when a PNG or JPEG reports none; otherwise they too are taken as linear
// (EnvMapInfo::srgb_decoded says which happened). Channels: 1 is grey
// (the core replicates it to R, G, B), 2 is grey + alpha, 3 is RGB, 4 or more is RGB and
// channels that are not read (counted in EnvMapInfo::ignored_channels). Alpha is never
// applied to colour: it is read unassociated and then ignored.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "shpack/io/io_status.h"
#include "shpack/io/layout.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"

namespace shpack::io {

inline constexpr std::size_t kBandBudgetBytes = std::size_t{64} << 20;  // 64 MiB of floats

struct EnvMapOptions {
  Layout layout = Layout::Auto;
  ProjectOptions project;  // method, NaN/Inf and negative policies, threads
};

// What the file held.
struct EnvMapInfo {
  std::uint32_t width = 0, height = 0;
  std::uint32_t channels = 0;          // channels in the file
  std::uint32_t ignored_channels = 0;  // channels not projected: alpha and any after R, G, B
  Layout layout = Layout::Auto;        // the layout used (never Auto)
  bool srgb_decoded = false;           // integer sRGB pixels were linearised
  std::string format;                  // OpenImageIO's format name: "openexr", "hdr", "png", ...
};

struct EnvMapProjection {
  EnvMapInfo info;
  ShL2 radiance;       // L_c,i in Unity's frame (project.h)
  ProjectStats stats;  // texel counts over the whole image
};

// Reads `path` and projects it. Errors name the file: it is missing, a directory, not an
// image, truncated or otherwise unreadable (IoErrc::Unreadable), of zero size or an
// unusable kind (Unsupported), of a shape whose layout cannot be detected (UnknownLayout),
// or holds NaN/Inf texels under NonFinite::Error (NonFiniteTexel; the whole image is
// scanned first, so the message gives their number and the first in row-major order).
// On failure `out` is left as it was.
IoStatus project_env_map(const std::filesystem::path& path, const EnvMapOptions& options,
                         EnvMapProjection& out);

}  // namespace shpack::io
