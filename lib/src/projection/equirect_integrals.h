// equirect_integrals.h (private) - closed-form integrals over latitude-longitude patches, for
// the brute-force reference of `shpack preview` and the sun of `convert --extract-sun`.
//
// A patch theta in [t0, t1] (polar angle from +Y), lon in [p0, p1] (conventions.h) has the
// solid angle solid * length and the direction integral int w dw =
// (sin2 * cos, sin_cos * length, sin2 * sin), with the factors below.
#pragma once

#include <cmath>

#include "shpack/conventions.h"

namespace shpack::detail {

// Per unit of longitude, over [t0, t1].
struct ThetaIntegrals {
  double solid;    // int sin t dt = cos t0 - cos t1, cancellation-free
  double sin2;     // int sin^2 t dt = (t1 - t0)/2 - (sin 2t1 - sin 2t0)/4
  double sin_cos;  // int sin t cos t dt = (sin^2 t1 - sin^2 t0)/2
};
inline ThetaIntegrals theta_integrals(double t0, double t1) {
  const double s0 = std::sin(t0), s1 = std::sin(t1);
  return {2.0 * std::sin(0.5 * (t0 + t1)) * std::sin(0.5 * (t1 - t0)),
          0.5 * (t1 - t0) - 0.25 * (std::sin(2.0 * t1) - std::sin(2.0 * t0)), 0.5 * (s1 * s1 - s0 * s0)};
}

// Over [p0, p1]: int dp, int cos p dp, int sin p dp.
struct LonIntegrals {
  double length, cos, sin;
};
inline LonIntegrals lon_integrals(double p0, double p1) {
  return {p1 - p0, std::sin(p1) - std::sin(p0), std::cos(p0) - std::cos(p1)};
}

// int w dw over the patch.
inline Dir3 direction_integral(const ThetaIntegrals& t, const LonIntegrals& p) {
  return {t.sin2 * p.cos, t.sin_cos * p.length, t.sin2 * p.sin};
}

}  // namespace shpack::detail
