// Tests of the glTF reader (lib/scene/src/gltf_mesh.h): crafted files that crashed or were
// misread before (wrapping bounds checks, negative offsets, unsafe buffer URIs), the parts of
// glTF it now reads (strips, fans, quantized positions, sparse accessors, materials, with_uv's
// TEXCOORD_1 and NORMAL) and the work budgets of node DAGs. Positions and UVs are asserted
// exactly, transformed normals to 1e-15, errors by message substring.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "gltf_mesh.h"
#include "scene/scene_files.h"
#include "shpack/scene/scene_loader.h"

namespace shpack::scene::detail {
namespace {

namespace fs = std::filesystem;

template <class T>
std::string bytes_of(const std::vector<T>& v) {
  std::string out(v.size() * sizeof(T), '\0');
  std::memcpy(out.data(), v.data(), out.size());
  return out;
}

std::string data_uri_buffer(const std::string& bytes) {
  return R"({"byteLength": )" + std::to_string(bytes.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
         shpack_test::base64(bytes) + R"("})";
}

// Three float vertices (0,0,0) (1,0,0) (0,1,0): 36 bytes.
const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

// A document with one mesh of one primitive on node 0, given its accessors and bufferViews.
std::string document(const std::string& buffers, const std::string& views, const std::string& accessors,
                     const std::string& primitive = R"({"attributes": {"POSITION": 0}})", const std::string& extra = "") {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [)" + primitive + R"(]}], "buffers": [)" + buffers + R"(], "bufferViews": [)" + views +
         R"(], "accessors": [)" + accessors + "]" + extra + "}";
}

// Replaces the document's one-node list by `nodes` ("\"nodes\": [...]").
void set_nodes(std::string& doc, const std::string& nodes) {
  const std::string old = R"("nodes": [{"mesh": 0}])";
  doc.replace(doc.find(old), old.size(), nodes);
}

TriangleMesh read(const std::string& name, const std::string& text, const GltfLimits& limits = {}) {
  return read_gltf(shpack_test::write_scene(name, text), limits);
}

// The message of the error reading the file, or "" when it was read.
std::string error_of(const std::string& name, const std::string& text, const GltfLimits& limits = {}) {
  try {
    read(name, text, limits);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return what;
  }
  return "";
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

std::string float_accessor(std::uint64_t count, const std::string& more = "") {
  return R"({"bufferView": 0, "componentType": 5126, "count": )" + std::to_string(count) + R"(, "type": "VEC3")" + more + "}";
}

// ---- 1. sizes and ranges ----

TEST(Gltf, ACountOf2To62IsRefusedNotACrash) {
  const std::string e = error_of("count.gltf", document(data_uri_buffer(bytes_of(kTriangle)),
                                                        R"({"buffer": 0, "byteLength": 36})", float_accessor(4611686018427387904ull)));
  EXPECT_HAS(e, "accessors[0]: count 4611686018427387904");
  EXPECT_HAS(e, "exceeds its buffer view");
}

TEST(Gltf, AStrideOf2To63IsRefusedNotACrash) {
  const std::string e = error_of("stride.gltf", document(data_uri_buffer(bytes_of(kTriangle)),
                                                         R"({"buffer": 0, "byteLength": 36, "byteStride": 9223372036854775808})",
                                                         float_accessor(3)));
  EXPECT_HAS(e, "accessors[0]: count 3");
  EXPECT_HAS(e, "byteStride 9223372036854775808) exceeds its buffer view");
}

TEST(Gltf, NegativeAndFractionalOffsetsAreRefused) {
  const std::string buffer = data_uri_buffer(bytes_of(kTriangle)), view = R"({"buffer": 0, "byteLength": 36})";
  EXPECT_HAS(error_of("neg.gltf", document(buffer, view, float_accessor(3, R"(, "byteOffset": -4)"))),
             "accessors[0].byteOffset: -4 must be a non-negative integer");
  EXPECT_HAS(error_of("negview.gltf", document(buffer, R"({"buffer": 0, "byteLength": 36, "byteOffset": -12})", float_accessor(3))),
             "bufferViews[0].byteOffset: -12 must be a non-negative integer");
  EXPECT_HAS(error_of("frac.gltf", document(buffer, view, R"({"bufferView": 0, "componentType": 5126, "count": 2.5, "type": "VEC3"})")),
             "accessors[0].count: 2.5 must be a non-negative integer");
  EXPECT_HAS(error_of("negstride.gltf", document(buffer, R"({"buffer": 0, "byteLength": 36, "byteStride": -12})", float_accessor(3))),
             "bufferViews[0].byteStride: -12 must be a non-negative integer");
}

TEST(Gltf, ViewsAreCheckedAgainstTheirBufferAndBuffersAgainstTheirData) {
  const std::string bytes = bytes_of(kTriangle);
  EXPECT_HAS(error_of("view.gltf", document(data_uri_buffer(bytes), R"({"buffer": 0, "byteOffset": 18446744073709551615, "byteLength": 2})",
                                            float_accessor(3))),
             "bufferViews[0]: byteOffset 18446744073709551615 + byteLength 2 exceeds buffers[0] (byteLength 36)");
  EXPECT_HAS(error_of("short.gltf", document(R"({"byteLength": 40, "uri": "data:application/octet-stream;base64,)" + shpack_test::base64(bytes) + R"("})",
                                             R"({"buffer": 0, "byteLength": 36})", float_accessor(3))),
             "buffers[0].byteLength: 40 exceeds its data (36 bytes)");
  // byteStride 0 is tightly packed; an explicit 12 reads the same.
  for (const char* stride : {"0", "12"}) {
    const TriangleMesh m = read("packed.gltf", document(data_uri_buffer(bytes), std::string(R"({"buffer": 0, "byteLength": 36, "byteStride": )") + stride + "}",
                                                        float_accessor(3)));
    EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0})) << stride;
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2})) << stride;
  }
}

