// sampling_methods.h - other ways to project an equirect map: the rules that engines,
// importers and textbooks use, made comparable with the exact projection.
//
// Contract. Every method sees the image exactly as project.h does: radiance constant over
// each texel (conventions.h gives each texel's patch of the sphere), every value read with
// the NaN/Inf and negative policies of ProjectOptions. A method looks at that piecewise-
// constant image only through the texel a direction falls in (equirect_texel), so as its
// parameter grows each method converges to SamplingMethod::Exact of the same image. The result is
// the radiance coefficients L_c,i = int L_c(w) Y_i(w) dw in Unity's frame (sh_basis.h),
// accumulated in double with Neumaier sums in a fixed order: bit-identical from run to run.
//
//   spec           estimate of int L Y_i dw                               seed  allocates
//   exact, center  project_equirect (project.h)                            -   column tables
//   mip:K          box-filter 2^K x 2^K texels (a GPU mip level), then exact -   the small map
//   mc:N           (4 pi / N) sum_k L(w_k) Y(w_k), w_k i.i.d. uniform       yes   -
//   qmc:N          the same, w_k from a randomly digit-shifted Sobol net    yes   -
//   fib:N          the same, w_k the N spherical Fibonacci points            -    -
//   is:N           (1/N) sum_k L Y / p, p per texel ~ (lum + eps mean) Omega yes  W H doubles
//   riemann:N      N x 2N (theta, lon) grid, weight sin(theta) dtheta dlon   -    -
//   cube:N         6 N^2 cube texels, weight (2/N)^2 / (1+a^2+b^2)^1.5,      -    -
//                  renormalised to sum 4 pi (three.js LightProbeGenerator)
//   cube-exact:N   6 N^2 cube texels, exact solid angle (Filament, Babylon)  -    -
//   lsq:N          least-squares fit of the 9 coefficients to N Fibonacci   -    -
//                  samples (ShLeastSquares)
//
// Details of each method:
//  - mip:K, 0 <= K <= 31. The map is reduced to W' x H' = max(1, W >> K) x max(1, H >> K),
//    the size of mip level K on every GPU API. Each small texel is the plain average (by
//    texel count, not solid angle, as GPU reductions and engine importers do) of the source
//    texels under its footprint of W/W' x H/H' texels: when 2^K divides the size that is the
//    average of a 2^K x 2^K block; otherwise edge texels are split between two footprints in
//    proportion to their overlap (an exact box filter), so the small map covers the sphere
//    like the source. The small map is held in float32 RGB, as a GPU render target would, and
//    projected with SamplingMethod::Exact. mip:0 equals exact bit for bit.
//    Allocates 3 x W' x H' doubles (accumulators) and floats (the small map), and one
//    source row (3 x W floats).
//  - mc:N: directions y = 1 - 2 u1, lon = 2 pi u2 (uniform on the sphere, Archimedes), with
//    u1, u2 from std::mt19937_64(seed), whose output the C++ standard fixes: the same
//    samples on every platform (the last bits of the result still depend on the libm).
//  - qmc:N: (u1, u2) = the 2-D Sobol sequence (van der Corput; Sobol's second dimension),
//    XORed with two 32-bit digital shifts drawn from the seed. Sobol rather than Hammersley:
//    every prefix of 2^m Sobol points is a (0, m, 2)-net, so any N is well stratified and the
//    sequence extends without regenerating it, whereas the Hammersley set (k/N, radical
//    inverse) is a net only for N = 2^m and its first coordinate is a regular grid that can
//    alias with the texel rows; the digital shift keeps the net property, makes the
//    estimate unbiased, and lets a test measure the error over seeds. N < 2^32.
//  - fib:N: y_k = 1 - (2k + 1)/N, lon_k = 2 pi frac(k / phi), phi the golden ratio
//    (Swinbank & Purser 2006; Keinert et al. 2015); deterministic.
//  - is:N: a texel t is drawn with probability P_t ~ (max(lum_t, 0) + eps * mean) * Omega_t,
//    lum = Rec. 709 luminance 0.2126 R + 0.7152 G + 0.0722 B, mean = sum_t max(lum_t, 0)
//    Omega_t / (4 pi), eps = kImportanceFloor = 1/4; then a direction uniform in solid angle
//    inside t. The estimate (1/N) sum L_t Y(w) Omega_t / P_t is unbiased for the exact
//    projection (the CDF is built over texels in one pass, read with the policies). The floor
//    makes it a defensive mixture (Hesterberg 1995): a fraction eps/(1+eps) = 20% of the
//    probability is uniform in solid angle, so no texel is starved and the second moment is
//    at most (1+eps)/eps = 5 times that of mc. An image with mean <= 0 is sampled uniformly.
//    Allocates one double per texel (the CDF: 8 W H bytes, 256 MiB for 8192 x 4096) and one
//    row (3 x W floats).
//  - riemann:N: cell centres of an N x 2N grid in (t, u) (conventions.h), weight
//    sin(theta) (pi/N) (pi/N); the weights are not renormalised (sum 4 pi + O(N^-2)).
//    Its error is O(N^-2) once N >= H (each texel then holds whole cells when H divides N).
//    For N < H it reads one texel per cell, and when H/N is even every cell centre lies on a
//    texel edge, where the lookup's rounding picks one side: a half-texel shift, O(1/H).
//  - cube:N, cube-exact:N: the six N x N faces of conventions.h kCubeFaceAxes; each cube
//    texel takes the equirect texel its centre direction falls in (nearest-texel
//    resampling) and is weighted by cube_texel_weight_threejs (then all weights scaled by
//    4 pi / sum) or cube_texel_solid_angle. The cube is never stored.
//  - lsq:N, N >= 9: the N fib:N directions, values from the texels they fall in, fitted by
//    ShLeastSquares.
//
// Value policies and ProjectStats. exact, center, mip and is read every texel once, so their
// ProjectStats and NonFinite::Error behave exactly as project_equirect's. The other methods
// read only the texels their directions fall in: ProjectStats counts those reads (a texel
// read twice counts twice), the first non-finite is the first in sample order, and
// NonFinite::Error fails only if a NaN or Inf texel is read; a NaN that no sample hits is not
// seen. Use exact when every texel must be checked.
//
// Threads. ProjectOptions::threads is passed to project_equirect by exact, center and mip;
// the other methods run on the calling thread. ProjectOptions::method is ignored: the spec
// says which method runs.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

