// map_source.h - stage 1 of the pipeline (shpack/pipeline.h) for files: which pixels of an
// environment map file (or of six face files) are read, and how, resolved once when the
// source is opened; then the pixels, in bands of rows or whole, as the later stages need.
//
// OpenEXR files are read with OpenEXR itself, Radiance .hdr and PFM with shpack's own readers;
// every other format (TIFF, PNG, JPEG, and anything else OpenImageIO reads) through shpack's
// OpenImageIO module, which is loaded for the first such file. The reader is chosen by the
// file's magic number (lib/io/src/image_open.h). What is resolved at open():
//  - part and channels: R, G, B by name, or Y (grey, which the core replicates to R, G, B),
//    of the part or layer SourceOptions::layer names; files without layered names give their
//    first three channels (or their first, if fewer); channels not read are counted in
//    SourceInfo::ignored_channels. Alpha is never applied to colour: it is read unassociated
//    and then ignored (lib/io/src/image_source.h);
//  - the window: the image is the display window, black outside the data window;
//  - values: half, float and 8/16/32-bit integer channels all arrive as float (integers as
//    value / max). Float pixels (EXR, .hdr, PFM) are never transformed. Integer pixels are
//    linearised with the exact sRGB EOTF (srgb.h) when OpenImageIO reports the colour space
//    "sRGB", or when a PNG or JPEG reports none; otherwise they too are taken as linear
//    (SourceInfo::srgb_decoded says which happened);
//  - colour space: SourceOptions::colorspace, else the EXR's chromaticities, else Rec. 709,
//    as the matrix to linear Rec. 709 (colorspace.h resolve_colorspace), which the finish
//    stage applies;
//  - layout: SourceOptions::layout, or detected from the shape (layout.h).
// Pixels: read_rows streams an equirect map in bands (memory bounded by the band, whatever
// the map's size); read_whole holds the whole image (or the six faces) as float, writable,
// for the projectors that need every texel and for the transforms.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "shpack/colorspace.h"
#include "shpack/conventions.h"
#include "shpack/io/image_file.h"
#include "shpack/io/io_status.h"
#include "shpack/layout.h"
#include "shpack/pipeline.h"

namespace shpack::io {

namespace detail {
class ImageSource;
}

inline constexpr std::size_t kBandBudgetBytes = std::size_t{64} << 20;  // 64 MiB of floats

struct SourceOptions {
  Layout layout = Layout::Auto;
  std::string layer;                         // the part or channel layer ("" = the default choice)
  ColorSpace colorspace = ColorSpace::Auto;  // the input's primaries; Auto: the file's
  CubeFrame cube_frame = CubeFrame::Unity;   // the world the cube faces were made in (cube layouts)
  // The most texels the image may declare (--max-texels; image_file.h): its display window
  // and its data window, checked from the header at open() before anything is allocated or
  // decoded; for six face files, the six faces together.
  std::uint64_t max_texels = kDefaultMaxTexels;
};

// What the source holds, as resolved.
struct SourceInfo {
  std::uint32_t width = 0, height = 0;  // the image's (one face's, for six face files)
  std::uint32_t channels = 0;           // channels in the file (summed over face files)
  std::uint32_t ignored_channels = 0;   // channels not projected: alpha and any after R, G, B
  Layout layout = Layout::Auto;         // never Auto once open
  bool srgb_decoded = false;            // integer sRGB pixels were linearised
  std::string format;                   // the format's name, as OpenImageIO names it: "openexr", "hdr", "pnm" (PFM), "png", ...
  ColourResolution colour;              // the input's primaries and the matrix to Rec. 709
};

class MapSource {
 public:
  MapSource();
  ~MapSource();
  MapSource(const MapSource&) = delete;
  MapSource& operator=(const MapSource&) = delete;

  // One image. Errors name the file: it is missing, a directory, not an image, truncated or
  // otherwise unreadable (Unreadable), of zero size, an unusable kind, without the layer
  // asked for, or of primaries that are not three colours (Unsupported), of a shape whose
  // layout cannot be detected or that does not fit the layout asked for (UnknownLayout; the
  // message lists the layouts that fit), or named Layout::Faces (InvalidArgument).
  IoStatus open(const std::filesystem::path& path, const SourceOptions& options);

  // Six face files in Unity's face order (+X, -X, +Y, -Y, +Z, -Z), read whole, each as
  // open() reads a file (options.layout is ignored). Errors name the face's file: any of
  // open()'s, or a face that is not square or differs in size from the first, or faces that
  // declare different chromaticities (Unsupported).
  IoStatus open_faces(const std::array<std::filesystem::path, kCubeFaceCount>& paths, const SourceOptions& options);

  const SourceInfo& info() const noexcept { return info_; }
  const CubeFrame& cube_frame() const noexcept { return cube_frame_; }
  // The file that face `face` came from (the one file of a single image).
  const std::filesystem::path& path(std::uint32_t face = 0) const noexcept;

  // Streams the whole image (not faces) into `projector` and `reference` (the view error's
  // truth), both begun on this image's size: bands of whole projection tiles, one per worker
  // thread, within kBandBudgetBytes.
  IoStatus stream_into(EquirectProjector& projector, ViewReference& reference, unsigned threads);

  // The whole image, or the six faces, as float in memory this source owns (valid while it
  // lives), writable for the transforms.
  IoStatus read_whole(MapImage& map, unsigned threads);

 private:
  SourceInfo info_;
  CubeFrame cube_frame_ = CubeFrame::Unity;
  std::array<std::filesystem::path, kCubeFaceCount> paths_;
  std::unique_ptr<detail::ImageSource> image_;  // one image, until read
  std::array<ImageFile, kCubeFaceCount> faces_;  // six face files, read at open_faces
  std::vector<float> pixels_;                    // the whole image, once read
};

}  // namespace shpack::io
