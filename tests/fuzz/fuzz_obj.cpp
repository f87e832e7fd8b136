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

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr double kMaxAbs = 1.844e18;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  shpack::scene::detail::ObjMesh mesh;
  std::string error;
  if (!shpack::scene::detail::parse_obj(text, kMaxAbs, mesh, error)) {
    if (error.empty() || error.find('\n') != std::string::npos) std::abort();
    if (error.rfind("line ", 0) != 0 && error != "no faces") std::abort();
    return 0;
  }
  if (mesh.vertices.size() % 3 != 0 || mesh.indices.empty() || mesh.indices.size() % 3 != 0) std::abort();
  for (const double v : mesh.vertices)
    if (!std::isfinite(v) || std::fabs(v) > kMaxAbs) std::abort();
  for (const std::uint32_t i : mesh.indices)
    if (i >= mesh.vertices.size() / 3) std::abort();
  return 0;
}
