// env_map.h - reading an environment map file and projecting it onto L2 SH.
//
// The file is read with OpenImageIO (OpenEXR, Radiance .hdr, PFM, TIFF, PNG, JPEG, and
// anything else it reads). Its layout (layout.h) decides how:
//  - equirect: in bands of whole projection tiles, converted to float, and streamed into the
//    core's EquirectProjector, so memory stays bounded: a band holds kTileRows rows per
//    worker thread, capped at kBandBudgetBytes (never fewer than kTileRows rows), whatever
//    the image size;
//  - the cube layouts: the whole image as float (image_file.h), its six faces as views of it
//    (cube_layout.h, no copy), project_cube, then the cube frame (conventions.h CubeFrame);
//  - octahedral, angular, mirror ball: the whole image, project_sphere_map.
// Each layout is integrated in its own geometry; nothing is resampled.
//
// Pixels: half, float and 8/16/32-bit integer channels all arrive as float (integers as
// value / max). Float pixels (EXR, .hdr, PFM) are never transformed. Integer pixels are
// linearised with the exact sRGB EOTF (srgb.h) when OpenImageIO reports the colour space
// "sRGB", or when a PNG or JPEG reports none; otherwise they too are taken as linear
// (EnvMapInfo::srgb_decoded says which happened). Channels: R, G, B by name, or Y (grey,
// which the core replicates to R, G, B), of the part or layer EnvMapOptions::layer names;
// files without layered names give their first three channels (or their first, if fewer),
// and channels not read are counted in EnvMapInfo::ignored_channels. Alpha is never applied
// to colour: it is read unassociated and then ignored. The image is the display window,
// black outside the data window (lib/io/src/image_source.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "shpack/conventions.h"
#include "shpack/io/io_status.h"
#include "shpack/io/layout.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"

namespace shpack::io {

inline constexpr std::size_t kBandBudgetBytes = std::size_t{64} << 20;  // 64 MiB of floats

struct EnvMapOptions {
  Layout layout = Layout::Auto;
  ProjectOptions project;  // method, NaN/Inf and negative policies, threads
  std::string layer;       // the part or channel layer to read ("" = the default choice)
  CubeFrame cube_frame = CubeFrame::Unity;  // the world cube faces were made in (cube layouts only)
};

// What the file held.
struct EnvMapInfo {
  std::uint32_t width = 0, height = 0;
  std::uint32_t channels = 0;          // channels in the file
  std::uint32_t ignored_channels = 0;  // channels not projected: alpha and any after R, G, B
  Layout layout = Layout::Auto;        // the layout used (never Auto)
  bool srgb_decoded = false;           // integer sRGB pixels were linearised
  std::string format;                  // OpenImageIO's format name: "openexr", "hdr", "png", ...
  std::optional<std::array<double, 8>> chromaticities;  // the file's EXR chromaticities, if any
};

struct EnvMapProjection {
  EnvMapInfo info;
  ShL2 radiance;       // L_c,i in Unity's frame (project.h)
  ProjectStats stats;  // texel counts over the whole image
};

// Reads `path` and projects it. Errors name the file: it is missing, a directory, not an
// image, truncated or otherwise unreadable (IoErrc::Unreadable), of zero size, an unusable
// kind, or without the layer asked for (Unsupported), of a shape whose layout cannot be
// detected or that does not fit the layout asked for (UnknownLayout; the message lists the
// layouts that fit), a cube frame other than unity for a layout that is not a cube, or a
// method the layout does not have (InvalidArgument), or holds NaN/Inf texels under
// NonFinite::Error (NonFiniteTexel; the whole image is scanned first, so the message gives
// their number and the first one, in image coordinates; for the cube and sphere layouts
// only the texels that are projected count). On failure `out` is left as it was.
IoStatus project_env_map(const std::filesystem::path& path, const EnvMapOptions& options,
                         EnvMapProjection& out);

// The six faces of a cube map in six files, in Unity's face order (+X, -X, +Y, -Y, +Z, -Z),
// each read as project_env_map reads a file (options.layout is ignored; options.layer and
// options.cube_frame apply), all N x N with the same N. Errors name the face's file: any of
// project_env_map's, or a face that is not square or differs in size from the first
// (Unsupported), or faces that declare different chromaticities (Unsupported).
// EnvMapInfo: width = height = N, layout Layout::Faces, channels and ignored_channels
// summed over the files, srgb_decoded if any was.
IoStatus project_cube_faces(const std::array<std::filesystem::path, 6>& paths, const EnvMapOptions& options,
                            EnvMapProjection& out);

}  // namespace shpack::io
