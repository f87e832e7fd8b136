// pfm_decoder.h (private) - Portable Float Maps (.pfm) read by shpack itself, so that converting
// a PFM never loads OpenImageIO (image_open.h). Each file is one part, channels R, G, B ("PF")
// or Y ("Pf", grey), format "pnm" (OpenImageIO's name, which documents record).
//
// The file [1]: "PF" or "Pf", then three numbers separated by whitespace (a "#" comment to the
// end of its line may come before each, as OpenImageIO allows): width, height and the scale,
// then one whitespace byte, then width x height texels of 32-bit floats, row by row from the
// bottom row up. The scale's sign gives the byte order (negative: little-endian), and every
// value is multiplied by its absolute value, as OpenImageIO does (so values are those it gave;
// files almost always say 1 or -1, which change nothing). A scale of 0, or one that is not a
// finite number, is refused: it states no byte order. Bytes after the texels are ignored.
//
// Checks at open, before anything is allocated: the header ends within the first 64 KiB;
// width and height are 1 ... 2^31 - 1; the image is within `budget` (that message first);
// the file holds every texel the header declares. Rows are read in bands straight from
// their offsets (rows are fixed-size), in any order, with one read a band into a buffer of
// the band's size, on the calling thread.
//
// [1] P. Debevec, HDRShop's PFM: http://www.pauldebevec.com/Research/HDR/PFM/
#pragma once

#include <filesystem>
#include <memory>
#include <string_view>

#include "file_bytes.h"
#include "image_decoder.h"
#include "image_open.h"
#include "shpack/io/io_status.h"

namespace shpack::io::detail {

// Whether a file's first bytes are PFM's magic number: "PF" or "Pf", then whitespace.
bool is_pfm_magic(std::string_view head);

// Opens the PFM `file`, named `path` in messages, under `budget`. On failure `decoder` is
// null and the status names the file: Unreadable for what is not a PFM or is truncated,
// Unsupported for an image above the budget.
IoStatus open_pfm(const std::filesystem::path& path, FileBytes file, const TexelBudget& budget,
                  std::unique_ptr<ImageDecoder>& decoder);

}  // namespace shpack::io::detail