TEST(Gltf, ErrorsThroughTheSceneLoaderNameTheSceneTheFileAndTheJsonPath) {
  shpack_test::write_scene("chair.gltf", document(data_uri_buffer(bytes_of(kTriangle)), R"({"buffer": 0, "byteLength": 36})",
                                                  float_accessor(4611686018427387904ull)));
  const fs::path scene = shpack_test::write_scene("chair.json", R"({"probes": [[0, 1, 0]], "effects": [],
    "geometry": [{"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]}, {"type": "mesh", "path": "chair.gltf"}]})");
  Scene s;
  const io::IoStatus st = load_scene(scene, s);
  ASSERT_FALSE(st.ok());
  EXPECT_HAS(st.message, "geometry[1].path: ");
  EXPECT_HAS(st.message, "chair.gltf: accessors[0]: count 4611686018427387904");
}

// ---- 2. buffer URIs ----

TEST(Gltf, PercentEncodedUrisAreDecoded) {
  shpack_test::write_scene("my buffer.bin", bytes_of(kTriangle));
  const TriangleMesh m = read("space.gltf", document(R"({"byteLength": 36, "uri": "my%20buffer.bin"})",
                                                     R"({"buffer": 0, "byteLength": 36})", float_accessor(3)));
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_HAS(error_of("badescape.gltf", document(R"({"byteLength": 36, "uri": "my%2gbuffer.bin"})", R"({"buffer": 0, "byteLength": 36})",
                                                 float_accessor(3))),
             "buffers[0].uri: 'my%2gbuffer.bin': a bad percent escape");
}

TEST(Gltf, UrisOutsideTheFolderAbsoluteOrNotRegularFilesAreRefused) {
  const fs::path dir = shpack_test::scene_scratch();
  fs::create_directories(dir / "sub");
  shpack_test::write_scene("sub/inside.bin", bytes_of(kTriangle));
  const auto with_uri = [](const std::string& uri) {
    return document(R"({"byteLength": 36, "uri": ")" + uri + R"("})", R"({"buffer": 0, "byteLength": 36})", float_accessor(3));
  };
  // Within the folder, `..` is fine.
  EXPECT_EQ(read("sub/ok.gltf", with_uri("./x/../inside.bin")).vertices.size(), 9u);
  EXPECT_HAS(error_of("sub/up.gltf", with_uri("../sub/inside.bin")), "buffers[0].uri: '../sub/inside.bin': leaves the glTF file's folder");
  EXPECT_HAS(error_of("sub/up2.gltf", with_uri("a/../../x.bin")), "leaves the glTF file's folder");
  EXPECT_HAS(error_of("sub/up3.gltf", with_uri("%2E%2E/x.bin")), "leaves the glTF file's folder");
  EXPECT_HAS(error_of("zero.gltf", with_uri("/dev/zero")), "buffers[0].uri: '/dev/zero': absolute paths are refused");
  EXPECT_HAS(error_of("zero2.gltf", with_uri("%2Fdev%2Fzero")), "absolute paths are refused");
  EXPECT_HAS(error_of("scheme.gltf", with_uri("file:///dev/zero")), "absolute URIs are refused");
  // A link to /dev/zero and a FIFO beside the file: not regular files (and no hang).
  std::error_code ec;
  fs::remove(dir / "zero.bin", ec);
  fs::create_symlink("/dev/zero", dir / "zero.bin");
  EXPECT_HAS(error_of("zerolink.gltf", with_uri("zero.bin")), "zero.bin: is not a regular file");
  fs::remove(dir / "fifo.bin", ec);
  ASSERT_EQ(::mkfifo((dir / "fifo.bin").c_str(), 0600), 0);
  EXPECT_HAS(error_of("fifo.gltf", with_uri("fifo.bin")), "fifo.bin: is not a regular file");
  // A buffer file above the size limit.
  GltfLimits small;
  small.max_file_bytes = 35;
  try {
    read_gltf_bytes(with_uri("inside.bin"), dir / "sub", small);
    ADD_FAILURE() << "read beyond the limit";
  } catch (const std::runtime_error& e) {
    EXPECT_HAS(e.what(), "inside.bin: 36 bytes, more than the limit of 35");
  }
}

// ---- 3. primitive modes ----

// Four vertices (0,0,0) (1,0,0) (0,1,0) (1,1,0).
std::string quad_document(int mode) {
  return document(data_uri_buffer(bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0})), R"({"buffer": 0, "byteLength": 48})",
                  float_accessor(4), R"({"attributes": {"POSITION": 0}, "mode": )" + std::to_string(mode) + "}");
}

TEST(Gltf, TriangleStripsAreRead) {
  const TriangleMesh m = read("strip.gltf", quad_document(5));
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}));
  // {v_i, v_{i+(1+i%2)}, v_{i+(2-i%2)}}: (0, 1, 2), (1, 3, 2).
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
}

