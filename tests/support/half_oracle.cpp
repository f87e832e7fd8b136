#include "support/half_oracle.h"

#include <cmath>
#include <limits>

namespace shpack_test {

float half_bits_to_float(std::uint16_t h) {
  const bool negative = (h & 0x8000u) != 0;
  const int e = (h >> 10) & 0x1f;
  const int m = h & 0x3ff;
  double v;
  if (e == 0) {
    v = std::ldexp(static_cast<double>(m), -24);
  } else if (e == 31) {
    v = m == 0 ? std::numeric_limits<double>::infinity() : std::numeric_limits<double>::quiet_NaN();
  } else {
    v = std::ldexp(1024.0 + m, e - 25);
  }
  return static_cast<float>(negative ? -v : v);
}

}  // namespace shpack_test
