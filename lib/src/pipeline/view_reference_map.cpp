// view_reference_map.cpp - the reference E/pi (view_reference.h) of a whole map of any layout.
//
// Texel diameters, for the caps of cells that hold texels by their centroid. A curve of
// length s in the image moves the direction by at most K s, K the map's Lipschitz bound, so
// a texel square of side h = 2/N (diagonal h sqrt 2) has a diameter of at most K h sqrt 2:
//  - cube face: d = p/|p| with p = N + aU + bV, |p| >= 1, so |dd| <= |dp| / |p| <= |dp|: K = 1;
//  - octahedral: p = (u, v, 1 - |u| - |v|) (the lower half folded by reflections), |dp| <=
//    sqrt 3 |d(u, v)| and |p| >= 1/sqrt 3: K = 3;
//  - angular map: polar angle pi r (radial scale pi), tangential scale sin(pi r)/r <= pi, the
//    arc within a texel at most pi/2 times its chord: K = pi (1 + pi/2);
//  - mirror ball: polar angle 2 asin r, radial scale 2/sqrt(1 - r^2) (unbounded at the rim),
//    tangential scale 2 sqrt(1 - r^2) <= 2: per texel, 2 (asin r1 - asin r0) + pi h sqrt 2, with
//    r0 and r1 the least and largest radius of its square within the disc.
#include <algorithm>
#include <cmath>
#include <vector>

#include "common/angles.h"
#include "pipeline/layout_dispatch.h"
#include "projection/row_kernel.h"
#include "projection/sphere_map_texels.h"
#include "shpack/pipeline.h"
#include "shpack/project_cube.h"
#include "shpack/project_sphere_map.h"

namespace shpack {
namespace {

Dir3 flux_of(const std::array<double, kShCount>& integrals) noexcept {
  // int Y_1,-1 = k1 int y, int Y_10 = k1 int z, int Y_11 = k1 int x (sh_basis.h).
  return {integrals[3] / kY1, integrals[1] / kY1, integrals[2] / kY1};
}

double mirror_ball_diameter(std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept {
  const detail::TexelSquare t = detail::sphere_map_texel_square(n, x, y);
  const double dx = std::max({0.0, t.u0, -t.u1}), dy = std::max({0.0, t.v0, -t.v1});
  const double ux = std::max(std::abs(t.u0), std::abs(t.u1)), vy = std::max(std::abs(t.v0), std::abs(t.v1));
  const double r0 = std::min(1.0, std::hypot(dx, dy)), r1 = std::min(1.0, std::hypot(ux, vy));
  return 2 * (std::asin(r1) - std::asin(r0)) + kPi * t.h * std::sqrt(2.0);
}

// Rows of `image` through the projector's value policies, texel by texel to `add`.
template <class Add>
Status for_each_texel(const ImageView& view, const ProjectOptions& options, Add&& add) {
  ImageView image = view;
  if (Status st = resolve_view(image); !st.ok()) return st;
  std::vector<float> planes(3 * static_cast<std::size_t>(image.width));
  detail::TexelCounts counts;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    detail::load_row_planes(image.rows(y, 1), y, options, planes, counts);
    for (std::uint32_t x = 0; x < image.width; ++x)
      add(x, y, std::array<float, 3>{planes[x], planes[image.width + x], planes[2 * image.width + x]});
  }
  return {};
}

Status add_cube(const MapImage& map, const ProjectOptions& options, ViewReference& out) {
  std::array<ImageView, kCubeFaceCount> faces = map.faces;
  if (map.layout != Layout::Faces) {
    if (Status st = cube_face_views(map.image, detail::cube_layout_of(map.layout), faces); !st.ok()) return st;
  }
  for (int f = 0; f < kCubeFaceCount; ++f) {
    const std::uint32_t n = faces[f].width;
    const double diameter = 2 * std::sqrt(2.0) / n;
    std::array<double, kShCount> w{};
    Status failed;
    Status st = for_each_texel(faces[f], options, [&](std::uint32_t x, std::uint32_t y, const std::array<float, 3>& rgb) {
      if (Status s = cube_texel_basis_integrals(n, static_cast<CubeFace>(f), x, y, SamplingMethod::Exact, w); !s.ok()) {
        failed = s;
        return;
      }
      out.add_texel(rgb, w[0] / kY0, cube_frame_to_unity(map.cube_frame, flux_of(w)), diameter);
    });
    if (!st.ok()) return st;
    if (!failed.ok()) return failed;
  }
  return {};
}

Status add_sphere_map(const MapImage& map, const ProjectOptions& options, ViewReference& out) {
  const SphereMap kind = detail::sphere_map_of(map.layout);
  const std::uint32_t n = map.image.width;
  const double side = 2.0 / n * std::sqrt(2.0);
  const double lipschitz = kind == SphereMap::Octahedral ? 3.0 : kPi * (1 + kPi / 2);
  std::array<double, kShCount> w{};
  return for_each_texel(map.image, options, [&](std::uint32_t x, std::uint32_t y, const std::array<float, 3>& rgb) {
    if (!sphere_map_texel_basis_integrals(n, kind, x, y, w).ok() || !(w[0] > 0)) return;
    const double diameter = kind == SphereMap::MirrorBall ? mirror_ball_diameter(n, x, y) : lipschitz * side;
    out.add_texel(rgb, w[0] / kY0, flux_of(w), diameter);
  });
}

}  // namespace

Status build_view_reference(const MapImage& map, const ProjectOptions& project, ViewReference& out) noexcept {
  ProjectOptions options = project;
  options.nonfinite = NonFinite::Zero;
  try {
    ViewReference ref;
    if (map.layout == Layout::Equirect) {
      ImageView image = map.image;
      if (Status st = resolve_view(image); !st.ok()) return st;
      if (Status st = ref.begin_equirect(image.width, image.height, options); !st.ok()) return st;
      if (Status st = ref.add_rows(image, 0); !st.ok()) return st;
    } else {
      if (Status st = ref.begin_texels(); !st.ok()) return st;
      Status st = detail::is_sphere_map(map.layout) ? add_sphere_map(map, options, ref) : add_cube(map, options, ref);
      if (!st.ok()) return st;
    }
    if (Status st = ref.finish(); !st.ok()) return st;
    out = std::move(ref);
    return {};
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory for the reference E/pi");
  }
}

}  // namespace shpack
