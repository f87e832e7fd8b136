// format_common.h (private) - what the C#, HLSL and YAML writers share.
#pragma once

#include <string>
#include <vector>

#include "shpack/document.h"

namespace shpack::io::detail {

// The float in scientific notation with 9 significant digits ("1.23456780e-01").
//
// Why 9 digits read back to the same float even through double. 9 significant digits
// (std::numeric_limits<float>::max_digits10) put the decimal d within half a unit of its
// last digit of the float x: |d - x| <= 0.5 * 10^-8 * 10^E <= 2^-26.5 |x|, which is at most
// about 0.09 float ulp. A parser that rounds d to float directly gets x back. One that
// first rounds d to double (an error of at most 2^-53 |d|, i.e. 2^-29 float ulp) and then
// to float still lands within 0.1 ulp of x, far from the midpoints (0.5 ulp) where double
// rounding could pick the neighbour. The shortest round-trip form has no such margin: it
// may lie anywhere in x's rounding interval, close to a midpoint.
std::string float_scientific(float value);

// The float in %.9g form ("0.920851886", "1e-05"): 9 significant digits as above, in the
// shortest layout; what Unity's YAML assets hold.
std::string float_general(float value);

// One line each: the generator, the input (files and SHA-256), the options as in the JSON
// document ({"method": ..., ...}), and "L1 only" when doc.l1 is set. No comment markers.
std::vector<std::string> provenance_lines(const ShDocument& doc);

// Words of the first input's file stem (letters and digits; "sky_2k.exr" -> {"sky", "2k"}),
// or {"probe"} if it has none: the writers name their class, vectors and guard after it.
std::vector<std::string> stem_words(const ShDocument& doc);

}  // namespace shpack::io::detail
