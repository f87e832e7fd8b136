// project_cube.h - projection of a cube map (six faces) onto L2 SH.
//
// Contract. The six faces are radiance that is constant over each texel, in Unity's
// CubemapFace order (+X, -X, +Y, -Y, +Z, -Z) with the per-face axes of conventions.h
// (kCubeFaceAxes, D3D convention): texel (x, y) of an N x N face, row 0 at the top, is the
// patch of directions normalize(N_f + a U_f + b V_f) with a in [2x/N - 1, 2(x+1)/N - 1],
// b in [2y/N - 1, 2(y+1)/N - 1] (its centre is a = 2(x + 0.5)/N - 1, b = 2(y + 0.5)/N - 1).
// The result is the radiance coefficients L_c,i = int L_c(w) Y_i(w) dw in Unity's frame
// (sh_basis.h), in double, as for project_equirect (project.h).
//
//             +----+
//             | +Y |               the horizontal cross; each face is upright in its own
//        +----+----+----+----+     (U right, V down) orientation. A cross or a strip is six
//        | -X | +Z | +X | -Z |     sub-views of one image with no copy, and a face stored
//        +----+----+----+----+     upside down (the vertical cross's -Z) is a view with
//             | -Y |               negative strides (image_view.h).
//             +----+
//
// Faces: any ImageView that resolve_view accepts (image_view.h: F32 or F16, 1 or more
// channels, any byte strides), all N x N with the same N >= 1. A 1 x 1 cube is six
// uniform faces.
//
// Methods (ProjectOptions::method):
//  - SamplingMethod::Exact (default): each of the 9 basis polynomials is integrated over each
//    texel in closed form (derivation in lib/src/cube_moments.h), so the projection of the
//    piecewise-constant cube has no quadrature error: a bright texel contributes exactly its
//    own integral, whatever N.
//  - SamplingMethod::Center: the basis at the texel centre times the texel's exact solid angle; its
//    error falls as h^2 on smooth input.
//
// Values: as project_equirect. NaN/Inf texels fail with Errc::NonFiniteTexel (x, y and
// face of the first one in face, then row-major order) under NonFinite::Error, or count as
// 0 under NonFinite::Zero; negative texels are kept or clamped to 0 (Negative). Counts go to
// ProjectStats, whose first_nonfinite_x/y are face-local (ProjectStats has no face field;
// under NonFinite::Error the Status names the face).
//
// Numerics. A texel's weights are its exact integrals up to about 10 u / h of its solid
// angle (u = 2^-53, h = 2/N): 5e-16 at N = 1, 4e-13 at N = 1024, 1.6e-12 at N = 4096
// (cube_moments.h; measured in tests/projection/project_cube_test.cpp). Texel sums are double;
// rows are combined with Neumaier's compensated sum in fixed tiles of kTileRows face rows
// (the same rows of all six faces, which share the texel weights), reduced in tile, then
// face order: the result is bit-identical for any thread count.
//
// Memory. Allocates, once per call: per worker at most 27 N doubles (two rows of edge
// terms and one row of texel weights) and 3 N floats (one face row as planes), and 2.7 KiB
// per tile of partial sums. Worker threads when ProjectOptions::threads != 1. On any error,
// `radiance` and `stats` are left as they were.
#pragma once

#include <array>
#include <cstdint>

#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"

namespace shpack {

inline constexpr int kCubeFaceCount = 6;

// Errors: Errc::BadView (a face fails resolve_view, is not square, or differs in size from
// face 0; Status::face says which), Errc::InvalidArgument (unknown method),
// Errc::NonFiniteTexel, Errc::OutOfMemory.
Status project_cube(const std::array<ImageView, kCubeFaceCount>& faces, const ProjectOptions& options,
                    ShL2& radiance, ProjectStats* stats = nullptr) noexcept;

// What project_cube adds to the radiance coefficients per unit of radiance in texel (x, y)
// of `face` of an N x N cube: int_texel Y_i dw (SamplingMethod::Exact), or Y_i(centre) times the
// texel's solid angle (SamplingMethod::Center); out[0] / k0 is the texel's solid angle. The same
// arithmetic as project_cube, so a cube that is 1 in that texel and 0 elsewhere projects
// to exactly these numbers. Errors: Errc::InvalidArgument (size 0, x or y >= size, face or
// method out of range).
Status cube_texel_basis_integrals(std::uint32_t size, CubeFace face, std::uint32_t x, std::uint32_t y,
                                  SamplingMethod method, std::array<double, kShCount>& out) noexcept;

}  // namespace shpack
