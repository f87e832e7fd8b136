// test_util.h - small helpers shared by the tests: paths, printing, norms.
#pragma once

#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

// gtest printers (found by ADL) so failures show the values.
inline void PrintTo(const Dir3& d, std::ostream* os) {
  *os << "(" << d.x << ", " << d.y << ", " << d.z << ")";
}
inline std::ostream& operator<<(std::ostream& os, const Dir3& d) {
  PrintTo(d, &os);
  return os;
}
inline void PrintTo(const ShL2& sh, std::ostream* os) {
  const auto old = os->precision(17);
  for (int c = 0; c < kChannelCount; ++c) {
    *os << (c == 0 ? "{[" : " [");
    for (int i = 0; i < kShCount; ++i) *os << (i ? ", " : "") << sh.c[c][i];
    *os << "]";
  }
  *os << "}";
  os->precision(old);
}
inline void PrintTo(const Status& s, std::ostream* os) {
  *os << errc_name(s.code) << " (" << s.what << ") x=" << s.x << " y=" << s.y;
}
inline void PrintTo(Errc e, std::ostream* os) { *os << errc_name(e); }

}  // namespace shpack

namespace shpack_test {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2^-52
inline constexpr double kU = kEps / 2;                                   // unit roundoff 2^-53

inline std::filesystem::path source_dir() { return SHPACK_SOURCE_DIR; }
inline std::filesystem::path hdri_path(const std::string& name) {
  return source_dir() / "data" / "hdri" / (name + ".exr");
}

inline std::string describe(const shpack::Status& s) {
  std::ostringstream os;
  shpack::PrintTo(s, &os);
  return os.str();
}

// Euclidean norm of channel c's 9 coefficients.
inline double channel_norm(const shpack::ShL2& sh, int c) {
  double s = 0;
  for (double v : sh.c[c]) s += v * v;
  return std::sqrt(s);
}

// max_i |a_i - b_i| over channel c.
inline double channel_max_diff(const shpack::ShL2& a, const shpack::ShL2& b, int c) {
  double m = 0;
  for (int i = 0; i < shpack::kShCount; ++i) m = std::fmax(m, std::fabs(a.c[c][i] - b.c[c][i]));
  return m;
}

inline shpack::ShL2 to_sh(const std::array<double, 9>& v, const std::array<double, 3>& rgb) {
  shpack::ShL2 out;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) out.c[c][i] = rgb[c] * v[i];
  return out;
}

}  // namespace shpack_test