inline constexpr std::uint64_t kDefaultMethodSeed = 0x5eed;
inline constexpr double kImportanceFloor = 0.25;  // eps of is:N (see above)

struct MethodSpec {
  SamplingMethod method = SamplingMethod::Exact;
  std::uint32_t param = 0;                  // K for mip, N for the others, 0 for exact/center
  std::uint64_t seed = kDefaultMethodSeed;  // used by mc, qmc and is; ignored by the others

  friend bool operator==(const MethodSpec&, const MethodSpec&) = default;
};

// True for the methods whose result depends on MethodSpec::seed (mc, qmc, is).
constexpr bool uses_seed(SamplingMethod m) noexcept {
  return m == SamplingMethod::MonteCarlo || m == SamplingMethod::QuasiMonteCarlo ||
         m == SamplingMethod::Importance;
}

// Largest N of riemann:N and cube:N, so that their 2 N^2 and 6 N^2 samples fit in 64 bits.
inline constexpr std::uint32_t kMaxGridParam = 1u << 30;

// InvalidArgument unless the parameter is in its method's domain: param == 0 for exact and
// center, 0 <= K <= 31 for mip, N >= 9 for lsq, 1 <= N <= kMaxGridParam for riemann, cube
// and cube-exact, N >= 1 for the others.
Status validate_method(const MethodSpec& spec) noexcept;

// Parses "exact", "center", "mip:K", "mc:N", "qmc:N", "fib:N", "is:N", "riemann:N",
// "cube:N", "cube-exact:N", "lsq:N" (decimal, no sign, no spaces), and "mc:N:SEED",
// "qmc:N:SEED", "is:N:SEED" with a decimal uint64 seed (default kDefaultMethodSeed).
// On failure `spec` is left unchanged and the Status says what was wrong.
Status parse_method(std::string_view text, MethodSpec& spec) noexcept;

