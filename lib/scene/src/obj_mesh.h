// obj_mesh.h (private) - the triangles of a Wavefront OBJ file, for scene geometry.
//
// Only what a ray tracer needs is read: `v x y z` (a fourth number or a colour after it is
// ignored) and `f` (references `i`, `i/t`, `i//n`, `i/t/n`; negative ones count back from the
// last vertex so far; positive ones may point forward). Asked for (with_uv, a lightmap's
// mesh), also `vt u v` (v optional, 0 by default; a third number ignored), `vn x y z`, and the
// faces' texture and normal indices `t` and `n` (counted as vertex indices are): each distinct
// (vertex, texture, normal) corner then becomes its own vertex, positions duplicated; the
// normals only when every reference has one. Texture coordinates are as written: OBJ's v
// runs up, 0 at the bottom of the image (glTF's runs down: v_gltf = 1 - v_obj); normals too
// (not normalised). Everything else (groups, lines, points, `usemtl`, `mtllib`; without
// with_uv texture coordinates and normals too) is skipped: no other file is ever opened, material libraries included. Faces are triangulated: a triangle as it is, a quad
// along its shorter diagonal (as tinyobjloader did), larger polygons as a fan from their
// first vertex (right for convex polygons, which exporters write). Positions stay in the
// file's frame; the scene loader scales, mirrors and moves them.
//
// Careless and hostile files are refused, never patched: each problem names its line
// ("line 12: vertex index 9 is out of range (the file has 8 vertices)"). Work and memory are
// linear in the size of the text.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace shpack::scene::detail {

struct ObjMesh {
  std::vector<double> vertices;        // xyz per vertex, as written
  std::vector<std::uint32_t> indices;  // three per triangle
  // with_uv only: u v per vertex (parallel to vertices), as written; empty without with_uv,
  // when the file has no `vt`, or when some face reference has no texture index.
  std::vector<double> uv;
  // with_uv: x y z per vertex (parallel to vertices), as written, when uv is filled and every
  // face reference has a normal index into the file's `vn`; empty otherwise.
  std::vector<double> normals;
  // with_uv and uv empty: the first line with a face reference without a texture index, or 0
  // when the file has no `vt` at all (or without with_uv).
  std::size_t uv_missing_line = 0;
};

// Parses `text`. On success returns true and fills `out` (at least one triangle). Otherwise
// returns false with `error` set to one line, "line L: problem"; `out` is then unspecified.
// Coordinates must be finite and at most `max_abs` in magnitude. Throws only std::bad_alloc.
// Without with_uv, `vt` and `vn` lines and texture and normal indices are not looked at. With
// it, their numbers must be finite (no bound), and an index out of range of the file's `vt`
// (`vn`) lines is an error like a vertex index's ("line 9: texture index 7 is out of range
// (the file has 4 texture coordinates)"); with no `vt` (`vn`) at all, those indices are not
// checked and uv (normals) stays empty.
// When uv is filled, vertices holds one vertex per distinct (vertex, texture) pair of the
// faces, in first-use order (positions not used by any face are dropped); otherwise vertices
// is as without with_uv.
bool parse_obj(std::string_view text, double max_abs, ObjMesh& out, std::string& error, bool with_uv = false);

}  // namespace shpack::scene::detail
