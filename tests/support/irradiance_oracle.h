// irradiance_oracle.h - brute-force E(n)/pi of a piecewise-constant equirect image.
//
//   E(n)/pi = (1/pi) sum_t v_t int_t max(0, n.w) dw      (docs/conventions.md section 1)
//
// by direct quadrature over every texel, with a rigorous bound on its error:
//
//  - For a patch with centre direction w_c, every w in it satisfies |w - w_c| <= r with
//    r = dtheta/2 + max(sin theta) dlon/2 (walk along the meridian, then the parallel;
//    a chord is no longer than the arc), hence |n.w - n.w_c| <= r.
//  - If n.w_c >= r the integrand is n.w on the whole patch, a smooth trigonometric
//    polynomial: a Gauss-Legendre rule of the order the remainder bound asks for
//    (gauss_legendre.h) gives it to rounding. If n.w_c <= -r the patch contributes 0.
//  - Otherwise the terminator n.w = 0 crosses the patch (the kink of max(0, .)): the patch
//    is split in 2 x 2 down to `max_depth` levels; on a leaf that is still cut, both the
//    true integral and the (positive-weight) Gauss-Legendre estimate lie in
//    [0, (n.w_c + r) Omega_leaf], so the error is at most (n.w_c + r) Omega_leaf.
//  - Rounding: per-texel terms are O(u) relative and are summed in double along a row
//    (<= W u) and in long double across rows: at most (W + 64) u sum_t |v_t| Omega_t.
// The bound is the sum of all of these, divided by pi.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shpack/conventions.h"
#include "support/rgb_image.h"

namespace shpack_test {

struct IrradianceEstimate {
  std::array<double, 3> e_over_pi{};  // per channel
  std::array<double, 3> bound{};      // |error| <= bound, per channel
};

class IrradianceOracle {
 public:
  // Keeps a reference to `image`, which must outlive the oracle. max_depth: subdivision
  // levels of the texels the terminator crosses (the bound falls ~4x per level).
  IrradianceOracle(const RgbImage& image, int max_depth);
  IrradianceEstimate eval(const shpack::Dir3& n) const;

 private:
  struct Row {
    double theta0, theta1, sin_c, cos_c, radius;
    double int_sin2, int_sincos;  // int sin^2 theta dtheta, int sin theta cos theta dtheta
    double abs_sum[3];            // sum_i |v| over the row
    double omega;                 // solid angle of one texel of the row
  };
  struct Column {
    double lon0, lon1, cos_c, sin_c;
    double int_cos, int_sin;  // int cos lon dlon, int sin lon dlon
  };
  void integrate_cut(double theta0, double theta1, double lon0, double lon1, int depth,
                     const shpack::Dir3& n, double& estimate, double& bound) const;

  const RgbImage& image_;
  int max_depth_;
  std::vector<Row> rows_;
  std::vector<Column> columns_;
  std::vector<int> theta_order_, lon_order_;  // per subdivision depth
  double dlon_;
};

}  // namespace shpack_test
