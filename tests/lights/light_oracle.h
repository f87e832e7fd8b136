// light_oracle.h - brute-force radiance SH of area and cap lights, for tests/lights.
//
// Each oracle integrates L Y_i(w) over the light itself (its surface, in area measure,
// dw = cos(theta_x) dA / |x - p|^2, or its cap in local polar coordinates) with composite
// Gauss-Legendre rules in the radial variable and the periodic trapezoid rule in the angle,
// evaluating Y_i with the independent Legendre-recurrence basis (support/sh_oracle.h). It
// knows nothing of shpack's closed forms or of the boundary integrals. Every result comes
// with an a posteriori error estimate: the difference between the rule at resolution n and
// at 2n (the 2n value is returned). The integrands are analytic on the closed domain (the
// probe is off the light), so convergence is geometric and the estimate bounds the error of
// the finer rule with a wide margin.
#pragma once

#include <array>
#include <functional>

#include "shpack/lights.h"

namespace shpack_test {

struct OracleSh {
  std::array<double, 9> value{};  // int_light Y_i dw for unit radiance
  double error = 0;               // max_i |fine - coarse|
  double scale = 0;               // |int_light Y_0 dw| = k0 Omega: the size of the numbers
  // Rounding bound of the fine rule's sums: (terms - 1) u sum_k |w_k Y_i(w_k)| <= terms u
  // Omega max|Y_i|, with max|Y_i| <= k2 = 1.0926 (recursive summation, Higham 2002, eq. 4.4).
  double rounding = 0;
};

OracleSh rect_oracle(const shpack::RectLight& rect, shpack::Point3 probe, int panels);
OracleSh disk_oracle(const shpack::DiskLight& disk, shpack::Point3 probe, int panels);
// The visible part of a sphere of radius R seen from `probe`, integrated over its surface.
OracleSh sphere_surface_oracle(shpack::Point3 centre, double radius, shpack::Point3 probe, int panels);
// A cap of half-angle a about the unit axis d, in local coordinates (u = cos theta', phi').
OracleSh cap_oracle(shpack::Dir3 axis, double half_angle, int panels);
// A zonal function of y, f(y) = upper(y) for y > 0 and lower(y) for y < 0, both polynomials of
// degree <= 1 given as {constant, slope}.
OracleSh zonal_y_oracle(std::array<double, 2> upper, std::array<double, 2> lower, int panels);

// int_{y > 0} f(w) Y_i(w) dw for a smooth f on the upper hemisphere, in (y, phi): composite
// Gauss-Legendre in y, trapezoid in phi.
OracleSh upper_hemisphere_oracle(const std::function<double(double x, double y, double z)>& f, int panels);

}  // namespace shpack_test