TEST(Gltf, TriangleFansAreRead) {
  const TriangleMesh m = read("fan.gltf", quad_document(6));
  // {v_{i+1}, v_{i+2}, v_0}: (1, 2, 0), (2, 3, 0).
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0}));
}

TEST(Gltf, PointsLinesAndUnknownModesAreRefused) {
  EXPECT_HAS(error_of("lines.gltf", quad_document(1)), "meshes[0].primitives[0].mode: 1 (lines) has no surface");
  EXPECT_HAS(error_of("points.gltf", quad_document(0)), "0 (points) has no surface");
  EXPECT_HAS(error_of("seven.gltf", quad_document(7)), "mode: 7 is not a glTF primitive mode");
}

// ---- 3. KHR_mesh_quantization ----

TEST(Gltf, QuantizedPositionsAreReadWithTheNodeTransform) {
  // SHORT normalized: 32767 -> 1, -32767 -> -1, 16384 -> 16384/32767; the node scales by 2
  // and moves by (1, 0, 0).
  const std::vector<std::int16_t> p = {0, 0, 0, 32767, 0, 0, 0, -32767, 16384, 0};  // 3 x VEC3 + padding
  const std::string ext = R"(, "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"])";
  std::string doc = document(data_uri_buffer(bytes_of(p)), R"({"buffer": 0, "byteLength": 18})",
                             R"({"bufferView": 0, "componentType": 5122, "normalized": true, "count": 3, "type": "VEC3"})",
                             R"({"attributes": {"POSITION": 0}})", ext);
  set_nodes(doc, R"("nodes": [{"mesh": 0, "scale": [2, 2, 2], "translation": [1, 0, 0]}])");
  const TriangleMesh m = read("quant.gltf", doc);
  ASSERT_EQ(m.vertices.size(), 9u);
  EXPECT_EQ(m.vertices, (std::vector<double>{1, 0, 0, 3, 0, 0, 1, -2, 2 * (16384 / 32767.0)}));
  // UNSIGNED_BYTE, not normalized: the integers themselves.
  const std::vector<std::uint8_t> b = {0, 0, 0, 200, 0, 0, 0, 7, 255};
  const TriangleMesh u = read("quant8.gltf", document(data_uri_buffer(bytes_of(b)), R"({"buffer": 0, "byteLength": 9})",
                                                      R"({"bufferView": 0, "componentType": 5121, "count": 3, "type": "VEC3"})",
                                                      R"({"attributes": {"POSITION": 0}})", ext));
  EXPECT_EQ(u.vertices, (std::vector<double>{0, 0, 0, 200, 0, 0, 0, 7, 255}));
  // Without the extension declared, integer positions are refused.
  EXPECT_HAS(error_of("noext.gltf", document(data_uri_buffer(bytes_of(b)), R"({"buffer": 0, "byteLength": 9})",
                                             R"({"bufferView": 0, "componentType": 5121, "count": 3, "type": "VEC3"})")),
             "accessors[0]: POSITION of UNSIGNED_BYTE needs the extension KHR_mesh_quantization");
}

TEST(Gltf, OtherRequiredExtensionsAreRefusedByName) {
  const std::string e = error_of("draco.gltf", document(data_uri_buffer(bytes_of(kTriangle)), R"({"buffer": 0, "byteLength": 36})",
                                                        float_accessor(3), R"({"attributes": {"POSITION": 0}})",
                                                        R"(, "extensionsRequired": ["KHR_mesh_quantization", "KHR_draco_mesh_compression"])"));
  EXPECT_HAS(e, "extensionsRequired[1]: 'KHR_draco_mesh_compression' is not supported");
}

// Strings from the file reach the message quoted, their control characters as \xNN and cut
// to 64 bytes: a version, an extension's name or a URI with a line break once made a
// two-line message (found by fuzz_gltf).
TEST(Gltf, StringsFromTheFileAreQuotedOnOneLine) {
  EXPECT_HAS(error_of("version.gltf", R"({"asset": {"version": "1\nshpack: fake"}})"),
             "asset.version: '1\\x0ashpack: fake': only glTF 2.x is read");
  const std::string long_name(100, 'x');
  EXPECT_HAS(error_of("ext.gltf", R"({"asset": {"version": "2.0"}, "extensionsRequired": ["a\u001b[31m)" + long_name + R"("]})"),
             "extensionsRequired[0]: 'a\\x1b[31m" + long_name.substr(0, 58) + "...' is not supported");
  EXPECT_HAS(error_of("uri.gltf", document(R"({"byteLength": 36, "uri": "/x\r.bin"})", R"({"buffer": 0, "byteLength": 36})", float_accessor(3))),
             "buffers[0].uri: '/x\\x0d.bin': absolute paths are refused");
}

// ---- 3. sparse accessors ----

TEST(Gltf, SparseAccessorsSubstituteTheirValues) {
  // Base: the triangle; sparse: vertex 2 becomes (5, 6, 7). Bytes: 36 base, 4 index (uint16 + pad), 12 values.
  std::string bytes = bytes_of(kTriangle) + bytes_of(std::vector<std::uint16_t>{2, 0}) + bytes_of(std::vector<float>{5, 6, 7});
  const std::string views = R"({"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 4},
                               {"buffer": 0, "byteOffset": 40, "byteLength": 12})";
  const std::string sparse = R"(, "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 2}})";
  const TriangleMesh m = read("sparse.gltf", document(data_uri_buffer(bytes), views, float_accessor(3, sparse)));
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 5, 6, 7}));
  // Without a bufferView the base is zeros.
  const TriangleMesh z = read("sparse0.gltf", document(data_uri_buffer(bytes), views,
                                                       R"({"componentType": 5126, "count": 3, "type": "VEC3")" + sparse + "}"));
  EXPECT_EQ(z.vertices, (std::vector<double>{0, 0, 0, 0, 0, 0, 5, 6, 7}));
  // A substitution index beyond the accessor is refused.
  bytes = bytes_of(kTriangle) + bytes_of(std::vector<std::uint16_t>{3, 0}) + bytes_of(std::vector<float>{5, 6, 7});
  EXPECT_HAS(error_of("sparsebad.gltf", document(data_uri_buffer(bytes), views, float_accessor(3, sparse))),
             "accessors[0].sparse.indices: index 3 is beyond the accessor's count 3");
  // Sparse ranges are checked against their views.
  const std::string big = R"(, "sparse": {"count": 2, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 2}})";
  EXPECT_HAS(error_of("sparserange.gltf", document(data_uri_buffer(bytes), views, float_accessor(3, big))),
             "accessors[0].sparse.values: byteOffset 0 + 2 elements of 12 bytes exceeds its buffer view (12 bytes)");
}

