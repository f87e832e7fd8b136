// half_oracle.h - IEEE binary16 -> binary32 by arithmetic (ldexp), independent of shpack's
// bit-level half_to_float.
#pragma once

#include <cstdint>

namespace shpack_test {

// value = (-1)^s 2^(e-15) (1 + m/1024) for 0 < e < 31; (-1)^s m 2^-24 for e = 0;
// Inf for e = 31, m = 0; NaN for e = 31, m != 0.
float half_bits_to_float(std::uint16_t h);

}  // namespace shpack_test
