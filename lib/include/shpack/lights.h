// lights.h - analytic lights: the radiance SH of each light as a probe sees it.
//
// References (cited below as [n]):
//  [1] P.-P. Sloan, "Stupid Spherical Harmonics (SH) Tricks", GDC 2008 (zonal harmonics of a
//      cone, rotation of zonal functions: L_lm = sqrt(4 pi/(2l+1)) z_l Y_lm(d)).
//  [2] J. Arvo, "Applications of Irradiance Tensors to the Simulation of Non-Lambertian
//      Phenomena", SIGGRAPH 1995 (moments of a spherical polygon by boundary integrals).
//  [3] A. van Oosterom, J. Strackee, "The Solid Angle of a Plane Triangle", IEEE Trans.
//      Biomed. Eng. 30(2), 1983: tan(Omega/2) = a.(b x c) / (1 + a.b + b.c + c.a).
//  [4] J. Wang, R. Ramamoorthi, "Analytic Spherical Harmonic Coefficients for Polygonal Area
//      Lights", SIGGRAPH 2018 (the same boundary-integral idea for every band; for l <= 2 it
//      reduces to [2]).
//  [5] L. N. Trefethen, J. A. C. Weideman, "The Exponentially Convergent Trapezoidal Rule",
//      SIAM Review 56(3), 2014, Thm 3.2 (error of the periodic trapezoid rule).
//  [6] Khronos, KHR_lights_punctual, "Inner and Outer Cone Angles" (spot falloff).
//
// Every function ADDS the radiance coefficients L_c,i = int L_c(w) Y_i(w) dw of one light,
// as seen from the probe, to a caller-owned ShL2 (sh_basis.h; Unity's frame, conventions.h).
// Nothing is allocated, nothing throws; on an error `radiance` is left untouched. Colours are
// linear RGB. Units: radiance W sr^-1 m^-2, irradiance W m^-2, intensity W sr^-1 (or the
// photometric counterparts throughout: the maths is linear).
//
// Physical normalisation, as DirectXMath's SHMath states it: a light of irradiance E at
// normal incidence lights a white Lambertian surface facing it to exit radiance E/pi; that
// is what Unity's ShadeSH9 returns for the surface (times 17/16 for a delta light: the L2
// truncation of the cosine lobe gives sum_l (A_l/pi)(2l+1)/(4 pi) = 17/(16 pi) at the peak).
//
// Cancellation. Half-angles enter as cos a and as 1 - cos a = 2 sin^2(a/2); nothing
// switches to another formula at small sizes, so a light of zero angular size gives the
// delta exactly and a tiny one is accurate to rounding.
//
// Errors: Errc::InvalidArgument (what says which parameter) for a non-finite value, a zero
// direction, a negative colour, a size out of its domain; Errc::ProbeInsideLight when the
// probe lies inside (or on) the light's volume or at a point light's position.
#pragma once

#include <array>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

using Rgb = std::array<double, kChannelCount>;  // linear R, G, B

struct Point3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Point3&, const Point3&) = default;
};

// Directional light (the sun): light arriving from direction `towards_light` (any non-zero
// length; normalised here) with irradiance E at normal incidence, from a uniform disc of
// angular diameter 2a (0 <= 2a < pi; 0 is a delta, the sun is 0.53 degrees).
//  - a = 0: L_i = E Y_i(d)                           (docs/conventions.md section 5)
//  - a > 0: a cap of half-angle a and radiance L = E / (pi sin^2 a) (irradiance of a cap at
//    normal incidence is L pi sin^2 a). Its zonal integrals [1] are
//      2 pi int_{cos a}^1 P_l(t) dt = 2 pi (1 - cos a), pi sin^2 a, pi cos a sin^2 a,
//    so L_i = E Y_i(d) g_l with g_0 = 2/(1 + cos a) = 1/cos^2(a/2), g_1 = 1, g_2 = cos a:
//    the delta's coefficients, shaded by the disc's size, and exactly the delta at a = 0.
Status add_directional_light(Dir3 towards_light, double angular_diameter, const Rgb& irradiance,
                             ShL2& radiance) noexcept;