// ---- 3. materials ----

TEST(Gltf, MaterialsGiveAlbedoAndEmissionPerPrimitive) {
  const std::string bytes = bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1});
  const std::string views = R"({"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36})";
  const std::string accessors = float_accessor(3) + R"(, {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"})";
  const std::string primitives = R"({"attributes": {"POSITION": 0}, "material": 1}, {"attributes": {"POSITION": 1}, "material": 0},
                                    {"attributes": {"POSITION": 0}})";
  const std::string materials = R"(, "materials": [
      {"name": "lamp", "emissiveFactor": [1, 0.5, 0.25], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}},
       "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.2, 0.3, 1]}},
      {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 1, 0.25, 0.5]}}])";
  const TriangleMesh m = read("mat.gltf", document(data_uri_buffer(bytes), views, accessors, primitives, materials));
  ASSERT_EQ(m.materials.size(), 2u);
  // In first-use order: materials[1] (baseColorFactor 1 lowered to kGltfMaxAlbedo), then materials[0].
  EXPECT_EQ(m.materials[0].label, "materials[1]");
  EXPECT_EQ(m.materials[0].albedo, (std::array<double, 3>{0.5, kGltfMaxAlbedo, 0.25}));
  EXPECT_EQ(m.materials[0].emission, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(m.materials[1].label, "materials[0] 'lamp'");
  EXPECT_EQ(m.materials[1].albedo, (std::array<double, 3>{0.1, 0.2, 0.3}));
  EXPECT_EQ(m.materials[1].emission, (std::array<double, 3>{4, 2, 1}));
  EXPECT_EQ(m.triangle_material, (std::vector<std::int32_t>{0, 1, -1}));
  const std::vector<MeshPart> parts = split_by_material(m);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0].material, -1);
  EXPECT_EQ(parts[1].material, 0);
  EXPECT_EQ(parts[2].material, 1);
  EXPECT_EQ(parts[2].vertices, (std::vector<double>{0, 0, 1, 1, 0, 1, 0, 1, 1}));
  EXPECT_EQ(parts[2].indices, (std::vector<std::uint32_t>{0, 1, 2}));
  // Out-of-range factors are refused with their path.
  EXPECT_HAS(error_of("badmat.gltf", document(data_uri_buffer(bytes), views, accessors, primitives,
                                              R"(, "materials": [{"emissiveFactor": [2, 0, 0]}, {}])")),
             "materials[0].emissiveFactor[0]: must be in [0, 1]");
}

// Through the loader: one shape per material, the material's factors as albedo and emission
// unless the scene entry gives its own, which then hold for every part.
TEST(Gltf, MaterialsReachTheSceneShapesUnlessTheSceneGivesItsOwn) {
  const std::string bytes = bytes_of(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1});
  const std::string views = R"({"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36})";
  const std::string accessors = float_accessor(3) + R"(, {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"})";
  const std::string primitives = R"({"attributes": {"POSITION": 0}, "material": 0}, {"attributes": {"POSITION": 1}, "material": 1})";
  const std::string materials = R"(, "materials": [
      {"name": "lamp", "emissiveFactor": [1, 0.5, 0.25], "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.2, 0.3, 1]}},
      {"name": "wood", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.4, 0.3, 1]}}])";
  shpack_test::write_scene("lamp.gltf", document(data_uri_buffer(bytes), views, accessors, primitives, materials));
  Scene s;
  const fs::path plain = shpack_test::write_scene("lamp.json", R"({"probes": [[0, 5, 0]], "effects": [],
    "geometry": [{"type": "mesh", "name": "lamp", "path": "lamp.gltf"}]})");
  ASSERT_TRUE(load_scene(plain, s).ok());
  ASSERT_EQ(s.geometry.size(), 2u);
  EXPECT_EQ(s.geometry[0].label, "geometry[0] 'lamp' materials[0] 'lamp'");
  EXPECT_EQ(s.geometry[0].albedo, (std::array<double, 3>{0.1, 0.2, 0.3}));
  EXPECT_EQ(s.geometry[0].emission, (std::array<double, 3>{1, 0.5, 0.25}));
  EXPECT_EQ(s.geometry[1].albedo, (std::array<double, 3>{0.5, 0.4, 0.3}));
  EXPECT_EQ(s.geometry[1].emission, (std::array<double, 3>{0, 0, 0}));
  EXPECT_EQ(s.geometry[1].indices.size(), 3u);
  const fs::path given = shpack_test::write_scene("lamp2.json", R"({"probes": [[0, 5, 0]], "effects": [],
    "geometry": [{"type": "mesh", "path": "lamp.gltf", "albedo": 0.7}]})");
  Scene t;
  ASSERT_TRUE(load_scene(given, t).ok());
  ASSERT_EQ(t.geometry.size(), 2u);
  for (const SceneShape& shape : t.geometry) EXPECT_EQ(shape.albedo, (std::array<double, 3>{0.7, 0.7, 0.7}));
  EXPECT_EQ(t.geometry[0].emission, (std::array<double, 3>{1, 0.5, 0.25}));  // not given: the material's
}

