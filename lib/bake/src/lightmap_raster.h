// lightmap_raster.h (private) - which texels of a lightmap its triangles cover, and the
// points that stand for each texel's footprint (docs/lightmaps.md, "Texels").
//
// Texel (i, j) is the square [i, i + 1] x [j, j + 1] of texel space, x = u W, y = (1 - v) H
// (row 0 at the top of the image, Unity's v up). Each triangle is clipped to each texel square
// it meets (Sutherland-Hodgman against the four sides). A texel belongs to the chart whose
// clipped polygons cover most of it, and their area is its coverage; a texel is used when
// that is positive. Its sample points are the centres of a kSubsamples x kSubsamples grid of
// sub-squares that a triangle of its chart contains, or, when a sliver covers none of them,
// the centroid of that chart's largest clipped polygon: the texel's value is the mean over
// its points, each standing for an equal share of the covered area. Another chart's part of
// the texel (where two charts meet in the atlas) is not its surface: it is left out, counted
// in `shared`.
//
// Normals: a mesh with shading normals (scene.h) has them interpolated by the barycentrics and
// normalised, turned to the front's side if a vertex's normal points behind it; else the
// triangle's own.
//
// Charts are the connected sets of triangles that share a vertex (same position and same UV),
// so a UV seam separates charts; dilation and padding never cross from one chart to another.
// Two triangles of different charts that both contain a sub-square's centre strictly inside
// overlap: the raster fails, naming the shape and the texel (a lightmap UV set must not
// overlap, or two surfaces would share texels).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "shpack/scene/scene.h"
#include "shpack/vec3.h"

namespace shpack::bake {

inline constexpr int kSubsamples = 2;  // per side: 4 points per fully covered texel

struct TexelPoint {
  Vec3 position;  // on the surface
  Vec3 normal;    // unit: the shading normal (interpolated from the mesh's, on the front's side), else the geometric one
  Vec3 geometric; // unit, the triangle's front (its winding, as the ray tracer's): the side rays leave from
};

struct LightmapRaster {
  std::uint32_t width = 0, height = 0;
  std::vector<float> coverage;        // per texel, the share of its square its chart covers, [0, 1]
  std::vector<std::int32_t> chart;    // per texel, its chart (the one covering most of it), -1 unused
  std::vector<std::uint32_t> first;   // per texel, its first point in `points`; width*height+1 entries
  std::vector<TexelPoint> points;
  std::uint64_t degenerate = 0;       // triangles skipped: no area in UV or in space
  std::uint64_t shared = 0;           // used texels that more than one chart covers
};

// Rasterises `target`'s shapes (each with uv, scene.h). Returns false with `error` set to one
// line (without the scene file) for UVs outside [0, 1] or not finite, overlapping charts, or
// a lightmap no triangle covers.
bool rasterize_lightmap(const scene::LightmapTarget& target, const std::vector<scene::SceneShape>& geometry,
                        LightmapRaster& out, std::string& error);

}  // namespace shpack::bake
