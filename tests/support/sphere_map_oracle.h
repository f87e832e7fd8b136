// sphere_map_oracle.h - the sphere maps of project_sphere_map.h, transcribed independently
// for the tests: the direction of each image point, and slow integrals over texels.
//
// Disc maps (angular, mirror ball): polar coordinates about the image centre. The ray at
// azimuth alpha (from +u towards +v) meets the texel's square in [rho_in, rho_out] (slab
// intersection), clipped to the disc; along it dw = sin(psi) dpsi dalpha with psi the angle
// from the map's centre direction (angular: psi = pi rho from +Z; mirror ball:
// psi = 2 asin(rho) from -Z). The inner integral of Y_i sin(psi) over psi is a trigonometric
// polynomial of degree <= 3, integrated by 20-point Gauss-Legendre (its remainder bound,
// gauss_legendre.h, is below 1e-25 on psi ranges <= pi). The outer integral over alpha is
// cut at the corner azimuths and where the edges cross the rim; between cuts it is analytic
// except, for the mirror ball, a (alpha - alpha*)^(3/2) term at a rim crossing alpha* (psi
// has a square-root point at rho = 1). So each half of a piece is integrated by two 20-point
// rules, or, for the mirror ball at a rim crossing, graded geometrically towards it (16
// halvings, 16 points each: each graded interval is one half-length away from the singular
// end, ellipse parameter 5.8, error < 1e-24 of its part; the last, 2^-16 of the piece, holds
// the t^(3/2) term's 2^-40 of it, integrated by the same rule to ~1e-6 of that).
// Accumulated in long double.
//
// Octahedral maps: the texel's square is clipped (Sutherland-Hodgman) against each of the
// eight triangles of the unfolded octahedron, each clipped polygon fan-triangulated, and each
// triangle split into 16 and integrated by a 12 x 12 collapsed (Duffy) Gauss-Legendre rule
// of Y_i(p/|p|)/|p|^3, p the point of the octahedron. Two closed forms check it: the solid
// angle of a planar polygon seen from the origin (Van Oosterom & Strackee, IEEE Trans.
// Biomed. Eng. 30(2), 1983: tan(Omega/2) = |a.(b x c)| / (abc + (a.b)c + (a.c)b + (b.c)a) per
// triangle) and the first moment int d dw = (1/2) sum_k Theta_k n_k over the edges of the
// spherical polygon (J. Arvo, "Applications of Irradiance Tensors to the Simulation of
// Non-Lambertian Phenomena", SIGGRAPH 1995), n_k the unit normal of the edge's great circle,
// Theta_k its arc, vertices counter-clockwise seen from outside.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "shpack/conventions.h"
#include "shpack/project_sphere_map.h"

namespace shpack_test {

// The direction of image point (u, v) (v up), or false outside the map's disc.
bool sphere_map_direction(shpack::SphereMap map, double u, double v, shpack::Dir3& d);

// The image point of direction d (unit), in [-1, 1]^2 (v up): the inverse of the above.
void sphere_map_point(shpack::SphereMap map, const shpack::Dir3& d, double& u, double& v);

// The rules above as weighted directions: sink(d, w) for each node of texel (x, y) of an
// N x N map, so that sum w g(d) is int over the texel of g dw for any smooth g. `refine`
// splits every piece and psi range (disc maps) or triangle (octahedral, into 4 per doubling)
// further, for integrands that vary faster than the basis.
using DirectionSink = std::function<void(const shpack::Dir3& d, long double weight)>;
void sphere_map_texel_integrate(shpack::SphereMap map, std::uint32_t n, std::uint32_t x, std::uint32_t y,
                                const DirectionSink& sink, int refine = 1);

// int Y_i dw over texel (x, y) of an N x N map (i = 0..8) and its solid angle (index 9).
std::array<long double, 10> sphere_map_texel_oracle(shpack::SphereMap map, std::uint32_t n,
                                                    std::uint32_t x, std::uint32_t y);

// Octahedral texel (x, y): its solid angle and first moment int d dw in closed form.
struct OctahedralClosedForm {
  long double solid_angle = 0;
  std::array<long double, 3> first_moment{};  // x, y, z
};
OctahedralClosedForm octahedral_texel_closed_form(std::uint32_t n, std::uint32_t x, std::uint32_t y);

}  // namespace shpack_test