// A cone of uniform radiance L about `axis`, half-angle a in [0, pi]:
//   L_i = L Y_i(d) {4 pi sin^2(a/2), pi sin^2 a, pi cos a sin^2 a}_l       [1]
// (cap integral 2 pi (1 - cos a) = 4 pi sin^2(a/2)). a = pi is the uniform sphere.
Status add_cone_light(Dir3 axis, double half_angle, const Rgb& radiance, ShL2& out) noexcept;

// Point light of intensity I at `position`: irradiance I / r^2 at normal incidence from the
// direction d = (position - probe) / r, a delta: L_i = (I / r^2) Y_i(d). A light of power
// (flux) P radiating evenly has I = P / (4 pi). ProbeInsideLight if probe == position.
Status add_point_light(Point3 position, const Rgb& intensity, Point3 probe, ShL2& radiance) noexcept;

// Sphere light: a Lambertian sphere of radius R > 0 and uniform radiance L, centre at distance
// r > R, given by its intensity I = pi R^2 L (its power is 4 pi I, as a point light's). It
// covers the cap of half-angle a = asin(R/r) about d, and with E = I / r^2 = L pi sin^2 a
// its coefficients are those of add_directional_light's disc:
//   L_i = (I / r^2) Y_i(d) {2 / (1 + cos a), 1, cos a}_l,  cos a = sqrt((r - R)(r + R)) / r,
// which tends to the point light as R -> 0 (the difference is O(R^2 / r^2)).
// ProbeInsideLight if r <= R. R = 0 is the point light.
Status add_sphere_light(Point3 centre, double radius, const Rgb& intensity, Point3 probe,
                        ShL2& radiance) noexcept;

// Spot light: a point light of on-axis intensity I at `position`, pointing along `axis`,
// whose intensity towards the probe is I f(cos t), t the angle between the axis and the
// direction from the light to the probe, with KHR_lights_punctual's falloff [6]:
//   f = 1 inside the inner cone (t <= inner), 0 outside the outer cone (t >= outer), and in
//   between s^2 with s = (cos t - cos outer) / (cos inner - cos outer).
// 0 <= inner <= outer <= pi (half-angles, radians); inner == outer is a hard edge. Still a
// delta as the probe sees it: L_i = (I f / r^2) Y_i(d).
struct SpotLight {
  Point3 position;
  Dir3 axis;                // direction the spot points to (normalised here)
  double inner_angle = 0;   // half-angle of full intensity
  double outer_angle = 0;   // half-angle beyond which it is dark
};
Status add_spot_light(const SpotLight& spot, const Rgb& intensity, Point3 probe,
                      ShL2& radiance) noexcept;
// f(cos t) above, for the same parameters (the engine uses it for visibility planning).
double spot_falloff(const SpotLight& spot, double cos_t) noexcept;

// Rectangular area light, one-sided, uniform radiance L: centre, unit `right` and `up`
// (orthogonal, normalised here), width along right, height along up, emitting towards
// normal = right x up (the algebraic cross product: right = +X, up = +Y emits along +Z, a
// Unity transform's forward). A probe behind it or in its plane receives nothing.
//
// Closed form after Arvo [2] (the l <= 2 case of [4]). For a spherical region A bounded by
// great-circle arcs a_k -> b_k (unit vectors, A on the left), the surface divergence theorem
// applied to (w.w')^(n-1) grad(w.w') gives (n+1) tau_n = (n-1) tau_{n-2} - boundary terms,
// tau_n = int_A (w.w')^n dw'. For n = 0, 1, 2:
//   Omega = sum of van Oosterom-Strackee triangle solid angles [3] over a fan,
//   int_A w dw = (1/2) sum_k Theta_k n_k,        n_k = a_k x b_k / |a_k x b_k|,
//   int_A w w^T dw = (1/3) [ Omega I + sum_k sym((a_k x b_k) (a_k + b_k)^T) / (1 + a_k.b_k) ]
// (the edge term (w.n)(w.a sin T + w.e (1 - cos T)) simplified with tan(T/2) = (1 - cos T) /
// sin T; 1 + a.b = |a + b|^2 / 2 has no cancellation). The 9 coefficients are these moments
// times k_i (sh_basis.h). Exact up to rounding.
struct RectLight {
  Point3 centre;
  Dir3 right, up;
  double width = 0, height = 0;  // > 0
};
Status add_rect_light(const RectLight& rect, const Rgb& radiance, Point3 probe,
                      ShL2& radiance_sh) noexcept;

