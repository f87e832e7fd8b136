// colorspace.h - the RGB primaries of an input, and the 3 x 3 matrix to shpack's output
// space, linear Rec. 709 / sRGB primaries with the D65 white (Unity's linear colour space).
//
// An OpenEXR file may say its primaries in its "chromaticities" attribute (CIE xy of red,
// green, blue and white; OpenEXR ImfChromaticities.h, Rec. 709 when absent), and
// `convert --colorspace` may name them instead. The matrix is computed here from the
// chromaticities, not taken from OpenImageIO's colour management (which needs an OCIO
// configuration that Debian does not ship):
//
//   RGB -> XYZ:  M = [r g b] diag(S), with r = (x_r/y_r, 1, (1 - x_r - y_r)/y_r) etc. and S
//                solving [r g b] S = W, the white's XYZ with Y = 1 (SMPTE RP 177-1993, 3.3);
//   adaptation:  Bradford, A = B^-1 diag(B W_709 / B W_src) B with
//                B = [[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]]
//                (K. M. Lam, 1985; the matrix of ICC.1:2010 Annex E), so the source's white
//                becomes Rec. 709's white (R = G = B) and grey stays grey;
//   to output:   M_709^-1 A M_src.
//
// The projection is linear in the texel values, so the matrix is applied to the projected
// coefficients (each coefficient's R, G, B mixed by it): the same result as converting
// every texel first. --negative and the diagnostics therefore see the file's own values.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "shpack/rotate.h"
#include "shpack/sh_basis.h"

namespace shpack {

// CIE 1931 xy of red, green, blue and white: {x_r, y_r, x_g, y_g, x_b, y_b, x_w, y_w}.
using Chromaticities = std::array<double, 8>;

enum class ColorSpace : std::uint8_t {
  Auto,          // the file's chromaticities if it has them, else Rec. 709
  LinearRec709,  // Rec. 709 / sRGB primaries, D65 (ITU-R BT.709-6)
  AcesCg,        // ACES AP1 primaries, ACES white (S-2014-004)
  Aces2065_1,    // ACES AP0 primaries, ACES white (SMPTE ST 2065-1)
  LinearP3D65,   // Display P3: DCI-P3 primaries, D65 (SMPTE EG 432-1)
  LinearRec2020, // Rec. 2020 primaries, D65 (ITU-R BT.2020-2)
};

// "auto", "linear-rec709", "acescg", "aces2065-1", "linear-p3-d65", "linear-rec2020".
const char* colorspace_name(ColorSpace space) noexcept;

// The chromaticities of a named space (not Auto).
Chromaticities colorspace_chromaticities(ColorSpace space) noexcept;

// The named space whose chromaticities equal `c` within 1e-4 (what an EXR's float
// attribute and rounded published values allow), or Auto if none does.
ColorSpace named_colorspace(const Chromaticities& c) noexcept;

// The matrix from linear RGB with chromaticities `c` to linear Rec. 709 (above), or false
// with `problem` set when the chromaticities are not those of three independent colours and
// a white with y > 0 (e.g. collinear primaries).
bool rgb_to_rec709_matrix(const Chromaticities& c, Matrix3& out, std::string& problem);

// The colour space an input is taken as (the source stage, pipeline.h): `requested` if it is
// not Auto, else the file's chromaticities, else Rec. 709; its name for the document
// ("file" for chromaticities that match no named space) and the matrix to linear Rec. 709
// (none for Rec. 709 itself). False, with `problem` set, as rgb_to_rec709_matrix.
struct ColourResolution {
  std::string name;
  std::optional<Matrix3> matrix;
};
bool resolve_colorspace(ColorSpace requested, const std::optional<Chromaticities>& file, ColourResolution& out,
                        std::string& problem);

// Each coefficient's (R, G, B) times `m`: what projecting the converted texels would give.
ShL2 mix_channels(const ShL2& sh, const Matrix3& m) noexcept;

}  // namespace shpack