// ---- 3. node graphs ----

// nodes[k] has two children, both nodes[k + 1], for `levels` levels; the last holds the mesh.
std::string dag_document(int levels) {
  std::string nodes;
  for (int k = 0; k < levels; ++k)
    nodes += R"({"children": [)" + std::to_string(k + 1) + ", " + std::to_string(k + 1) + "]},";
  nodes += R"({"mesh": 0})";
  std::string doc = document(data_uri_buffer(bytes_of(kTriangle)), R"({"buffer": 0, "byteLength": 36})", float_accessor(3));
  set_nodes(doc, R"("nodes": [)" + nodes + "]");
  return doc;
}

TEST(Gltf, ANodeDagIsInstancedWithinTheBudgetAndRefusedBeyondIt) {
  // Three levels: 8 paths to the mesh, 8 triangles.
  const TriangleMesh m = read("dag3.gltf", dag_document(3));
  EXPECT_EQ(m.indices.size(), 24u);
  EXPECT_EQ(m.vertices.size(), 72u);
  // Thirty levels: 2^30 triangles, refused before anything is allocated.
  const std::string e = error_of("dag30.gltf", dag_document(30));
  EXPECT_HAS(e, "nodes: the scene instantiates 1073741824 triangles, more than the budget of 50000000");
  // A hundred levels: 2^100 paths, counted without overflow.
  EXPECT_HAS(error_of("dag100.gltf", dag_document(100)), "more than 2^64 triangles");
}

TEST(Gltf, NodeCyclesAreRefused) {
  std::string doc = document(data_uri_buffer(bytes_of(kTriangle)), R"({"buffer": 0, "byteLength": 36})", float_accessor(3));
  set_nodes(doc, R"("nodes": [{"mesh": 0, "children": [1]}, {"children": [2]}, {"children": [0]}])");
  EXPECT_HAS(error_of("cycle.gltf", doc), "nodes[2].children: node 0 is its own ancestor (a cycle)");
  doc = document(data_uri_buffer(bytes_of(kTriangle)), R"({"buffer": 0, "byteLength": 36})", float_accessor(3));
  set_nodes(doc, R"("nodes": [{"mesh": 0, "children": [0]}])");
  EXPECT_HAS(error_of("self.gltf", doc), "nodes[0].children: node 0 is its own ancestor (a cycle)");
}

TEST(Gltf, ALongNodeChainDoesNotOverflowTheStack) {
  std::string nodes;
  const int n = 50000;
  for (int k = 0; k < n; ++k) nodes += R"({"children": [)" + std::to_string(k + 1) + "]},";
  nodes += R"({"mesh": 0, "translation": [0, 0, 1]})";
  std::string doc = document(data_uri_buffer(bytes_of(kTriangle)), R"({"buffer": 0, "byteLength": 36})", float_accessor(3));
  set_nodes(doc, R"("nodes": [)" + nodes + "]");
  const TriangleMesh m = read("chain.gltf", doc);
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 1, 1, 0, 1, 0, 1, 1}));
}

// ---- containers ----

TEST(Gltf, GlbChunksAreChecked) {
  std::string json = document(R"({"byteLength": 36})", R"({"buffer": 0, "byteLength": 36})", float_accessor(3));
  while (json.size() % 4) json += ' ';
  const std::string bin = bytes_of(kTriangle);
  const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string glb = "glTF" + u32(2) + u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size())) +
                          u32(static_cast<std::uint32_t>(json.size())) + u32(0x4E4F534Au) + json +
                          u32(static_cast<std::uint32_t>(bin.size())) + u32(0x004E4942u) + bin;
  EXPECT_EQ(read("ok.glb", glb).vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  std::string huge = glb;
  const std::uint32_t big = 0xFFFFFFF0u;
  std::memcpy(huge.data() + 12, &big, 4);  // the JSON chunk's length
  EXPECT_HAS(error_of("huge.glb", huge), "a .glb chunk at byte 12 longer than the file");
  EXPECT_HAS(error_of("short.glb", glb.substr(0, 10)), "a .glb shorter than its 12-byte header");
}

// ---- lightmap UVs (TEXCOORD_1) and normals, with_uv ----