// The name parse_method reads back to the same spec: "mc:4096", or "mc:4096:7" when the seed
// is not the default (the seed is printed only for methods that use it). No allocation.
struct MethodName {
  std::array<char, 48> text{};  // NUL-terminated; the longest name has 35 characters
  std::string_view view() const noexcept { return text.data(); }
  const char* c_str() const noexcept { return text.data(); }
};
MethodName method_name(const MethodSpec& spec) noexcept;

// Projects an equirect image (ImageView, resolved by resolve_view) with `spec`: radiance
// coefficients comparable with project_equirect(SamplingMethod::Exact). Errors: BadView,
// InvalidArgument (validate_method), NonFiniteTexel (NonFinite::Error, see above),
// OutOfMemory (mip, is, exact, center: their documented buffers).
Status project_with_method(const ImageView& image, const MethodSpec& spec,
                           const ProjectOptions& options, ShL2& radiance,
                           ProjectStats* stats = nullptr) noexcept;

// ---- Building blocks, public so that tests and tools can pin them ------------------------

// The texel of a W x H equirect image that direction d falls in: the inverse of
// conventions.h's mapping, u = 0.5 - lon / (2 pi), t = theta / pi, with lon = atan2(z, x)
// and theta = atan2(sqrt(x^2 + z^2), y) (the same angle as acos(y) for a unit d, but
// accurate near the poles and valid for any length), column floor(u W), row floor(t H),
// clamped to the image. Texels are half-open [i/W, (i+1)/W) x [j/H, (j+1)/H); lon = +-pi
// (the -X seam) lands in column 0 or W-1 by the sign of z. d = 0 gives the top row; a
// non-finite d gives texel (0, 0).
struct EquirectTexel {
  std::uint32_t x = 0, y = 0;
  friend bool operator==(const EquirectTexel&, const EquirectTexel&) = default;
};
EquirectTexel equirect_texel(const Dir3& d, std::uint32_t width, std::uint32_t height) noexcept;

// Exact solid angle of texel (x, y) of an N x N cube face (the same on every face), by the
// corner formula of conventions.md: with f(a, b) = atan2(a b, sqrt(a^2 + b^2 + 1)) and the
// texel's corners a0 < a1, b0 < b1 in [-1, 1], Omega = f(a0,b0) - f(a0,b1) - f(a1,b0) + f(a1,b1).
// The 6 N^2 texels sum to 4 pi.
double cube_texel_solid_angle(std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept;

// three.js's centre-point weight of the same texel before renormalisation,
// (2/N)^2 / (1 + a^2 + b^2)^(3/2) at the texel centre (a, b): the solid angle of a small
// patch of area (2/N)^2 at distance sqrt(1 + a^2 + b^2), seen at that slant. Its sum over
// the cube is 4 pi + O(N^-2); cube:N scales every weight by 4 pi / sum.
double cube_texel_weight_threejs(std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept;

// Least-squares fit of L2 radiance coefficients to samples (direction, RGB value): per
// channel, the c minimising sum_k (v_k - sum_i c_i Y_i(d_k))^2. Each add() rotates the new
// row into a 9 x 9 triangular factor R with Givens rotations (a QR factorisation updated in
// place), so the normal equations, whose condition number is the square of the sample
// matrix's, are never formed; in double, no allocation. If the samples are values of an L2
// function, the fit returns its coefficients up to rounding.
class ShLeastSquares {
 public:
  // `direction` must be a unit vector (Y_i is evaluated as a polynomial).
  void add(const Dir3& direction, const std::array<double, 3>& value) noexcept;
  // InvalidArgument if fewer than 9 samples were added or the directions leave some L2
  // function (nearly) undetermined: |R_ii| <= 1e-10 max_j |R_jj|.
  Status solve(ShL2& radiance) const noexcept;
  std::uint64_t count() const noexcept { return count_; }

 private:
  std::array<std::array<double, kShCount>, kShCount> r_{};              // upper triangle
  std::array<std::array<double, kChannelCount>, kShCount> qt_value_{};  // Q^T v
  std::uint64_t count_ = 0;
};

}  // namespace shpack
