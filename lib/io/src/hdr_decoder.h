// hdr_decoder.h (private) - Radiance pictures (.hdr, .pic: RGBE) read by shpack itself, so
// that converting a .hdr never loads OpenImageIO (image_open.h). Each file is one part,
// channels R, G, B, format "hdr" (OpenImageIO's name, which documents record).
//
// The file, as Radiance writes it [1, 2]:
//  - the magic line "#?RADIANCE" (or "#?RGBE", which other writers use), then header lines
//    up to the first empty one, all within the first 64 KiB (Radiance writes a few hundred
//    bytes). FORMAT=32-bit_rle_rgbe, or no FORMAT line (Radiance reads that as RGBE), is
//    read; FORMAT=32-bit_rle_xyze (CIE XYZ) and any other format are refused, as OpenImageIO
//    refused them. Every other line is read past and not applied, as OpenImageIO did not
//    apply it, so the numbers are those it gave: EXPOSURE (Radiance's pixels are radiance
//    times EXPOSURE; `--intensity 1/EXPOSURE` undoes it), COLORCORR, PRIMARIES, GAMMA, VIEW,
//    PIXASPECT.
//  - the resolution string: two axes, the first the slow one (scanlines), each with its
//    direction and size, "-Y H +X W" for the usual top-down, left-to-right order. All eight
//    orderings are read into that top-down, left-to-right image of W x H texels (Radiance's
//    picture is y-up: "+Y" scanlines run from the bottom, "-X" pixels from the right; "+X W
//    -Y H" stores columns). OpenImageIO returns the pixels in file order with an orientation
//    tag, which shpack never applied, so for the seven other orderings these images differ
//    from OpenImageIO's: they are the right way round. Sizes are 1 ... 2^31 - 1.
//  - scanlines: flat, new-style or old-style RLE (rgbe_scanline.h), RGBE to float exactly as
//    OpenImageIO did (m * 2^(E - 136), not Radiance's (m + 0.5) * 2^(E - 136)).
//
// Checks at open, before anything is allocated: the header lies within its 64 KiB and ends
// in a blank line and a resolution string; the image is within `budget` (the budget's
// message first, so a header that claims too much is refused as such); the file holds at
// least 4 bytes for every scanline the header declares (no scanline is shorter). A scanline
// that does not decode (truncated, a run past its end, a wrong width) fails the read that
// reaches it, naming it.
//
// Rows in bands: scanlines are decoded on demand and the file offset of each one decoded is
// kept (8 bytes a scanline), so any band costs the scanlines it needs plus, the first time,
// those before them: a band asked for after a later one (backwards) seeks back to its first
// scanline's offset and decodes only its own. A top-down file read in increasing bands is
// read once, front to back, holding one scanline; a bottom-up one ("+Y") is decoded once more
// to find its offsets first. A file that stores columns ("+X W -Y H", ...) is decoded whole at
// the first read, after a first pass has checked every scanline, and held as float (12 bytes a
// texel, within the budget). Decoding runs on the calling thread: RLE scanlines are sequential.
//
// [1] G. Ward, "Real Pixels", Graphics Gems II (1991), 80-83.
// [2] Radiance, src/common/header.c, resolu.h and resolu.c (str2resolu).
#pragma once

#include <filesystem>
#include <memory>
#include <string_view>

#include "file_bytes.h"
#include "image_decoder.h"
#include "image_open.h"
#include "shpack/io/io_status.h"

namespace shpack::io::detail {

// Whether a file's first bytes are a Radiance magic line: "#?RADIANCE" or "#?RGBE", then a
// line break or a blank.
bool is_radiance_magic(std::string_view head);

// Opens the Radiance picture `file`, named `path` in messages, under `budget`. On failure
// `decoder` is null and the status names the file: Unreadable for what is not a Radiance
// picture or is truncated, Unsupported for a format other than RGBE or an image above the
// budget.
IoStatus open_hdr(const std::filesystem::path& path, FileBytes file, const TexelBudget& budget,
                  std::unique_ptr<ImageDecoder>& decoder);

}  // namespace shpack::io::detail