TriangleMesh read_uv(const std::string& name, const std::string& text) {
  return read_gltf(shpack_test::write_scene(name, text), {}, /*with_uv=*/true);
}

std::string error_of_uv(const std::string& name, const std::string& text) {
  try {
    read_uv(name, text);
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    return what;
  }
  return "";
}

// The triangle's positions (view 0, accessor 0) and `attribute` bytes after them (view 1).
std::string attribute_document(const std::string& attribute, const std::string& accessors, const std::string& primitive,
                               const std::string& extra = "") {
  const std::string bytes = bytes_of(kTriangle) + attribute;
  return document(data_uri_buffer(bytes),
                  R"({"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": )" +
                      std::to_string(attribute.size()) + "}",
                  float_accessor(3) + ", " + accessors, primitive, extra);
}

const std::string kQuantization = R"(, "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"])";

TEST(GltfUv, FloatTexcoord1IsCopiedAndCountedAsTheSecondSet) {
  const std::vector<float> uv = {0.25f, 0.5f, 1, 0.75f, 0.125f, 0};
  const std::string doc = attribute_document(bytes_of(uv), R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"})",
                                             R"({"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_1": 1}})");
  const TriangleMesh m = read_uv("uv1.gltf", doc);
  EXPECT_EQ(m.uv1, (std::vector<double>{0.25, 0.5, 1, 0.75, 0.125, 0}));
  EXPECT_EQ(m.texcoord_sets, 2);
  EXPECT_EQ(m.vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_TRUE(m.normals.empty());
  // Without with_uv: the same mesh, no UVs, the sets still counted.
  const TriangleMesh plain = read("uv1plain.gltf", doc);
  EXPECT_TRUE(plain.uv1.empty());
  EXPECT_EQ(plain.texcoord_sets, 2);
  EXPECT_EQ(plain.vertices, m.vertices);
  EXPECT_EQ(plain.indices, m.indices);
}

TEST(GltfUv, NormalizedUnsignedTexcoordsAreDividedByTheirMaximum) {
  const std::vector<std::uint16_t> u16 = {0, 65535, 32768, 1, 12345, 65534};
  const TriangleMesh m = read_uv("uv16.gltf", attribute_document(bytes_of(u16),
                                                                 R"({"bufferView": 1, "componentType": 5123, "normalized": true, "count": 3, "type": "VEC2"})",
                                                                 R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1}})"));
  EXPECT_EQ(m.uv1, (std::vector<double>{0, 1, 32768 / 65535.0, 1 / 65535.0, 12345 / 65535.0, 65534 / 65535.0}));
  EXPECT_EQ(m.texcoord_sets, 0);  // no TEXCOORD_0
  const std::vector<std::uint8_t> u8 = {0, 255, 51, 102, 1, 254};
  const TriangleMesh b = read_uv("uv8.gltf", attribute_document(bytes_of(u8),
                                                                R"({"bufferView": 1, "componentType": 5121, "normalized": true, "count": 3, "type": "VEC2"})",
                                                                R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1}})"));
  EXPECT_EQ(b.uv1, (std::vector<double>{0, 1, 51 / 255.0, 102 / 255.0, 1 / 255.0, 254 / 255.0}));
  // Unnormalized UNSIGNED_SHORT and (un)normalized SHORT need KHR_mesh_quantization, which
  // then gives the integers themselves or v / 32767.
  const std::string raw = R"({"bufferView": 1, "componentType": 5123, "count": 3, "type": "VEC2"})";
  const std::string prim = R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1}})";
  EXPECT_HAS(error_of_uv("uvraw.gltf", attribute_document(bytes_of(u16), raw, prim)),
             "accessors[1]: TEXCOORD_1 of UNSIGNED_SHORT needs the extension KHR_mesh_quantization");
  EXPECT_EQ(read_uv("uvrawq.gltf", attribute_document(bytes_of(u16), raw, prim, kQuantization)).uv1,
            (std::vector<double>{0, 65535, 32768, 1, 12345, 65534}));
  const std::vector<std::int16_t> s16 = {-32767, 32767, 16384, 0, -1, 7};
  EXPECT_EQ(read_uv("uvs16.gltf", attribute_document(bytes_of(s16),
                                                     R"({"bufferView": 1, "componentType": 5122, "normalized": true, "count": 3, "type": "VEC2"})",
                                                     prim, kQuantization))
                .uv1,
            (std::vector<double>{-1, 1, 16384 / 32767.0, 0, -1 / 32767.0, 7 / 32767.0}));
  EXPECT_HAS(error_of_uv("uvs16noext.gltf", attribute_document(bytes_of(s16),
                                                               R"({"bufferView": 1, "componentType": 5122, "normalized": true, "count": 3, "type": "VEC2"})",
                                                               prim)),
             "accessors[1]: TEXCOORD_1 of normalized SHORT needs the extension KHR_mesh_quantization");
  // Never UNSIGNED_INT, never anything but VEC2.
  EXPECT_HAS(error_of_uv("uvint.gltf", attribute_document(bytes_of(std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}),
                                                          R"({"bufferView": 1, "componentType": 5125, "count": 3, "type": "VEC2"})",
                                                          prim, kQuantization)),
             "accessors[1]: TEXCOORD_1 of UNSIGNED_INT is not allowed");
  EXPECT_HAS(error_of_uv("uvvec3.gltf", attribute_document(bytes_of(kTriangle), R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"})",
                                                           prim)),
             "accessors[1]: TEXCOORD_1 must be VEC2, not 'VEC3'");
}

