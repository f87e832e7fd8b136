// layout_render.h - an analytic environment rendered by the test code into every layout,
// with what the tolerance of its projection needs (layout_proof_test.cpp).
//
// The environment: f_c(d) = sum_i b_c,i Y_i(d) + L_c exp(kappa (a.d - 1)) + K_c [s.d >= cos r]:
// a random band-limited part (support/band_limited.h), a small bright lobe (a von Mises-Fisher
// lobe of angular width ~1/sqrt(kappa) about the axis a) and a small bright disc (a spherical
// cap of constant radiance K_c and angular radius r about the axis s, hard-edged like a sun).
// Its radiance coefficients have a closed form. Both the lobe and the cap are zonal, h(a.d),
// and the Funk-Hecke theorem gives, for every spherical harmonic Y of degree l (so for each
// real Y_lm of sh_basis.h), int h(a.d) Y(d) dw = lambda_l Y(a) with
// lambda_l = 2 pi int_-1^1 h(t) P_l(t) dt.
// The coefficients are b_c,i + L_c lambda_l Y_i(a) + K_c mu_l Y_i(s). For the lobe,
//   lambda_0 = 2 pi (1 - e) / kappa,                       e = exp(-2 kappa)
//   lambda_1 = 2 pi (1/kappa - 1/kappa^2 + e (1/kappa + 1/kappa^2))
//   lambda_2 = 2 pi (1/kappa - 3/kappa^2 + 3/kappa^3 - e (1/kappa + 3/kappa^2 + 3/kappa^3))
// (integration by parts of t^k exp(kappa t); all terms positive for kappa > 3: no cancellation).
// For the cap, h = [t >= c] with c = cos r, so mu_l = 2 pi int_c^1 P_l(t) dt:
//   mu_0 = 2 pi (1 - c)        = 2 pi 2 sin^2(r/2)      (P_0 = 1)
//   mu_1 = 2 pi (1 - c^2) / 2  = pi sin^2 r             (P_1 = t)
//   mu_2 = 2 pi (c - c^3) / 2  = pi c sin^2 r           (P_2 = (3t^2 - 1)/2: [(t^3 - t)/2]_c^1)
// written with sines so that a small r loses nothing to cancellation in 1 - c.
//
// Rendering: each texel holds the average of f over its patch of the sphere (its integral
// over the texel divided by its solid angle), by composite Gauss-Legendre in the layout's own
// coordinates with its Jacobian (equirect: sin(theta) dtheta dlon; cube: da db / r^3;
// sphere maps: du dv times their Jacobian, or the oracle of support/sphere_map_oracle.h for
// texels cut by a fold or the rim); rounded to float.
//
// Tolerance. A texel holding the exact average f_t of f makes the projection's error
//   sum_t int_t (f - f_t)(Y_i - Y_i,t) dw   (Y_i,t the average of Y_i over t),
// which is at most sum_t Omega_t osc_t(f) osc_t(Y_i) <= sum_t Omega_t D_t^2 G_t(f) G_l, with D_t
// a bound on the texel's geodesic diameter, G_t(f) on |grad f| over it, and
// G_l = sqrt(l (l + 1) (2l + 1) / (4 pi)) >= |grad Y_lm| (the addition theorem for gradients:
// sum_m |grad Y_lm|^2 = l (l + 1) (2l + 1) / (4 pi)). Rounding the averages to float adds at
// most 2^-24 sum_t |f_t| Omega_t max|Y_i|, max|Y_i| <= sqrt(5 / (4 pi)).
// That gradient bound is for the smooth part (band-limited and lobe); the projection is
// linear, so the cap's error adds to it, and the cap's step is bounded texel by texel: a texel the cap's edge does not cross holds the cap exactly (every quadrature node
// of it sees the same constant, 0 or K_c), so it adds no error; on a texel the edge crosses,
// the stored cap value is a weighted mean of 0 and K_c (positive weights), so it differs from
// the cap by at most K_c everywhere on the texel, and its error is at most
// int_t K_c |Y_i| dw <= K_c max|Y_i| Omega_t, whatever the accuracy of the rendering there.
// In all: K_c max|Y_i| (sum of Omega_t over the cut texels), which falls like the width of the
// ring of cut texels, O(h). A texel is counted as cut unless its direction's angle from s is
// more than D_t away from r (every point of the texel is within D_t of its direction), which
// over-counts the ring by a texel's diameter on each side but never misses a cut texel.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/cube_layout.h"
#include "shpack/project_sphere_map.h"
#include "shpack/sh_basis.h"

namespace shpack_layout_test {

struct AnalyticEnvironment {
  shpack::ShL2 band_limited;  // b_c,i
  shpack::Dir3 axis;          // a, unit
  double kappa = 0;
  std::array<double, 3> lobe{};  // L_c
  shpack::Dir3 cap_axis;          // s, unit
  double cap_radius = 0;          // r, radians
  std::array<double, 3> cap{};    // K_c

  std::array<double, 3> operator()(const shpack::Dir3& d) const;
  bool in_cap(const shpack::Dir3& d) const;
  shpack::ShL2 exact() const;  // the closed form above
  // A bound on |grad f_c| of the smooth part (band-limited and lobe) over directions whose
  // angle from the lobe's axis is in [lo, hi].
  double gradient_bound(int channel, double lo, double hi) const;
};

// A random band-limited part (support/band_limited.h), a lobe of kappa = 400 (width
// ~3 degrees) that is 40 times brighter than the mean, about a fixed, asymmetric axis, and a
// hard-edged disc of radius 3 degrees, about 20 times brighter than the mean, about another.
AnalyticEnvironment make_environment(std::uint64_t seed);

struct Texel {
  std::array<double, 3> average{};  // before float rounding
  double cap_cover = 0;             // the part of `average` that is the cap: average_c = smooth_c + K_c cap_cover
  double solid_angle = 0;
  double diameter = 0;      // D_t, a bound on the geodesic diameter
  shpack::Dir3 direction;   // the normalised first moment: within D_t of every point of the texel
};

struct Rendering {
  std::uint32_t width = 0, height = 0;
  std::vector<float> rgb;     // the image, row-major from the top
  std::vector<Texel> texels;  // the texels that are projected
};

// `fine` asks for twice the subdivision and four more nodes: comparing the two measures the
// rendering's own quadrature error.
Rendering render_equirect(std::uint32_t width, std::uint32_t height, const AnalyticEnvironment& f, bool fine = false);
std::array<Rendering, 6> render_cube_faces(std::uint32_t n, const AnalyticEnvironment& f, bool fine = false);
// The six faces placed in one image as `layout` places them (cube_layout.h); unused cells 0.
Rendering assemble_cube_image(shpack::CubeLayout layout, const std::array<Rendering, 6>& faces);
Rendering render_sphere_map(shpack::SphereMap map, std::uint32_t n, const AnalyticEnvironment& f, bool fine = false);

// Whether the cap's edge may cross the texel (the classification above).
bool cut_by_cap_edge(const Texel& t, const AnalyticEnvironment& f);
// The sum of Omega_t over the texels cut by the cap's edge.
double cut_solid_angle(const std::vector<Texel>& texels, const AnalyticEnvironment& f);

// The tolerance above for coefficient i of channel c, over the rendered texels: smooth
// part, cap edge and float rounding.
double projection_tolerance(const std::vector<Texel>& texels, const AnalyticEnvironment& f, int channel, int i);

}  // namespace shpack_layout_test
