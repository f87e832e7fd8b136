// obj_mesh.h (private) - the triangles of a Wavefront OBJ file, for scene geometry.
//
// Only what a ray tracer needs is read: `v x y z` (a fourth number or a colour after it is
// ignored) and `f` (references `i`, `i/t`, `i//n`, `i/t/n`; negative ones count back from the
// last vertex so far; positive ones may point forward). Everything else (normals, texture
// coordinates, groups, lines, points, `usemtl`, `mtllib`) is skipped: no other file is ever
// opened, material libraries included. Faces are triangulated: a triangle as it is, a quad
// along its shorter diagonal (as tinyobjloader did), larger polygons as a fan from their
// first vertex (right for convex polygons, which exporters write). Positions stay in the
// file's frame; the scene loader scales, mirrors and moves them.
//
// Careless and hostile files are refused, never patched: each problem names its line
// ("line 12: vertex index 9 is out of range (the file has 8 vertices)"). Work and memory are
// linear in the size of the text.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shpack::scene::detail {

struct ObjMesh {
  std::vector<double> vertices;        // xyz per vertex, as written
  std::vector<std::uint32_t> indices;  // three per triangle
};

// Parses `text`. On success returns true and fills `out` (at least one triangle). Otherwise
// returns false with `error` set to one line, "line L: problem"; `out` is then unspecified.
// Coordinates must be finite and at most `max_abs` in magnitude. Throws only std::bad_alloc.
bool parse_obj(std::string_view text, double max_abs, ObjMesh& out, std::string& error);

}  // namespace shpack::scene::detail