TEST(GltfUv, SparseTexcoord1SubstitutesItsValues) {
  // Base: three UVs; sparse: vertex 1 becomes (0.5, 0.25). Bytes after the positions: 24 base,
  // 4 index (uint16 + pad), 8 values.
  const std::string attribute = bytes_of(std::vector<float>{0, 0, 1, 0, 0, 1}) + bytes_of(std::vector<std::uint16_t>{1, 0}) +
                                bytes_of(std::vector<float>{0.5f, 0.25f});
  const std::string bytes = bytes_of(kTriangle) + attribute;
  const std::string views = R"({"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                               {"buffer": 0, "byteOffset": 60, "byteLength": 4}, {"buffer": 0, "byteOffset": 64, "byteLength": 8})";
  const std::string sparse = R"("sparse": {"count": 1, "indices": {"bufferView": 2, "componentType": 5123}, "values": {"bufferView": 3}})";
  const TriangleMesh m = read_uv("uvsparse.gltf", document(data_uri_buffer(bytes), views,
                                                           float_accessor(3) + R"(, {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2", )" +
                                                               sparse + "}",
                                                           R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1}})"));
  EXPECT_EQ(m.uv1, (std::vector<double>{0, 0, 0.5, 0.25, 0, 1}));
  // Without a bufferView the base is zeros.
  const TriangleMesh z = read_uv("uvsparse0.gltf", document(data_uri_buffer(bytes), views,
                                                            float_accessor(3) + R"(, {"componentType": 5126, "count": 3, "type": "VEC2", )" + sparse + "}",
                                                            R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1}})"));
  EXPECT_EQ(z.uv1, (std::vector<double>{0, 0, 0.5, 0.25, 0, 0}));
}

TEST(GltfUv, ATexcoord1CountOtherThanPositionsIsRefusedNamingTheAccessor) {
  const std::vector<float> uv = {0, 0, 1, 0, 0, 1};
  const std::string doc = attribute_document(bytes_of(uv), R"({"bufferView": 1, "componentType": 5126, "count": 2, "type": "VEC2"})",
                                             R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1}})");
  EXPECT_HAS(error_of_uv("uvcount.gltf", doc),
             "accessors[1]: TEXCOORD_1 of meshes[0].primitives[0] has count 2, but its POSITION (accessors[0]) has 3");
  // A caller that does not ask for UVs reads the file as before.
  EXPECT_EQ(read("uvcountplain.gltf", doc).vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  // Ranges and finiteness are checked as POSITION's are.
  EXPECT_HAS(error_of_uv("uvrange.gltf", attribute_document(bytes_of(uv), R"({"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"})",
                                                            R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1}})")),
             "accessors[1]: count 4 (byteOffset 0, byteStride 8) exceeds its buffer view (24 bytes)");
  const std::vector<float> nan = {0, 0, 1, std::nanf(""), 0, 1};
  EXPECT_HAS(error_of_uv("uvnan.gltf", attribute_document(bytes_of(nan), R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"})",
                                                          R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1}})")),
             "accessors[1]: TEXCOORD_1 of vertex 1 is not finite");
  EXPECT_HAS(error_of_uv("uvmissing.gltf", attribute_document(bytes_of(uv), R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"})",
                                                              R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 7}})")),
             "meshes[0].primitives[0].attributes.TEXCOORD_1: accessors[7] does not exist (2 accessors)");
}

TEST(GltfUv, UvSetsAreCountedAndTexcoord1ReadOnlyWhenEveryPrimitiveHasIt) {
  const std::vector<float> uv = {0, 0, 1, 0, 0, 1};
  const std::string accessor = R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"})";
  // Only TEXCOORD_0: one set, no lightmap UVs.
  const TriangleMesh one = read_uv("uv0.gltf", attribute_document(bytes_of(uv), accessor, R"({"attributes": {"POSITION": 0, "TEXCOORD_0": 1}})"));
  EXPECT_TRUE(one.uv1.empty());
  EXPECT_EQ(one.texcoord_sets, 1);
  // No TEXCOORD at all: none.
  const TriangleMesh none = read_uv("uvnone.gltf", attribute_document(bytes_of(uv), accessor, R"({"attributes": {"POSITION": 0}})"));
  EXPECT_TRUE(none.uv1.empty());
  EXPECT_EQ(none.texcoord_sets, 0);
  // Two primitives, one without TEXCOORD_1 (whose broken TEXCOORD_1 elsewhere is then not
  // read either): no uv1, and the least number of sets.
  const TriangleMesh mixed = read_uv("uvmixed.gltf", attribute_document(bytes_of(uv), accessor,
                                                                        R"({"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_1": 1, "TEXCOORD_2": 1}},
                                                                           {"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_1": 9}},
                                                                           {"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "TEXCOORD_2": 1}})"));
  EXPECT_TRUE(mixed.uv1.empty());
  EXPECT_EQ(mixed.texcoord_sets, 1);
  EXPECT_EQ(mixed.vertices.size(), 27u);
}

