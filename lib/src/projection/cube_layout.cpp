#include "shpack/cube_layout.h"

namespace shpack {
namespace {

// Cells in CubeFace order (+X, -X, +Y, -Y, +Z, -Z), from docs/conventions.md.
constexpr std::array<CubeCell, kCubeFaceCount> kHorizontalCross = {
    {{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {3, 1, false}}};
constexpr std::array<CubeCell, kCubeFaceCount> kVerticalCross = {
    {{2, 1, false}, {0, 1, false}, {1, 0, false}, {1, 2, false}, {1, 1, false}, {1, 3, true}}};

bool known(CubeLayout layout) noexcept {
  return layout == CubeLayout::HorizontalCross || layout == CubeLayout::VerticalCross ||
         layout == CubeLayout::HorizontalStrip || layout == CubeLayout::VerticalStrip;
}

const char* shape_problem(CubeLayout layout) noexcept {
  switch (layout) {
    case CubeLayout::HorizontalCross: return "a horizontal cross must be 4N x 3N texels";
    case CubeLayout::VerticalCross: return "a vertical cross must be 3N x 4N texels";
    case CubeLayout::HorizontalStrip: return "a horizontal strip must be 6N x N texels";
    case CubeLayout::VerticalStrip: return "a vertical strip must be N x 6N texels";
  }
  return "unknown cube layout";
}

}  // namespace

CubeGrid cube_layout_grid(CubeLayout layout) noexcept {
  switch (layout) {
    case CubeLayout::HorizontalCross: return {4, 3};
    case CubeLayout::VerticalCross: return {3, 4};
    case CubeLayout::HorizontalStrip: return {6, 1};
    case CubeLayout::VerticalStrip: return {1, 6};
  }
  return {};
}

CubeCell cube_layout_cell(CubeLayout layout, CubeFace face) noexcept {
  const auto f = static_cast<std::uint32_t>(face);
  switch (layout) {
    case CubeLayout::HorizontalCross: return kHorizontalCross[f];
    case CubeLayout::VerticalCross: return kVerticalCross[f];
    case CubeLayout::HorizontalStrip: return {f, 0, false};
    case CubeLayout::VerticalStrip: return {0, f, false};
  }
  return {};
}

Status cube_face_views(const ImageView& image, CubeLayout layout,
                       std::array<ImageView, kCubeFaceCount>& faces) noexcept {
  if (!known(layout)) return Status::error(Errc::InvalidArgument, "unknown cube layout");
  ImageView resolved = image;
  if (Status st = resolve_view(resolved); !st.ok()) return st;
  if (resolved.width == 1 && resolved.height == 1) {
    faces.fill(resolved);  // a uniform environment: the one texel on every face
    return Status::success();
  }
  const CubeGrid grid = cube_layout_grid(layout);
  const std::uint32_t n = resolved.width / grid.columns;
  if (n == 0 || resolved.width != n * grid.columns || static_cast<std::uint64_t>(resolved.height) !=
                                                         std::uint64_t{n} * grid.rows)
    return Status::error(Errc::InvalidArgument, shape_problem(layout));
  std::array<ImageView, kCubeFaceCount> out;
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const CubeCell cell = cube_layout_cell(layout, static_cast<CubeFace>(f));
    ImageView& face = out[f];
    face = resolved;
    face.width = face.height = n;
    if (cell.rotated_180) {
      // Texel (x, y) of the face is texel (N-1-x, N-1-y) of the cell.
      face.data = resolved.pixel(cell.column * n + (n - 1), cell.row * n + (n - 1));
      face.pixel_stride = -resolved.pixel_stride;
      face.row_stride = -resolved.row_stride;
    } else {
      face.data = resolved.pixel(cell.column * n, cell.row * n);
    }
  }
  faces = out;
  return Status::success();
}

}  // namespace shpack
