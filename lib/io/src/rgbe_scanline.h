// rgbe_scanline.h (private) - one scanline of a Radiance picture: its bytes read forward from
// the file (file_bytes.h ByteStream), its run-length encodings undone, its RGBE pixels turned
// into float.
// The reader of the file's header and of its scanline order is hdr_decoder.h.
//
// A scanline of L pixels, 4 bytes a pixel (R, G, B mantissas and a shared exponent E), is
// stored in one of three ways [1, 2]:
//  - new-style (adaptive) RLE, for 8 <= L <= 0x7fff: the bytes 2, 2, L >> 8, L & 255, then
//    each of the four components in turn, as runs (a byte 128 + n, 1 <= n <= 127, then the
//    value n times) and literals (a byte n, 1 <= n <= 128, then n values);
//  - flat: L records of 4 bytes;
//  - old-style RLE: flat records, where a record 1, 1, 1, n repeats the previous pixel
//    n << s times, s being 8 times the number of such records just before it.
// Radiance decides per scanline: new-style if it starts with 2, 2 and a byte below 128 (a
// pixel never does: its largest mantissa is at least 128), else records, so one reader
// serves flat and old-style. Unlike Radiance's reader, every run is checked against the
// scanline's end, an old-style run needs a pixel before it, and a literal of 0 bytes is an
// error (as in OpenImageIO's reader).
//
// [1] G. Ward, "Real Pixels", Graphics Gems II (1991), 80-83.
// [2] Radiance, src/common/color.c: freadcolrs, oldreadcolrs, colr_color.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "file_bytes.h"

namespace shpack::io::detail {

// Decodes the next scanline of `in` into `rgbe` (4 bytes a pixel, rgbe.size() / 4 pixels).
// False with the problem (a clause: "the file ends inside it", "a run of 9 from pixel 0 goes
// past its 8 pixels", ...) if the bytes are not a scanline of that length.
bool read_rgbe_scanline(ByteStream& in, std::span<std::uint8_t> rgbe, std::string& problem);

// RGBE pixels to float R, G, B (3 floats a pixel): m * 2^(E - 136) for each mantissa m, and
// 0 where E = 0. This is OpenImageIO's rule, so that values are those it gave; Radiance's
// colr_color adds half a step, (m + 0.5) * 2^(E - 136) [2]. Every value is exact in float:
// m < 2^8, and 2^(E - 136) spans 2^-135 ... 2^119, whose multiples of m are float numbers
// (subnormal below 2^-126, still multiples of 2^-149).
void rgbe_to_float(std::span<const std::uint8_t> rgbe, float* rgb);

}  // namespace shpack::io::detail
