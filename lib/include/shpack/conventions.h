// conventions.h - every geometric convention of shpack, stated once.
//
// Normative source: docs/conventions.md.
// tests/projection/conventions_test.cpp pins each statement below with a test.
//
// Frame. All SH that shpack computes are in Unity's world frame: LEFT-handed, +X right,
// +Y up, +Z forward (the outputs for other engines are mapped from it by engine_frame.h). A right-handed Y-up frame (OpenGL, three.js, glTF) maps to it by
// d_unity = (x, y, -z), which flips the signs of SH indices 2 (z), 5 (yz) and 7 (xz).
//
// Equirectangular (latitude-longitude) images follow Unity's Skybox/Panoramic shader
// (ToRadialCoords). Image W x H, column i from the left, row j from the top, texel centre
// u = (i + 0.5)/W, t = (j + 0.5)/H:
//
//   theta = pi * t              polar angle from +Y
//   lon   = (0.5 - u) * 2 pi    so lon falls as u grows
//   d     = (sin theta cos lon, cos theta, sin theta sin lon)
//
//        u = 0      0.25      0.5      0.75      1
//   t=0  +---------+---------+---------+---------+   top row    -> +Y
//        |   -X    |   +Z    |   +X    |   -Z    |   (column centres)
//   t=1  +---------+---------+---------+---------+   bottom row -> -Y
//
// Texel (i, j) covers theta in [pi j/H, pi (j+1)/H] and lon in
// [(0.5 - (i+1)/W) 2 pi, (0.5 - i/W) 2 pi]; its exact solid angle is
// (2 pi / W)(cos(pi j/H) - cos(pi (j+1)/H)), and the image sums to 4 pi.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace shpack {

struct Dir3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Dir3&, const Dir3&) = default;
};

// The Unity direction of a right-handed Y-up direction (OpenGL, three.js, glTF).
constexpr Dir3 from_right_handed_y_up(Dir3 d) noexcept { return {d.x, d.y, -d.z}; }

// Sign of each L2 coefficient under z -> -z, in Unity's index order:
// indices 2 (z), 5 (yz) and 7 (xz) change sign.
inline constexpr std::array<double, 9> kMirrorZSign = {1, 1, -1, 1, 1, -1, 1, -1, 1};

// Polar angle of the top edge of equirect row j (of H rows): theta = pi j / H.
inline double equirect_theta(double t) noexcept { return std::numbers::pi * t; }

// Longitude of equirect horizontal coordinate u in [0, 1]: lon = (0.5 - u) 2 pi.
inline double equirect_lon(double u) noexcept { return (0.5 - u) * 2.0 * std::numbers::pi; }

// Direction of the equirect point (u, t), both in [0, 1], t from the top.
inline Dir3 equirect_direction(double u, double t) noexcept {
  const double theta = equirect_theta(t), lon = equirect_lon(u);
  return {std::sin(theta) * std::cos(lon), std::cos(theta), std::sin(theta) * std::sin(lon)};
}

// Cube faces in Unity's CubemapFace order.
//
//             +----+
//             | +Y |
//        +----+----+----+----+      horizontal cross (4N x 3N), each face upright
//        | -X | +Z | +X | -Z |      in its own orientation below
//        +----+----+----+----+
//             | -Y |
//             +----+
enum class CubeFace : std::uint8_t { PosX, NegX, PosY, NegY, PosZ, NegZ };

// Per-face axes (D3D convention, which Unity presents on every API). Texel (x, y) of an
// N x N face, row 0 at the top: a = 2(x + 0.5)/N - 1, b = 2(y + 0.5)/N - 1,
// direction = normalize(normal + a * u_axis + b * v_axis).
struct CubeFaceAxes {
  Dir3 u_axis, v_axis, normal;
};
inline constexpr std::array<CubeFaceAxes, 6> kCubeFaceAxes = {{
    {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}},   // +X
    {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},   // -X
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},     // +Y
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   // -Y
    {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},    // +Z
    {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},  // -Z
}};

// The world a set of cube faces was made in (docs/conventions.md, "Faces made for other
// engines"). The face table above gives a direction d in that world; Unity's is:
//   Unity:   d                      (the default: faces as Unity shows them)
//   Gl:      (d.x, d.y, -d.z)       right-handed OpenGL world: a z mirror
//   ThreeJs: (-d.x, d.y, -d.z)      three.js samples cube textures with x negated
//                                   (flipEnvMap = -1), then the z mirror: a 180 degree
//                                   turn about +Y. Unconfirmed against a three.js render.
enum class CubeFrame : std::uint8_t { Unity, Gl, ThreeJs };

// Unity's direction of a direction d of faces made in `frame`.
constexpr Dir3 cube_frame_to_unity(CubeFrame frame, Dir3 d) noexcept {
  switch (frame) {
    case CubeFrame::Gl: return {d.x, d.y, -d.z};
    case CubeFrame::ThreeJs: return {-d.x, d.y, -d.z};
    case CubeFrame::Unity: break;
  }
  return d;
}

// What the frame does to L2 coefficients projected in it: each map above is a sign change
// of some axes, so coefficient i changes sign with its polynomial P_i (sh_basis.h):
// z -> -z flips i = 2 (z), 5 (yz), 7 (xz) (kMirrorZSign); (x, z) -> (-x, -z) flips
// i = 2 (z), 3 (x), 4 (xy), 5 (yz) and keeps 7 (xz = (-x)(-z)).
inline constexpr std::array<double, 9> kThreeJsSign = {1, 1, -1, -1, -1, -1, 1, 1, 1};
inline constexpr std::array<double, 9> kUnitySign = {1, 1, 1, 1, 1, 1, 1, 1, 1};
constexpr const std::array<double, 9>& cube_frame_sign(CubeFrame frame) noexcept {
  return frame == CubeFrame::Gl ? kMirrorZSign : frame == CubeFrame::ThreeJs ? kThreeJsSign : kUnitySign;
}

}  // namespace shpack
