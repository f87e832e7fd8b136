// lightmap_raster.h (private) - which texels of a lightmap its triangles cover, and the
// points that stand for each texel's footprint (docs/lightmaps.md, "Texels").
//
// Texel (i, j) is the square [i, i + 1] x [j, j + 1] of texel space, x = u W, y = (1 - v) H
// (row 0 at the top of the image, Unity's v up). Each triangle is clipped to each texel square
// it meets (Sutherland-Hodgman against the four sides): the clipped polygons' areas are the
// texel's coverage. A texel is used when its coverage is positive; its sample points are the
// centres of a kSubsamples x kSubsamples grid of sub-squares that some triangle contains, or,
// when a sliver covers none of them, the centroid of its largest clipped polygon: the texel's
// value is the mean over its points, each standing for an equal share of the covered area.
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
  std::vector<float> coverage;        // per texel, covered share of its square, [0, 1]
  std::vector<std::int32_t> chart;    // per texel, its chart (the largest covering), -1 unused
  std::vector<std::uint32_t> first;   // per texel, its first point in `points`; width*height+1 entries
  std::vector<TexelPoint> points;
  std::uint64_t degenerate = 0;       // triangles skipped: no area in UV or in space
};

// Rasterises `target`'s shapes (each with uv, scene.h). Returns false with `error` set to one
// line (without the scene file) for UVs outside [0, 1] or not finite, overlapping charts, or
// a lightmap no triangle covers.
bool rasterize_lightmap(const scene::LightmapTarget& target, const std::vector<scene::SceneShape>& geometry,
                        LightmapRaster& out, std::string& error);

}  // namespace shpack::bake