// Disk area light, one-sided, uniform radiance L: centre, unit normal (the side it emits
// to), radius R > 0. The moments of add_rect_light are boundary integrals; on the circle
// B(t) = centre + R (cos t e1 + sin t e2) they are smooth 2 pi-periodic integrals in t
//   Omega      = int (R^2 + R q.e(t)) / (|X| (|X| + h)) dt       (= int (1 - cos theta) dphi
//                                                                  about the plane's normal)
//   int w dw   = -(1/2) int X x X' / |X|^2 dt,
//   int w w^T  = (1/3) [ Omega I - int sym(X (X x X')^T) / |X|^3 dt ]
// (X = B - probe, h the probe's height over the plane, q the disk centre minus the probe's
// foot point; the minus signs: t runs clockwise as the probe sees it), computed with the
// N-point trapezoid rule, whose error for an integrand analytic in |Im t| < s is
// O(exp(-s N)) [5]. Here s = acosh((h^2 + |q|^2 + R^2) / (2 R |q|)) (the zeros of |X|^2):
// N is the smallest multiple of 8 >= max(16, kDiskStripProduct / s), capped at kDiskMaxNodes,
// so that the predicted exp(-s N) is below 1e-17 wherever the cap is not reached (probes
// within about R/100 of the disk's rim plane); tests/lights measures the error against brute
// force. `nodes_used` and `error_estimate` (|I_N - I_{N/2}| relative to Omega, a bound on the
// error once convergence is geometric) report it.
inline constexpr double kDiskStripProduct = 40.0;
inline constexpr int kDiskMaxNodes = 8192;
struct DiskLight {
  Point3 centre;
  Dir3 normal;
  double radius = 0;  // > 0
};
struct DiskQuadrature {
  int nodes_used = 0;
  double error_estimate = 0;
};
Status add_disk_light(const DiskLight& disk, const Rgb& radiance, Point3 probe, ShL2& radiance_sh,
                      DiskQuadrature* quadrature = nullptr) noexcept;

// Hemisphere light: radiance `sky` for directions above the horizon (y > 0), `ground` below.
// Its even part is the constant (sky + ground)/2 and its odd part has no band 2, so exactly
//   L_0 = 2 pi k0 (sky + ground),  L_1 (y) = pi k1 (sky - ground),  all others 0.
Status add_hemisphere_light(const Rgb& sky, const Rgb& ground, ShL2& radiance) noexcept;

// Ambient light: uniform radiance L in every direction: L_0 = 4 pi k0 L = 2 sqrt(pi) L; a white
// surface then reflects exactly L, and Unity-form sh[c][0] = L (conventions.md section 5).
Status add_ambient_light(const Rgb& radiance, ShL2& out) noexcept;

// Gradient sky (procedural environment): radiance horizon + (zenith - horizon) y above the
// horizon (y = the direction's up component), `ground` below. A zonal function f(y) about +Y
// has, with m_k = 2 pi int_{-1}^{1} f(y) y^k dy and the azimuthal means of z^2 and x^2,
// (1 - y^2)/2:  L_0 = k0 m_0, L_1 = k1 m_1, L_6 = -(k3/2)(3 m_2 - m_0),
// L_8 = -(k4/2)(3 m_2 - m_0), all others 0. Exact.
Status add_gradient_sky(const Rgb& zenith, const Rgb& horizon, const Rgb& ground,
                        ShL2& radiance) noexcept;

}  // namespace shpack
