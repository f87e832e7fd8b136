// cube_layout.h - the six faces of a cube map stored in one image, as six views of it.
//
// docs/conventions.md ("Single-image cube layouts") places faces of N x N texels in the
// cells (column, row) of one image, row 0 at the top, each face upright in its own
// orientation (conventions.h kCubeFaceAxes) except the vertical cross's -Z:
//
//   horizontal cross, 4N x 3N        vertical cross, 3N x 4N
//        +----+                           +----+
//        | +Y |                           | +Y |
//   +----+----+----+----+            +----+----+----+
//   | -X | +Z | +X | -Z |            | -X | +Z | +X |
//   +----+----+----+----+            +----+----+----+
//        | -Y |                           | -Y |
//        +----+                           +----+
//                                         | -Z |  rotated 180 degrees: its texel (x, y)
//   horizontal strip, 6N x N              +----+  is stored at (N-1-x, N-1-y) of the cell
//   +----+----+----+----+----+----+
//   | +X | -X | +Y | -Y | +Z | -Z |      vertical strip, N x 6N: the same faces top to bottom
//   +----+----+----+----+----+----+
//
// cube_face_views makes the six faces as strided views of the one image, with no copy: a
// face is the image's view moved to the cell's first texel, with the image's strides; the
// rotated face starts at the cell's last texel and has both strides negated (image_view.h
// allows negative strides). The unused cells of a cross are never read. A 1 x 1 image is a
// uniform environment whatever its layout (conventions.md): its one texel is all six faces.
#pragma once

#include <array>
#include <cstdint>

#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/project_cube.h"
#include "shpack/status.h"

namespace shpack {

enum class CubeLayout : std::uint8_t { HorizontalCross, VerticalCross, HorizontalStrip, VerticalStrip };

// Where a face lies: its cell, in units of the face size N, and whether it is stored
// rotated by 180 degrees.
struct CubeCell {
  std::uint32_t column = 0, row = 0;
  bool rotated_180 = false;
};

// The layout's image in cells: (4, 3), (3, 4), (6, 1), (1, 6).
struct CubeGrid {
  std::uint32_t columns = 0, rows = 0;
};
CubeGrid cube_layout_grid(CubeLayout layout) noexcept;

// The cell of `face` in `layout` (the tables above).
CubeCell cube_layout_cell(CubeLayout layout, CubeFace face) noexcept;

// The six faces of `image`, in CubeFace order, ready for project_cube. Errors: Errc::BadView
// (the image fails resolve_view), Errc::InvalidArgument (the image is not columns N x rows N
// of the layout's grid for some N >= 1, and not 1 x 1; or an unknown layout). On error
// `faces` is left as it was.
Status cube_face_views(const ImageView& image, CubeLayout layout,
                       std::array<ImageView, kCubeFaceCount>& faces) noexcept;

}  // namespace shpack
