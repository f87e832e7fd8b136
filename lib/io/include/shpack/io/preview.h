// preview.h - pictures of an output document (`shpack preview`), to judge lighting by eye.
//
// One sRGB 8-bit image with these panels (S = PreviewSettings::size):
//
//   "front"  S x S   a white diffuse sphere seen from -Z (Unity's default camera looks along
//                    +Z): screen right +X, up +Y; the pixel's normal is (sx, sy, -sqrt(1 - r^2))
//   "top"    S x S   the same sphere seen from above (+Y): screen right +X, up +Z;
//                    normal (sx, sqrt(1 - r^2), sy)
//   "sh"     2S x S  E/pi over all directions, laid out as an equirect map (conventions.h:
//                    centre column +X, a quarter from the left +Z, top row +Y)
//
// Every value is what Unity shows, ShadeSH9(n) = SHEvalLinearL0L1 + SHEvalLinearL2
// evaluated in float from the document's shader vectors (unity_pack.h's shade_sh9), plus the
// Lambert term colour * intensity * max(0, n . -forward) of every directional light the
// document carries (its "sun" and "lights"), each marked by a cyan ring at its direction on
// the E/pi and error panels. Ticks name +Z, +X and -Z along the equirect panels' top, up
// being the top row. The mean the tone mapping and the percentages use is the mean of all of
// it: the L00 terms plus a quarter of each light's colour * intensity. Where any channel is negative (L2 ringing, which the built-in Standard shader
// clamps to 0), the pixel is marked with magenta diagonal stripes on black.
//
// With a reference map (the input the document came from, in any layout `convert` reads):
//
//   "reference"  2S x S  the exact E/pi of the map: (1/pi) sum over texels of
//                        L int max(0, n.w) dw, in linear Rec. 709 (the file's colour matrix,
//                        as convert applies it) with the document's intensity and rotation
//   "error"      2S x S  luminance of sh - reference, blue (sh too dark) - white - red (too
//                        bright), with a colour bar labelled with its end values
//   "input"      <= 2S x S  the map itself as stored (its own layout; six faces side by
//                        side), nearest texels, radiance with the same colour matrix,
//                        intensity and tone mapping
//
// The reference is the view error's (view_reference.h): exact where a cell of texels lies
// wholly on one side of the normal's horizon, within a stated bound where the horizon cuts
// it; the report gives the largest bound over the panel's pixels (0.5 to 2.7 % of the mean
// E/pi on the bundled maps). NaN/Inf texels are read as 0, as the view error reads them.
//
// Tone mapping, the same for every panel: v -> Reinhard(k v) = k v / (1 + k v) per channel,
// then the sRGB encoding (IEC 61966-2-1), with k = 1 / (mean E/pi luminance), the luminance
// of the L00 terms (sh[c][0] is the mean of E/pi over the sphere): an average-lit normal is
// shown at 0.5 before encoding. Luminance weights are Unity's LinearRgbToLuminance
// (0.2126729, 0.7151522, 0.0721750; UnityCG.cginc).
//
// Labels are drawn in DejaVu Sans (Debian's fonts-dejavu-core, which scripts/install-deps.sh
// installs) through OpenImageIO's FreeType renderer, a tenth of the spheres' size high (11
// pixels at least); without the font or the module, in a built-in 5x7 bitmap font (upper
// case, digits, a few signs). PreviewReport::truetype_text says which.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shpack/io/io_status.h"
#include "shpack/io/json_reader.h"
#include "shpack/layout.h"

namespace shpack::io {

// An 8-bit sRGB RGB image, row-major from the top.
struct Rgb8Image {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // 3 per pixel

  const std::uint8_t* at(std::uint32_t x, std::uint32_t y) const { return &pixels[(std::size_t{y} * width + x) * 3]; }
  std::uint8_t* at(std::uint32_t x, std::uint32_t y) { return &pixels[(std::size_t{y} * width + x) * 3]; }
};

struct PreviewSettings {
  std::uint32_t size = 128;          // S, the sphere's diameter in pixels; 32..1024
  std::filesystem::path reference;   // the input map; empty: no reference panels
  Layout reference_layout = Layout::Auto;  // how it holds the sphere (convert's --layout)
  std::string reference_label;       // how the reference is named in the image (its file name)
};

// Where each panel is, for readers of the image (tests, the gallery).
struct PanelRect {
  std::uint32_t x = 0, y = 0, width = 0, height = 0;
};

struct PreviewReport {
  double exposure = 1;                 // k of the tone mapping
  double mean_luminance = 0;           // luminance of the L00 terms: mean E/pi
  double negative_fraction = 0;        // share of the sphere where a channel of ShadeSH9 < 0
  PanelRect front, top, sh;            // the panels
  bool has_reference = false;          // the fields below are set only with a reference
  PanelRect reference, error, colour_bar;
  PanelRect input;                     // the input map as stored, fitted into 2S x S
  std::array<double, 3> reference_bound{};  // per channel: max over pixels of the bound, E/pi units
  double reference_bound_luminance = 0;     // max over pixels of the luminance of the bound
  double error_scale = 0;              // the colour bar spans [-error_scale, +error_scale]
  double max_abs_error = 0;            // luminance of sh - reference, max over pixels
  double rms_error = 0;                // root mean square over the sphere (solid-angle weighted)
  bool truetype_text = false;          // the labels are DejaVu Sans (else the bitmap font)
};

// Renders the panels for `content` (and settings.reference if set). Errors name the
// reference file: those of the map source (map_source.h: unreadable, a shape no layout fits
// or that does not fit the layout named); and InvalidArgument for a size outside 32..1024.
IoStatus render_preview(const ShJsonContent& content, const PreviewSettings& settings, Rgb8Image& image,
                        PreviewReport& report);

// Writes `image` as PNG through write_file_atomically (atomic_write.h): the file is replaced
// whole or not at all.
IoStatus write_png(const std::filesystem::path& path, const Rgb8Image& image);

}  // namespace shpack::io
