// libFuzzer target: lib/scene's OBJ reader (obj_mesh.h, meshes of `shpack bake` scenes) given
// arbitrary bytes as the text of an OBJ file.
// Properties: no crash, no sanitizer report, no exception but bad_alloc (none within
// -rss_limit_mb for these sizes: memory is linear in the text); on success at least one
// triangle, every index within the vertices, every coordinate finite and within the bound; on
// failure one non-empty line starting "line " or saying "no faces".
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "obj_mesh.h"

namespace {

// One parse, with or without the texture coordinates and normals (a lightmap's mesh): with
// them, `uv` is empty or holds u, v for every vertex, and `normals` is empty or holds x, y, z
// for every vertex (only beside uv), each finite.
void check(std::string_view text, bool with_uv) {
  constexpr double kMaxAbs = 1.844e18;
  shpack::scene::detail::ObjMesh mesh;
  std::string error;
  if (!shpack::scene::detail::parse_obj(text, kMaxAbs, mesh, error, with_uv)) {
    if (error.empty() || error.find('\n') != std::string::npos) std::abort();
    if (error.rfind("line ", 0) != 0 && error != "no faces") std::abort();
    return;
  }
  if (mesh.vertices.size() % 3 != 0 || mesh.indices.empty() || mesh.indices.size() % 3 != 0) std::abort();
  for (const double v : mesh.vertices)
    if (!std::isfinite(v) || std::fabs(v) > kMaxAbs) std::abort();
  for (const std::uint32_t i : mesh.indices)
    if (i >= mesh.vertices.size() / 3) std::abort();
  if (!mesh.uv.empty() && (!with_uv || mesh.uv.size() != 2 * (mesh.vertices.size() / 3))) std::abort();
  for (const double u : mesh.uv)
    if (!std::isfinite(u)) std::abort();
  if (!mesh.normals.empty() && (mesh.uv.empty() || mesh.normals.size() != mesh.vertices.size())) std::abort();
  for (const double n : mesh.normals)
    if (!std::isfinite(n)) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check(text, false);
  check(text, true);
  return 0;
}
