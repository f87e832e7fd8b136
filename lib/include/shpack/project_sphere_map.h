// project_sphere_map.h - projection onto L2 SH of the square images that hold the whole
// sphere in one chart: octahedral maps, angular maps (light probes) and mirrored balls.
//
// Image plane. An N x N image, texel (x, y) with row 0 at the top, is the square
// [-1, 1]^2 of coordinates (u, v), u to the right and v UP: texel (x, y) covers
// u in [2x/N - 1, 2(x+1)/N - 1], v in [1 - 2(y+1)/N, 1 - 2y/N] (centre u = 2(x + 0.5)/N - 1,
// v = 1 - 2(y + 0.5)/N). Every direction d is in Unity's frame (conventions.h). Each map is
// a view of the sphere with the same handedness as a cube face (conventions.h): facing the
// direction shown at the image centre, the image's right is on the viewer's right.
//
// SphereMap::Octahedral - Unity's octahedral encoding, UnpackNormalOctQuadEncode of the
// SRP Core ShaderLibrary Packing.hlsl (after Cigolle et al., "A Survey of Efficient
// Representations for Independent Unit Vectors", JCGT 3(2), 2014):
//
//   +-----------------+   p = (u, v, 1 - |u| - |v|) in the diamond |u| + |v| <= 1 (z >= 0);
//   | -Z    +Y    -Z  |   outside it the corners fold over:
//   |     /    \      |   p = (sgn u (1 - |v|), sgn v (1 - |u|), 1 - |u| - |v|)   (z < 0);
//   | -X    +Z    +X  |   d = p / |p|. Centre +Z, middle of the top edge +Y, of the right
//   |     \    /      |   edge +X; the four corners -Z. Each of the 8 triangles maps
//   | -Z    -Y    -Z  |   linearly onto one face of the octahedron |x| + |y| + |z| = 1,
//   +-----------------+   whose plane is n.p = 1 with n = p_u x p_v, so
//   dw = |p . (p_u x p_v)| / |p|^3 du dv = du dv / |p|^3.
//
// SphereMap::Angular - the "angular map" of P. Debevec's light probe gallery
// (www.pauldebevec.com/Probes): "the center of the image is straight forward, the
// circumference of the image is straight backwards, and the horizontal line through the
// center linearly maps azimuthal angle to pixel coordinate"; the direction is (0, 0, -1)
// (forward in that right-handed, +Y-up frame) turned by phi = pi sqrt(u^2 + v^2) towards
// the azimuth atan2(v, u). Mapped to Unity's frame by d_unity = (x, y, -z) (conventions.h):
//
//        +Y                 rho = sqrt(u^2 + v^2) <= 1 (texels outside the disc are
//     .-----.               ignored), psi = pi rho is the angle from +Z:
//    /  +Z   \  +X          d = (sin psi u/rho, sin psi v/rho, cos psi).
//    \ (fwd) /              Centre +Z, rim -Z, right +X, top +Y.
//     '-----'  rim: -Z      dw = sin psi dpsi dalpha = (pi sin(pi rho) / rho) du dv.
//
// (The same page writes the inverse as r = (1/pi) acos(D_z) / sqrt(D_x^2 + D_y^2), which
// puts +z at the centre, as do Radiance's angmap.cal and HDRView; read in a right-handed
// frame, that version is the z mirror image of the one above. shpack follows the page's
// text, the reading under which the map is an unmirrored view.)
//
// SphereMap::MirrorBall - an orthographic photograph of a mirrored ball, the camera looking
// along +Z. The ball's silhouette is the unit disc; at (u, v) its surface normal is
// n = (u, v, -s), s = sqrt(1 - u^2 - v^2), and the ball shows the reflected view ray:
//
//     .-----.  rim: +Z      d = e - 2 (n.e) n with e = (0, 0, 1):
//    /  -Z   \  +X          d = (2us, 2vs, 2 rho^2 - 1). Centre -Z (back at the camera),
//    \(camera)/             rim +Z (straight ahead, behind the ball), right +X, top +Y.
//     '-----'               psi = 2 asin(rho) is the angle from -Z, and
//   dw = sin psi dpsi dalpha = 4 rho drho dalpha = 4 du dv: the solid angle of a texel is
//   4 times its area inside the disc (closed form, used as such).
//
// SamplingMethod (SamplingMethod::Exact only). Each texel's nine integrals int P_i(d) dw (times k_i) over
// its part inside the map are computed by Gauss-Legendre quadrature of the basis times the
// exact Jacobian, in coordinates where the integrand is analytic (lib/src/sphere_map_*.cpp
// derive them): octahedral texels are cut along the folds |u| + |v| = 1, u = 0, v = 0; disc
// texels that reach the rim are integrated in the chart v = sqrt(1 - u^2) sin(phi) (the
// rim is phi = +-pi/2, and s = sqrt(1 - u^2) cos(phi) is analytic), the outer variable
// substituted at the square-root points of the limits (u = sigma -+ tau^2, or
// u = sigma -+ D cosh^2 t for two such points D apart). The orders come from the
// Gauss-Legendre remainder bounds (lib/src/gauss_legendre.h) evaluated for 1e-20 of the
// integrand's scale: four decades of margin, because for the substituted integrands the
// bounds are estimates (at 1e-16 the measured errors reached 2e-11). Measured against an
// independent oracle (tests/projection/project_sphere_map_test.cpp, sizes 1 to 255), every
// texel's integrals are within 3e-15 of the largest texel solid angle of the image (the
// test's bound is 1e-12), and the solid angles of each map sum to 4 pi within 5e-15. The
// mirror ball's solid angles are the closed form above. There is no closed form behind the
// other integrals, so unlike project_cube this is accurate quadrature, not exact.
//
// Values: as project_equirect (NonFinite, Negative, ProjectStats), over the texels that have
// a part of positive area inside the map; the corners of angular and mirror-ball images are
// never read or counted (they often hold the photograph's background).
//
// Numerics and memory: texel sums in double per row, rows combined with Neumaier sums in
// fixed tiles of kTileRows rows reduced in tile order: bit-identical for any thread count.
// Allocates one row of floats (3 N) per worker and the tiles' partial sums; worker threads
// when ProjectOptions::threads != 1. On error `radiance` and `stats` are left as they were.
#pragma once

#include <array>
#include <cstdint>

#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

enum class SphereMap : std::uint8_t { Octahedral, Angular, MirrorBall };

// Errors: Errc::BadView (the view fails resolve_view or is not square), Errc::InvalidArgument
// (a method other than SamplingMethod::Exact, or an unknown map), Errc::NonFiniteTexel (x, y of the
// first one in row-major order), Errc::OutOfMemory.
Status project_sphere_map(const ImageView& image, SphereMap map, const ProjectOptions& options,
                          ShL2& radiance, ProjectStats* stats = nullptr) noexcept;

// What project_sphere_map adds per unit of radiance in texel (x, y) of an N x N map:
// int Y_i dw over the texel's part inside the map (out[0] / k0 is its solid angle; all zero
// for a texel outside the disc). The same arithmetic as project_sphere_map. Errors:
// Errc::InvalidArgument (size 0, x or y >= size, unknown map).
Status sphere_map_texel_basis_integrals(std::uint32_t size, SphereMap map, std::uint32_t x,
                                        std::uint32_t y, std::array<double, kShCount>& out) noexcept;

}  // namespace shpack