TEST(GltfUv, NormalsAreTransformedByTheInverseTransposeAndNormalised) {
  // The node: scale x by 2, then rotate 90 degrees about z ((x, y, z) -> (-y, x, z)), then move.
  // Its inverse transpose is R S^-1: (1, 1, 0) -> (0.5, 1, 0) -> (-1, 0.5, 0), normalised
  // (-2, 1, 0) / sqrt(5); M itself would give (-1, 2, 0) / sqrt(5).
  const std::vector<float> n = {1, 1, 0, 1, 0, 0, 0, 0, 3};
  std::string doc = attribute_document(bytes_of(n), R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"})",
                                       R"({"attributes": {"POSITION": 0, "NORMAL": 1}})");
  set_nodes(doc, R"("nodes": [{"mesh": 0, "matrix": [0, 2, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1]}])");
  const TriangleMesh m = read_uv("normals.gltf", doc);
  EXPECT_EQ(m.vertices, (std::vector<double>{5, 6, 7, 5, 8, 7, 4, 6, 7}));
  const std::vector<double> want = {-2 / std::sqrt(5.0), 1 / std::sqrt(5.0), 0, 0, 1, 0, 0, 0, 1};
  ASSERT_EQ(m.normals.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) EXPECT_NEAR(m.normals[k], want[k], 1e-15) << k;
  EXPECT_TRUE(read("normalsplain.gltf", doc).normals.empty());
  // A mirroring node turns normals with the surface; a zero normal stays zero.
  const std::vector<float> z = {1, 0, 0, 0, 0, 0, 0, 1, 0};
  std::string mirror = attribute_document(bytes_of(z), R"({"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"})",
                                          R"({"attributes": {"POSITION": 0, "NORMAL": 1}})");
  set_nodes(mirror, R"("nodes": [{"mesh": 0, "scale": [-1, 3, 1]}])");
  EXPECT_EQ(read_uv("mirror.gltf", mirror).normals, (std::vector<double>{-1, 0, 0, 0, 0, 0, 0, 1, 0}));
  // Quantized normals: normalized BYTE under KHR_mesh_quantization, refused without it.
  const std::vector<std::int8_t> b = {127, 0, 0, 0, 0, -127, 0, 0, 0, 0, 127, 0};  // VEC3 + a padding byte each
  const std::string quantized = R"({"bufferView": 1, "componentType": 5120, "normalized": true, "count": 3, "type": "VEC3"})";
  std::string qdoc = attribute_document(bytes_of(b), quantized, R"({"attributes": {"POSITION": 0, "NORMAL": 1}})", kQuantization);
  qdoc.replace(qdoc.find(R"("byteLength": 12})"), 17, R"("byteLength": 12, "byteStride": 4})");
  EXPECT_EQ(read_uv("qnormals.gltf", qdoc).normals, (std::vector<double>{1, 0, 0, 0, -1, 0, 0, 0, 1}));
  EXPECT_HAS(error_of_uv("qnormalsnoext.gltf", attribute_document(bytes_of(b), quantized, R"({"attributes": {"POSITION": 0, "NORMAL": 1}})")),
             "accessors[1]: NORMAL of normalized BYTE needs the extension KHR_mesh_quantization");
  EXPECT_HAS(error_of_uv("normalsu8.gltf", attribute_document(bytes_of(b), R"({"bufferView": 1, "componentType": 5121, "normalized": true, "count": 3, "type": "VEC3"})",
                                                              R"({"attributes": {"POSITION": 0, "NORMAL": 1}})", kQuantization)),
             "accessors[1]: NORMAL of normalized UNSIGNED_BYTE is not allowed");
}

TEST(GltfUv, SplitByMaterialCarriesUvsAndNormals) {
  // Primitive 0 (material 0) and 1 (no material) share the positions; their UVs differ.
  const std::string attribute = bytes_of(std::vector<float>{0, 0, 1, 0, 0, 1, 0.5f, 0.5f, 0.25f, 0.25f, 0.75f, 0.75f}) +
                                bytes_of(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1});
  const std::string bytes = bytes_of(kTriangle) + attribute;
  const std::string views = R"({"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                               {"buffer": 0, "byteOffset": 60, "byteLength": 24}, {"buffer": 0, "byteOffset": 84, "byteLength": 36})";
  const std::string accessors = float_accessor(3) + R"(, {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
      {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}, {"bufferView": 3, "componentType": 5126, "count": 3, "type": "VEC3"})";
  const TriangleMesh m = read_uv("uvparts.gltf", document(data_uri_buffer(bytes), views, accessors,
                                                          R"({"attributes": {"POSITION": 0, "TEXCOORD_1": 1, "NORMAL": 3}, "material": 0},
                                                             {"attributes": {"POSITION": 0, "TEXCOORD_1": 2, "NORMAL": 3}})",
                                                          R"(, "materials": [{}])"));
  ASSERT_EQ(m.uv1.size(), 12u);
  const std::vector<MeshPart> parts = split_by_material(m);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].material, -1);
  EXPECT_EQ(parts[0].uv1, (std::vector<double>{0.5, 0.5, 0.25, 0.25, 0.75, 0.75}));
  EXPECT_EQ(parts[0].normals, (std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(parts[1].material, 0);
  EXPECT_EQ(parts[1].uv1, (std::vector<double>{0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(parts[1].vertices, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  // Without UVs the parts have none.
  for (const MeshPart& part : split_by_material(read("uvpartsplain.gltf", document(data_uri_buffer(bytes), views, accessors))))
    EXPECT_TRUE(part.uv1.empty() && part.normals.empty());
}

}  // namespace
}  // namespace shpack::scene::detail
