// sphere_map_texels.h (private) - the texel integrals behind project_sphere_map.h.
#pragma once

#include <array>
#include <cstdint>

#include "shpack/project_sphere_map.h"
#include "shpack/sh_basis.h"

namespace shpack::detail {

// int over a texel's part inside the map of the nine basis polynomials P_i(d) dw
// (sh_basis.h, without k_i); element 0 is the solid angle.
using SphereMoments = std::array<double, kShCount>;

// A texel's square in the image plane (project_sphere_map.h): u0 < u1, v0 < v1 (v up), each
// edge coordinate (2k - N)/N correctly rounded, so the squares of mirrored texels are
// exactly mirrored; h = 2/N is the side.
struct TexelSquare {
  double u0, u1, v0, v1, h;
};
TexelSquare sphere_map_texel_square(std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept;

SphereMoments octahedral_texel_moments(const TexelSquare& t) noexcept;    // sphere_map_octahedral.cpp
SphereMoments angular_texel_moments(const TexelSquare& t) noexcept;       // sphere_map_disc.cpp
SphereMoments mirror_ball_texel_moments(const TexelSquare& t) noexcept;   // sphere_map_disc.cpp

// Texels [first, last) of row y of an N x N map with a part of positive area inside it:
// the whole row for octahedral maps; for the disc maps the texels whose nearest point to
// the centre is strictly inside the unit circle (a contiguous run, the disc being convex),
// possibly empty (first == last).
struct RowSpan {
  std::uint32_t first = 0, last = 0;
};
RowSpan sphere_map_row_span(SphereMap map, std::uint32_t n, std::uint32_t y) noexcept;

}  // namespace shpack::detail
