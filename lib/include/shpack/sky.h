// sky.h - the Preetham clear sky as an environment: its radiance and its L2 projection.
//
// [1] A. J. Preetham, P. Shirley, B. Smits, "A Practical Analytic Model for Daylight",
//     SIGGRAPH 1999: the Perez distribution F(theta, gamma) = (1 + A e^(B / cos theta))
//     (1 + C e^(D gamma) + E cos^2 gamma), its coefficients linear in the turbidity T
//     (Appendix A.2), and the zenith luminance Y_z (kcd/m^2) and chromaticity x_z, y_z
//     (Appendix A.2); each of Y, x, y is zenith * F(theta, gamma) / F(0, theta_s).
// [2] IEC 61966-2-1 (sRGB): CIE XYZ to linear Rec. 709 RGB, D65.
//
// theta is a direction's angle from the zenith (+Y), gamma its angle from the sun. The
// model holds above the horizon; below it the sky shows `ground`. Radiance is in kcd/m^2
// (Preetham's unit) times `intensity`, as linear Rec. 709 RGB from xyY -> XYZ -> RGB [2].
// The sun's disc itself is not part of the sky model: add it as a directional light.
#pragma once

#include "shpack/lights.h"

namespace shpack {

struct PreethamSky {
  Dir3 sun;               // towards the sun; its elevation must be >= 0 (normalised here)
  double turbidity = 3;   // T in [1.7, 10]: 2 very clear, 3 clear, 6 hazy
  Rgb ground{};           // radiance below the horizon
  double intensity = 1;   // factor on the sky's radiance
};

// Radiance arriving from unit direction d. Errc::InvalidArgument for parameters out of
// their domain (what says which).
Status preetham_radiance(const PreethamSky& sky, Dir3 d, Rgb& radiance) noexcept;

// Adds the sky's radiance coefficients: above the horizon by a product rule, Gauss-Legendre
// in cos theta (kPreethamThetaNodes) times the trapezoid rule in the azimuth
// (kPreethamPhiNodes, spectrally accurate for the periodic integrand); the ground half
// exactly (add_hemisphere_light). The integrand is smooth (e^(B / cos theta) vanishes with
// all its derivatives at the horizon for B < 0, which T >= 1.7 guarantees). `error_estimate`,
// if given, receives max |rule - rule at half the nodes| relative to |L_0|: a bound on the
// error once convergence is geometric (tests/lights measure it against brute force).
inline constexpr int kPreethamThetaNodes = 64;
inline constexpr int kPreethamPhiNodes = 192;
Status add_preetham_sky(const PreethamSky& sky, ShL2& radiance, double* error_estimate = nullptr) noexcept;

}  // namespace shpack
