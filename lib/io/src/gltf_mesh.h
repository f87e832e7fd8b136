// gltf_mesh.h (private) - the triangles of a glTF 2.0 file (.gltf or .glb), for scene geometry.
//
// Only what a ray tracer needs is read: every triangle primitive (mode 4) of every mesh that
// the default scene's node tree instantiates, its POSITION accessor (float VEC3) and its
// indices (unsigned byte, short or int; none means sequential), placed by the nodes' matrices
// or translation/rotation/scale. Buffers may be external files (relative to the glTF file),
// base64 data URIs, or the .glb binary chunk. Points and lines (other modes) have no surface
// and are skipped; sparse accessors are refused. Positions stay in glTF's right-handed,
// +Y-up frame: the scene loader converts them to Unity's (conventions.md: z -> -z).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace shpack::io::detail {

struct TriangleMesh {
  std::vector<double> vertices;         // xyz per vertex, world space of the glTF scene
  std::vector<std::uint32_t> indices;   // three per triangle
};

// Throws std::runtime_error with a message naming the problem (not the file: the caller does).
TriangleMesh read_gltf(const std::filesystem::path& path);

}  // namespace shpack::io::detail
