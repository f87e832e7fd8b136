// gltf_mesh.h (private) - the triangles of a glTF 2.0 file (.gltf or .glb), for scene geometry.
//
// Only what a ray tracer needs is read: every triangle primitive (mode 4, and strips 5 and
// fans 6, turned into triangles as the glTF spec numbers them) of every mesh that the default
// scene's node tree instantiates; its POSITION accessor (float VEC3, or with
// KHR_mesh_quantization BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT, normalized or not), sparse
// substitutions included; its indices (unsigned byte, short or int; none means sequential),
// placed by the nodes' matrices or translation/rotation/scale; and its material's
// baseColorFactor (rgb, the albedo) and emissiveFactor (times KHR_materials_emissive_strength).
// Asked for (with_uv), also its TEXCOORD_1 accessor, the lightmap UV set (VEC2: float, or
// normalized UNSIGNED_BYTE/UNSIGNED_SHORT; with KHR_mesh_quantization also BYTE/SHORT
// normalized or not and unnormalized UNSIGNED_BYTE/UNSIGNED_SHORT), and its NORMAL accessor
// (VEC3 float, or with KHR_mesh_quantization normalized BYTE/SHORT), each checked as POSITION
// is (count equal to POSITION's, finite values, sparse substitutions included) and read only
// when every instanced primitive has it. How many UV sets the primitives have (TEXCOORD_0,
// TEXCOORD_1, ...) is counted always, without reading them. Other attributes are ignored.
// Points and lines (modes 0-3) have no surface and are refused, as are required extensions
// other than the two above. Buffers may be files beside the glTF file (percent-encoded
// relative URIs, no `..` out of its folder, regular files within a size limit), base64 data
// URIs, or the .glb binary chunk. Every size is computed with overflow checks (checked_math.h)
// and every accessor is checked against its buffer view, every view against its buffer,
// before a byte is read; a node DAG is counted before it is instanced, against work budgets.
// Positions and normals stay in glTF's right-handed, +Y-up frame: the scene loader converts
// them to Unity's (conventions.md: z -> -z, for normals as for positions). UVs are as stored:
// glTF's v runs down from the top of the image, (0, 0) is the image's top-left texel corner
// (OBJ's and OpenGL's v runs up: v_gl = 1 - v_gltf).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace shpack::scene::detail {

// Work budgets, checked before anything is allocated for the instanced geometry.
inline constexpr std::uint64_t kGltfMaxTriangles = 50'000'000;       // instanced, whole file
inline constexpr std::uint64_t kGltfMaxVertices = 100'000'000;       // instanced, whole file
inline constexpr std::uint64_t kGltfMaxNodeInstances = 10'000'000;   // node visits (DAG paths)
inline constexpr std::uint64_t kGltfMaxFileBytes = 2'000'000'000;    // the .gltf/.glb and each buffer file
inline constexpr std::uint64_t kGltfMaxJsonBytes = 256'000'000;      // the JSON text
// The scene's albedo is below 1 (docs/scenes.md); a baseColorFactor channel above this is
// lowered to it.
inline constexpr double kGltfMaxAlbedo = 0.999;

struct GltfLimits {
  std::uint64_t max_triangles = kGltfMaxTriangles;
  std::uint64_t max_vertices = kGltfMaxVertices;
  std::uint64_t max_node_instances = kGltfMaxNodeInstances;
  std::uint64_t max_file_bytes = kGltfMaxFileBytes;  // also the sum of all buffers
  std::uint64_t max_json_bytes = kGltfMaxJsonBytes;
};

struct GltfMaterial {
  std::string label;                   // "materials[1] 'wood'"
  std::array<double, 3> albedo{};      // baseColorFactor rgb, at most kGltfMaxAlbedo
  std::array<double, 3> emission{};    // emissiveFactor x emissiveStrength
};

struct TriangleMesh {
  std::vector<double> vertices;         // xyz per vertex, world space of the glTF scene
  std::vector<std::uint32_t> indices;   // three per triangle
  std::vector<GltfMaterial> materials;  // the materials the triangles use, in first-use order
  std::vector<std::int32_t> triangle_material;  // per triangle: index into materials, -1 none
  // Only with with_uv, and only when every instanced primitive has the attribute (else empty):
  std::vector<double> uv1;      // TEXCOORD_1, u v per vertex (parallel to vertices), as stored
  std::vector<double> normals;  // NORMAL, xyz per vertex, by the node's inverse transpose, unit
                                // length (a zero normal, or one a singular node flattens, is 0 0 0)
  // The least, over all instanced primitives, of the number of consecutive TEXCOORD_n
  // attributes from TEXCOORD_0 (0: some primitive has no TEXCOORD_0; 1: only TEXCOORD_0, no
  // lightmap set); 0 without primitives. Counted by name, with or without with_uv.
  int texcoord_sets = 0;
};

// Throws std::runtime_error with a one-line message naming the JSON path of the problem,
// e.g. "accessors[3]: count 4611686018427387904 exceeds its buffer view" (not the file:
// the caller does). Without with_uv, TEXCOORD_1 and NORMAL are neither read nor checked (uv1
// and normals stay empty), as before they were read at all.
TriangleMesh read_gltf(const std::filesystem::path& path, const GltfLimits& limits = {}, bool with_uv = false);

// The same over the bytes of a .gltf or .glb already in memory; buffer URIs are resolved
// against `folder`.
TriangleMesh read_gltf_bytes(std::string_view bytes, const std::filesystem::path& folder,
                             const GltfLimits& limits = {}, bool with_uv = false);

// The mesh cut into one part per material (-1: triangles without a material first, then
// materials in the order of `mesh.materials`), each with its own compacted vertices, and
// their uv1 and normals when the mesh has them (else empty).
struct MeshPart {
  std::int32_t material = -1;
  std::vector<double> vertices;
  std::vector<std::uint32_t> indices;
  std::vector<double> uv1;      // u v per vertex of the part, when mesh.uv1 is filled
  std::vector<double> normals;  // xyz per vertex of the part, when mesh.normals is filled
};
std::vector<MeshPart> split_by_material(const TriangleMesh& mesh);

}  // namespace shpack::scene::detail
