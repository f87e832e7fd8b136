// accuracy.h - how far a projection is from the exact one, as Unity's shader sees it.
//
// A method's radiance coefficients L' are compared with the exact projection L of the same
// image (sampling_methods.h: every method converges to it). What a user sees is E/pi, the
// value ShadeSH9 returns, so the main errors are of E/pi per channel c,
//   dE_c(n) = sum_i C_i (L'_c,i - L_c,i) P_i(n)          (convolution.h, sh_basis.h),
// over a fixed set of kAccuracyNormals spherical Fibonacci normals, relative to the mean of
// the exact E_c/pi over the sphere, which is C_0 L_c,0 (only Y_0 has a non-zero mean).
// Each error is that of the worst channel, so a dim channel is not hidden by a bright one.
#pragma once

#include <array>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"

namespace shpack::study {

// Neighbouring normals are about sqrt(4 pi / 1024) = 6 degrees apart, and an L2 error
// (a quadratic in n) falls from its peak as the square of the angle, so the max over the
// normals is within about 1% of the max over the sphere; 1024 x 27 products per measurement.
inline constexpr int kAccuracyNormals = 1024;

// The n spherical Fibonacci normals y_k = 1 - (2k + 1)/n, longitude k * 2 pi / phi^2 (the
// golden angle), x = r cos(lon), z = r sin(lon): every part of the sphere within about
// sqrt(4 pi / n) of a normal. Deterministic, so every run measures on the same normals.
std::vector<Dir3> fibonacci_normals(int n);

struct AccuracyMetrics {
  double err_max_pct = 0;    // 100 max_c max_n |dE_c(n)/pi| / mean_c
  double err_rms_pct = 0;    // 100 max_c sqrt(mean_n (dE_c(n)/pi)^2) / mean_c
  double coef_err_max = 0;   // max_c max_i |L'_c,i - L_c,i| / L_c,0 (dimensionless)
  double min_e_over_pi = 0;  // min_c of the exact minimum over the sphere of E'_c/pi
                             // (sh_minimum.h), in the map's units: < 0 is L2 ringing
};

// Measures estimates against one reference. Channels whose exact mean is not positive
// (a black channel) have no relative error and are skipped; if every channel is, the
// relative errors are NaN.
class AccuracyMeter {
 public:
  explicit AccuracyMeter(const ShL2& reference_radiance, int normal_count = kAccuracyNormals);
  AccuracyMetrics measure(const ShL2& radiance) const;

 private:
  ShL2 reference_;
  std::vector<std::array<double, kShCount>> basis_;  // C_i P_i(n) for each normal
};

}  // namespace shpack::study
