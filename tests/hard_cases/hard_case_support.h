// hard_case_support.h - helpers for the hard-case tests: a cube-texel oracle, the
// shpack command as a child process (exit code, output, peak RSS), small image files written
// independently of shpack_io, and the float-rounding tolerance of the packed outputs.
// Test code only; never in lib/.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shpack/sh_basis.h"

namespace shpack_hard {

// ---------------------------------------------------------------------------------------
// Oracles in long double (x87 extended: 64-bit significand, unit roundoff 2^-64), so that
// their own error (~1e-18 relative) is far below every double tolerance they check.

// Gauss-Legendre rule on [-1, 1] with nodes and weights computed in long double (Newton's
// iteration on P_q), 1 <= q <= 48. The q-point rule on [a, b] integrates a trigonometric
// polynomial of frequency <= nu and coefficient sum A to within (b - a) A R with
// R = ((b - a) nu)^(2q) (q!)^4 / ((2q + 1) ((2q)!)^3) (support/gauss_legendre.h).
struct RuleLd {
  std::vector<long double> x, w;
};
const RuleLd& gauss_legendre_ld(int q);
// The smallest q with R <= 1e-22 for an interval of `length` and frequency `nu`.
int order_ld(long double length, long double nu);

// Y_i at a unit direction, in long double, from docs/conventions.md section 3 with k_i
// recomputed from std::numbers (not sh_basis.h).
std::array<long double, 9> basis_long_double(long double x, long double y, long double z);

using ShLd = std::array<std::array<long double, 9>, 3>;

// Equirect texels (docs/conventions.md section 2: theta in [pi j/H, pi (j+1)/H], lon in
// [(0.5 - (i+1)/W) 2 pi, (0.5 - i/W) 2 pi], d = (sin theta cos lon, cos theta,
// sin theta sin lon), dw = sin theta dtheta dlon). Every L2 basis polynomial is a sum of
// products f(theta) g(lon) (1; y = cos; z = sin sin; x = sin cos; xy, yz; 3z^2 - 1 =
// 3 sin^2 sin^2 - 1; xz; x^2 - y^2 = sin^2 cos^2 - cos^2), so a texel integral is a sum of
// products of six theta integrals of the row (frequency <= 3) and six lon integrals of the
// column (frequency <= 2), each by a Gauss-Legendre rule in long double of the order that
// R <= 1e-22 asks for. Quadrature, not shpack's closed forms.
class EquirectOracle {
 public:
  EquirectOracle(std::uint32_t width, std::uint32_t height);
  // int over texel (i, j) of Y_0..Y_8, and of 1 at index 9.
  std::array<long double, 10> texel(std::uint32_t i, std::uint32_t j) const;
  // The radiance coefficients of an RGB float image (3 floats a texel, row-major from the
  // top, any values, zeros skipped), summed in long double.
  ShLd project(const std::vector<float>& rgb) const;

 private:
  struct Row { long double t1, tc, ts, tsc, ts3, tc2; };     // int sin, cos sin, sin^2, sin^2 cos, sin^3, cos^2 sin
  struct Column { long double l1, lc, ls, lcc, lss, lsc; };  // int 1, cos, sin, cos^2, sin^2, sin cos
  std::uint32_t width_, height_;
  std::vector<Row> rows_;
  std::vector<Column> columns_;
};

// Cube texels: int over texel (x, y) of face `face` of an n x n cube of Y_i (i = 0..8) and,
// at index 9, of 1 (the solid angle). Tensor Gauss-Legendre quadrature of Y_i(d) da db / r^3
// (d = p / r, p = N + aU + bV, r = |p|) on sub-squares of side <= 1/8, 12 points a side, in
// long double. On a sub-square of side h the integrand is analytic with its nearest complex
// singularity at distance >= 1 (where 1 + a^2 + b^2 = 0), so the rule's error is below
// (h/2)^24 < 1e-28 of the integral.
std::array<long double, 10> cube_texel_oracle(std::uint32_t n, int face, std::uint32_t x, std::uint32_t y);

// ---------------------------------------------------------------------------------------
// The shpack command.

struct ChildRun {
  int exit_code = -1;        // -1: did not exit normally (signal) or could not start
  std::string out, err;      // its stdout and stderr
  long max_rss_kib = 0;      // peak resident set size of the child alone (its VmHWM)
  double seconds = 0;        // wall time
};

// The shpack executable under test (SHPACK_CLI_PATH, set by tests/hard_cases/CMakeLists.txt).
std::filesystem::path shpack_cli();

// Runs `program args...` with stdout and stderr captured through files in `scratch`
// (posix_spawn, no shell), polling its peak RSS (VmHWM, every 2 ms) until it exits.
ChildRun run_child(const std::filesystem::path& program, const std::vector<std::string>& args,
                   const std::filesystem::path& scratch);

// A fresh folder named after the running test under the test temp dir, removed with its
// content on destruction.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& file) const { return path_ / file; }

 private:
  std::filesystem::path path_;
};

// ---------------------------------------------------------------------------------------
// Image files, written without shpack_io.

enum class FileType { Float, Half };

// An EXR (ZIP compression) of `channels` channels, row-major from the top. Values are
// stored as given (Float) or rounded to half by OpenEXR's conversion (Half). Returns an
// error message, empty on success.
std::string write_exr(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                      int channels, const std::vector<float>& pixels, FileType type);

// A little-endian PFM ("PF", RGB) written by hand (OpenImageIO cannot write PFM); `rgb` is
// row-major from the top, and PFM stores rows bottom to top.
void write_pfm(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
               const std::vector<float>& rgb);

std::string read_text(const std::filesystem::path& path);

// ---------------------------------------------------------------------------------------
// Float outputs.

inline constexpr double kFloatU = 0x1p-24;  // unit roundoff of binary32

// |float(x) - want| when |x - want| <= err: rounding to nearest moves x by at most
// kFloatU |x| <= kFloatU (|want| + err), so the bound is kFloatU |want| + (1 + kFloatU) err.
inline double float_rounding_tol(double want, double err) {
  return kFloatU * (want < 0 ? -want : want) + (1 + kFloatU) * err;
}

}  // namespace shpack_hard
