// equirect_oracle.h - brute-force integrals over equirect texels (the test oracle).
//
// A texel (i, j) of a W x H image is the patch theta in [pi j/H, pi (j+1)/H],
// lon in [(0.5 - (i+1)/W) 2 pi, (0.5 - i/W) 2 pi] (docs/conventions.md section 2), with
// direction d = (sin theta cos lon, cos theta, sin theta sin lon) and dw = sin theta dtheta dlon.
//
// Integrals are tensor Gauss-Legendre rules in (theta, lon) - not in cos theta, because the
// odd powers of sin theta = sqrt(1 - mu^2) in x, z, xy, yz are not polynomial in mu and
// converge slowly on pole rows - with the order chosen from the remainder bound
// (gauss_legendre.h): every integrand here (basis, band-limited radiance, direction, each
// times sin theta) is a trigonometric polynomial of frequency <= 3 in theta and <= 2 in lon,
// so the relative quadrature error is below kOracleQuadratureTarget. The basis comes from
// the Legendre route (sh_oracle.h). Nothing here calls shpack's projection.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"
#include "support/rgb_image.h"

namespace shpack_test {

// Relative quadrature error target of the oracle's rules (far below every tolerance that
// uses them; rounding, ~1e-16 relative, dominates).
inline constexpr double kOracleQuadratureTarget = 1e-16;
inline constexpr double kThetaFrequency = 3.0;  // sin theta times a degree-2 trig polynomial
inline constexpr double kLonFrequency = 2.0;

struct Patch {
  double theta0, theta1;  // theta0 < theta1
  double lon0, lon1;      // lon0 < lon1
};

// The patch of texel (i, j), straight from the conventions.
Patch texel_patch(std::uint32_t i, std::uint32_t j, std::uint32_t width, std::uint32_t height);

// The direction (sin theta cos lon, cos theta, sin theta sin lon).
shpack::Dir3 direction_of(double theta, double lon);

// Solid angle of a patch by Gauss-Legendre quadrature of sin theta.
double patch_solid_angle(const Patch& p);

// int over the patch of Y_i (Legendre route), i = 0..8.
std::array<double, 9> patch_basis_integral(const Patch& p);

// int over texel (i, j) of Y_i.
std::array<double, 9> texel_basis_integral(std::uint32_t i, std::uint32_t j, std::uint32_t width,
                                           std::uint32_t height);

// Radiance coefficients of the piecewise-constant image: sum over texels of the texel
// value times its basis integral, accumulated in long double row by row (error
// <= (W + H) 2^-64 sum |terms|, far below the double rounding of each integral).
shpack::ShL2 project_oracle(const RgbImage& image);

// sum_t |v_c,t| Omega_t per channel: int |L_c| dw, the scale of every coefficient's error.
std::array<double, 3> abs_radiance_integral(const RgbImage& image);

// sum_t v_c,t^2 Omega_t per channel: int L_c^2 dw of the piecewise-constant image.
std::array<double, 3> radiance_energy(const RgbImage& image);

// The image whose texel (i, j) holds the average of f over the texel, rounded to float:
// (1/Omega_t) int_t f dw by the same rules. f is called with a unit direction.
using RadianceFunction = std::function<std::array<double, 3>(const shpack::Dir3&)>;
RgbImage render_texel_averages(std::uint32_t width, std::uint32_t height, const RadianceFunction& f);

// The image whose texel (i, j) holds f at the texel centre, rounded to float.
RgbImage render_texel_centres(std::uint32_t width, std::uint32_t height, const RadianceFunction& f);

}  // namespace shpack_test
