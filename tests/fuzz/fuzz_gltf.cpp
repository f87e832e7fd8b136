// libFuzzer target: lib/scene's glTF reader (gltf_mesh.h, meshes of `shpack bake` scenes)
// given arbitrary bytes as a .gltf or .glb held in memory. Buffer URIs resolve against an
// empty scratch folder holding one 64-byte file, "b.bin", so external buffers are exercised
// too. The work budgets are lowered so that no input can ask for more than a few hundred MB.
// Properties: no crash, no sanitizer report, no exception but std::runtime_error, whose
// message is one line.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "gltf_mesh.h"

namespace {

std::filesystem::path scratch() {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("shpack_fuzz_gltf_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "b.bin", std::ios::binary) << std::string(64, '\x01');
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path folder = scratch();
  shpack::scene::detail::GltfLimits limits;
  limits.max_triangles = 1'000'000;
  limits.max_vertices = 1'000'000;
  limits.max_node_instances = 100'000;
  limits.max_file_bytes = 1'000'000;
  // Without and with the lightmap's attributes (TEXCOORD_1, NORMAL): with them, uv1 and
  // normals are empty or parallel to the vertices, in the mesh and in every part.
  for (const bool with_uv : {false, true}) {
    try {
      const auto mesh = shpack::scene::detail::read_gltf_bytes(
          std::string_view(reinterpret_cast<const char*>(data), size), folder, limits, with_uv);
      if (mesh.indices.size() % 3 != 0) std::abort();
      for (const std::uint32_t i : mesh.indices)
        if (i >= mesh.vertices.size() / 3) std::abort();
      const std::size_t n = mesh.vertices.size() / 3;
      if ((!mesh.uv1.empty() && mesh.uv1.size() != 2 * n) || (!mesh.normals.empty() && mesh.normals.size() != 3 * n))
        std::abort();
      for (const auto& part : shpack::scene::detail::split_by_material(mesh)) {
        const std::size_t m = part.vertices.size() / 3;
        if ((!part.uv1.empty() && part.uv1.size() != 2 * m) || (!part.normals.empty() && part.normals.size() != 3 * m))
          std::abort();
      }
    } catch (const std::runtime_error& e) {
      if (std::string_view(e.what()).find('\n') != std::string_view::npos) std::abort();
    }
  }
  return 0;
}
