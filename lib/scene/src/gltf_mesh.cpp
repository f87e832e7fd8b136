#include "gltf_mesh.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "checked_math.h"
#include "shpack/io/file_checks.h"
#include "shpack/io/quoted.h"

namespace shpack::scene::detail {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using u64 = std::uint64_t;
using Matrix4 = std::array<double, 16>;  // column-major, as glTF stores node.matrix
constexpr Matrix4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
constexpr u64 kMaxU64 = std::numeric_limits<u64>::max();

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw std::runtime_error(path.empty() ? problem : path + ": " + problem);
}

std::string index_path(const std::string& path, u64 i) { return path + "[" + std::to_string(i) + "]"; }
std::string member_path(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }

// ---- JSON values, each checked and named by its path --------------------------------------

const Json* find(const Json& obj, const char* key) {
  if (!obj.is_object()) return nullptr;
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

const Json& object_at(const Json& j, const std::string& path) {
  if (!j.is_object()) fail(path, "must be an object");
  return j;
}

const Json& array_at(const Json& j, const std::string& path) {
  if (!j.is_array()) fail(path, "must be an array");
  return j;
}

const Json& required(const Json& obj, const char* key, const std::string& path) {
  const Json* v = find(obj, key);
  if (v == nullptr) fail(path, std::string("has no ") + key);
  return *v;
}

// A non-negative integer; 3.0 is accepted, 1.5, -1 and 1e300 are not.
u64 unsigned_of(const Json& j, const std::string& path) {
  if (j.is_number_unsigned()) return j.get<u64>();
  if (j.is_number_integer()) fail(path, std::to_string(j.get<std::int64_t>()) + " must be a non-negative integer");
  if (j.is_number_float()) {
    const double d = j.get<double>();
    if (d >= 0 && d < 9007199254740992.0 && std::floor(d) == d) return static_cast<u64>(d);
    fail(path, j.dump() + " must be a non-negative integer");
  }
  fail(path, "must be a non-negative integer");
}

u64 unsigned_or(const Json& obj, const char* key, u64 fallback, const std::string& path) {
  const Json* v = find(obj, key);
  return v == nullptr ? fallback : unsigned_of(*v, member_path(path, key));
}

double number_of(const Json& j, const std::string& path) {
  if (!j.is_number()) fail(path, "must be a number");
  const double d = j.get<double>();
  if (!std::isfinite(d)) fail(path, "must be finite");
  return d;
}

// `count` numbers from an array of exactly that size.
template <std::size_t N>
std::array<double, N> numbers_of(const Json& j, const std::string& path) {
  if (!j.is_array() || j.size() != N) fail(path, "must be an array of " + std::to_string(N) + " numbers");
  std::array<double, N> out{};
  for (std::size_t k = 0; k < N; ++k) out[k] = number_of(j[k], index_path(path, k));
  return out;
}

std::string string_of(const Json& j, const std::string& path) {
  if (!j.is_string()) fail(path, "must be a string");
  return j.get<std::string>();
}

// ---- files ----------------------------------------------------------------------------------

// The whole of a regular file of at most `limit` bytes. Opened without blocking and checked
// again on the open descriptor, so a FIFO or a device put in its place is refused too.
std::string read_regular_file(const fs::path& path, u64 limit) {
  if (io::IoStatus st = io::detail::check_regular_file(path); !st.ok()) throw std::runtime_error(st.message);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw std::runtime_error(path.string() + ": cannot open: " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat info {};
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) throw std::runtime_error(path.string() + ": is not a regular file");
  const auto size = static_cast<u64>(info.st_size);
  if (size > limit)
    throw std::runtime_error(path.string() + ": " + std::to_string(size) + " bytes, more than the limit of " +
                             std::to_string(limit));
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error(path.string() + ": " + (n < 0 ? std::strerror(errno) : "shorter than its size"));
    done += static_cast<std::size_t>(n);
  }
  return bytes;
}

// RFC 4648 base64 (the body of a data URI): padding only at the end, nothing but the alphabet.
std::string base64_decode(std::string_view text, const std::string& path) {
  std::string out;
  out.reserve(text.size() / 4 * 3);
  std::uint32_t value = 0;
  int bits = 0;
  std::size_t k = 0;
  for (; k < text.size() && text[k] != '='; ++k) {
    const char ch = text[k];
    int v;
    if (ch >= 'A' && ch <= 'Z') v = ch - 'A';
    else if (ch >= 'a' && ch <= 'z') v = ch - 'a' + 26;
    else if (ch >= '0' && ch <= '9') v = ch - '0' + 52;
    else if (ch == '+') v = 62;
    else if (ch == '/') v = 63;
    else fail(path, "bad base64 in a data URI");
    value = ((value << 6) | static_cast<std::uint32_t>(v)) & 0xFFFFFFu;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((value >> bits) & 0xFF));
    }
  }
  for (; k < text.size(); ++k)
    if (text[k] != '=') fail(path, "bad base64 in a data URI");
  return out;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// A buffer's relative URI as a path under `folder`: percent escapes decoded (Blender writes
// %20); schemes (file:, http:), absolute paths and `..` that leaves the folder refused.
fs::path resolve_uri(const std::string& uri, const fs::path& folder, const std::string& path) {
  std::size_t scheme = 0;
  while (scheme < uri.size() && (std::isalnum(static_cast<unsigned char>(uri[scheme])) || uri[scheme] == '+' ||
                                 uri[scheme] == '-' || uri[scheme] == '.'))
    ++scheme;
  if (scheme > 0 && scheme < uri.size() && uri[scheme] == ':' && std::isalpha(static_cast<unsigned char>(uri[0])))
    fail(path, io::quoted(uri) + ": absolute URIs are refused (only files beside the glTF file)");
  std::string decoded;
  for (std::size_t k = 0; k < uri.size(); ++k) {
    if (uri[k] != '%') {
      decoded += uri[k];
      continue;
    }
    const int hi = k + 2 < uri.size() ? hex_digit(uri[k + 1]) : -1, lo = k + 2 < uri.size() ? hex_digit(uri[k + 2]) : -1;
    if (hi < 0 || lo < 0) fail(path, io::quoted(uri) + ": a bad percent escape");
    decoded += static_cast<char>(hi * 16 + lo);
    k += 2;
  }
  if (decoded.find('\0') != std::string::npos) fail(path, io::quoted(uri) + ": a NUL byte");
  if (!decoded.empty() && decoded[0] == '/') fail(path, io::quoted(uri) + ": absolute paths are refused (only files beside the glTF file)");
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start <= decoded.size()) {
    const std::size_t end = std::min(decoded.find('/', start), decoded.size());
    const std::string part = decoded.substr(start, end - start);
    if (part == "..") {
      if (parts.empty()) fail(path, io::quoted(uri) + ": leaves the glTF file's folder");
      parts.pop_back();
    } else if (!part.empty() && part != ".") {
      parts.push_back(part);
    }
    start = end + 1;
  }
  if (parts.empty()) fail(path, io::quoted(uri) + ": names no file");
  fs::path out = folder;
  for (const std::string& part : parts) out /= part;
  return out;
}

// ---- transforms -------------------------------------------------------------------------------

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
  Matrix4 c{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) c[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
  return c;
}

// T * R * S of a node (glTF 2.0, section 5.25: rotation a unit quaternion [x, y, z, w]).
Matrix4 local_matrix(const Json& node, const std::string& path) {
  if (const Json* m = find(node, "matrix")) {
    const std::array<double, 16> v = numbers_of<16>(*m, member_path(path, "matrix"));
    return v;
  }
  std::array<double, 3> t{0, 0, 0}, s{1, 1, 1};
  std::array<double, 4> q{0, 0, 0, 1};
  if (const Json* j = find(node, "translation")) t = numbers_of<3>(*j, member_path(path, "translation"));
  if (const Json* j = find(node, "scale")) s = numbers_of<3>(*j, member_path(path, "scale"));
  if (const Json* j = find(node, "rotation")) q = numbers_of<4>(*j, member_path(path, "rotation"));
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  Matrix4 m{};
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) m[col * 4 + row] = r[row][col] * s[col];
  m[12] = t[0];
  m[13] = t[1];
  m[14] = t[2];
  m[15] = 1;
  return m;
}

// ---- accessors ------------------------------------------------------------------------------

constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
              kFloat = 5126;

u64 component_size(int type) {
  switch (type) {
    case kByte:
    case kUnsignedByte: return 1;
    case kShort:
    case kUnsignedShort: return 2;
    case kUnsignedInt:
    case kFloat: return 4;
    default: return 0;
  }
}

const char* component_name(int type) {
  switch (type) {
    case kByte: return "BYTE";
    case kUnsignedByte: return "UNSIGNED_BYTE";
    case kShort: return "SHORT";
    case kUnsignedShort: return "UNSIGNED_SHORT";
    case kUnsignedInt: return "UNSIGNED_INT";
    case kFloat: return "FLOAT";
    default: return "unknown";
  }
}

// One component at p, as glTF reads it (section 3.11: normalized integers to [-1, 1] or [0, 1]).
double read_component(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case kByte: {
      const auto v = static_cast<std::int8_t>(*p);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case kUnsignedByte: return normalized ? *p / 255.0 : *p;
    case kShort: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case kUnsignedShort: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case kUnsignedInt: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

// Where an accessor's bytes are, every range checked: element k, component c is at
// data + k * stride + c * component bytes, for k < count (data null: all zeros).
struct Layout {
  std::string path;  // "accessors[3]"
  const unsigned char* data = nullptr;
  u64 count = 0, stride = 0, element = 0;
  int type = 0, components = 0;
  bool normalized = false;
  // Sparse substitutions: `sparse_count` indices (of `sparse_index_type`) and values, tightly packed.
  u64 sparse_count = 0;
  const unsigned char* sparse_indices = nullptr;
  const unsigned char* sparse_values = nullptr;
  int sparse_index_type = 0;
};

// What an accessor holds, for layout()'s checks of its type and component type.
enum class Role : std::uint8_t { Position, Index, Texcoord, Normal };

struct Primitive {
  std::string path;       // "meshes[0].primitives[1]"
  Layout positions;
  std::optional<Layout> indices;
  // TEXCOORD_1 and NORMAL: the attributes' values, not yet checked (a caller that does not
  // ask for them is not refused over them), and their layouts once read() has decided to read
  // them (only when asked and every primitive has them).
  const Json* uv1_accessor = nullptr;
  const Json* normal_accessor = nullptr;
  std::optional<Layout> uv1, normals;
  int texcoord_sets = 0;  // TEXCOORD_0 .. TEXCOORD_{n-1} all present
  int mode = 4;
  std::int32_t material = -1;  // index into the glTF's materials
  u64 triangles = 0;
};

class Reader {
 public:
  Reader(std::string_view bytes, fs::path folder, const GltfLimits& limits) : folder_(std::move(folder)), limits_(limits) {
    if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
      read_glb(bytes);
    } else {
      if (bytes.size() > limits_.max_json_bytes) fail("", "the JSON is larger than " + std::to_string(limits_.max_json_bytes) + " bytes");
      doc_ = Json::parse(bytes);
    }
    object_at(doc_, "the document");
    check_asset_and_extensions();
  }

  TriangleMesh read(bool with_uv) {
    const std::vector<u64> roots = scene_roots();
    const std::vector<u64> order = topological_order(roots);  // parents before children
    // Instances of each node: the number of paths to it from the roots (saturating).
    std::vector<u64> paths(node_count_, 0);
    for (const u64 r : roots) paths[r] = saturating_add(paths[r], 1);
    u64 node_instances = 0;
    std::map<u64, u64> mesh_instances;  // mesh index -> instances
    for (const u64 n : order) {
      node_instances = saturating_add(node_instances, paths[n]);
      for (const u64 c : children_[n]) paths[c] = saturating_add(paths[c], paths[n]);
      if (const Json* m = find(node(n), "mesh")) {
        const std::string mpath = member_path(index_path("nodes", n), "mesh");
        const u64 mesh = unsigned_of(*m, mpath);
        element("meshes", mesh, mpath);
        mesh_instances[mesh] = saturating_add(mesh_instances[mesh], paths[n]);
      }
    }
    // What the instances cost, from the accessors' counts (every range checked, nothing read).
    std::map<u64, std::vector<Primitive>> meshes;
    u64 triangles = 0, vertices = 0;
    for (const auto& [mesh, instances] : mesh_instances) {
      std::vector<Primitive>& primitives = meshes[mesh];
      primitives = mesh_primitives(mesh);
      for (const Primitive& p : primitives) {
        triangles = saturating_add(triangles, saturating_mul(p.triangles, instances));
        vertices = saturating_add(vertices, saturating_mul(p.positions.count, instances));
      }
    }
    const auto more = [](u64 v) { return v == kMaxU64 ? "more than 2^64" : std::to_string(v); };
    if (triangles > limits_.max_triangles)
      fail("nodes", "the scene instantiates " + more(triangles) + " triangles, more than the budget of " +
                        std::to_string(limits_.max_triangles));
    if (vertices > limits_.max_vertices || vertices > std::numeric_limits<std::uint32_t>::max())
      fail("nodes", "the scene instantiates " + more(vertices) + " vertices, more than the budget of " +
                        std::to_string(std::min<u64>(limits_.max_vertices, std::numeric_limits<std::uint32_t>::max())));
    if (node_instances > limits_.max_node_instances)
      fail("nodes", "the scene instantiates " + more(node_instances) + " nodes, more than the budget of " +
                        std::to_string(limits_.max_node_instances) + " (nodes shared by several parents multiply)");

    TriangleMesh out;
    // TEXCOORD_1 and NORMAL: read (and checked, before anything is decoded) only when asked
    // for and every instanced primitive has them; otherwise uv1 / normals stay empty.
    bool any = false, all_uv1 = true, all_normals = true;
    int sets = std::numeric_limits<int>::max();
    for (const auto& [mesh, primitives] : meshes)
      for (const Primitive& p : primitives) {
        any = true;
        sets = std::min(sets, p.texcoord_sets);
        all_uv1 = all_uv1 && p.uv1_accessor != nullptr;
        all_normals = all_normals && p.normal_accessor != nullptr;
      }
    out.texcoord_sets = any ? sets : 0;
    const bool read_uv1 = with_uv && any && all_uv1, read_normals = with_uv && any && all_normals;
    for (auto& [mesh, primitives] : meshes)
      for (Primitive& p : primitives) {
        if (read_uv1) p.uv1 = attribute_layout(p, *p.uv1_accessor, "TEXCOORD_1", Role::Texcoord);
        if (read_normals) p.normals = attribute_layout(p, *p.normal_accessor, "NORMAL", Role::Normal);
      }

    // Each mesh decoded once, in its own space, then placed by every path to it.
    struct Decoded {
      std::vector<double> positions;
      std::vector<std::uint32_t> triangles;
      std::int32_t material;
      std::vector<double> uv1, normals;
    };
    std::map<u64, std::vector<Decoded>> decoded;
    for (auto& [mesh, primitives] : meshes)
      for (const Primitive& p : primitives)
        decoded[mesh].push_back({decode_positions(p), triangulate(p), p.material,
                                 p.uv1 ? decode_finite(*p.uv1, "TEXCOORD_1") : std::vector<double>{},
                                 p.normals ? decode_finite(*p.normals, "NORMAL") : std::vector<double>{}});

    out.vertices.reserve(static_cast<std::size_t>(vertices) * 3);
    if (read_uv1) out.uv1.reserve(static_cast<std::size_t>(vertices) * 2);
    if (read_normals) out.normals.reserve(static_cast<std::size_t>(vertices) * 3);
    out.indices.reserve(static_cast<std::size_t>(triangles) * 3);
    out.triangle_material.reserve(static_cast<std::size_t>(triangles));
    std::map<std::int32_t, std::int32_t> material_slot;  // glTF material -> out.materials index
    struct Visit {
      u64 node;
      Matrix4 parent;
    };
    std::vector<Visit> stack;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, kIdentity});
    while (!stack.empty()) {
      const Visit v = stack.back();
      stack.pop_back();
      const Matrix4 world = multiply(v.parent, locals_[v.node]);
      if (const Json* m = find(node(v.node), "mesh")) {
        for (const Decoded& d : decoded.at(m->get<u64>())) {
          const auto base = static_cast<std::uint32_t>(out.vertices.size() / 3);
          for (std::size_t k = 0; k + 2 < d.positions.size(); k += 3) {
            const double x = d.positions[k], y = d.positions[k + 1], z = d.positions[k + 2];
            for (int row = 0; row < 3; ++row) {
              const double w = world[row] * x + world[4 + row] * y + world[8 + row] * z + world[12 + row];
              if (!(std::fabs(w) <= std::numeric_limits<float>::max()))
                fail(index_path("nodes", v.node), "its transform takes a vertex of meshes[" + m->dump() + "] beyond float range");
              out.vertices.push_back(w);
            }
          }
          out.uv1.insert(out.uv1.end(), d.uv1.begin(), d.uv1.end());
          if (!d.normals.empty()) place_normals(world, d.normals, out.normals);
          std::int32_t slot = -1;
          if (d.material >= 0) {
            const auto [it, added] = material_slot.emplace(d.material, static_cast<std::int32_t>(out.materials.size()));
            if (added) out.materials.push_back(material(static_cast<u64>(d.material)));
            slot = it->second;
          }
          for (const std::uint32_t i : d.triangles) out.indices.push_back(base + i);
          out.triangle_material.insert(out.triangle_material.end(), d.triangles.size() / 3, slot);
        }
      }
      const std::vector<u64>& children = children_[v.node];
      for (auto c = children.rbegin(); c != children.rend(); ++c) stack.push_back({*c, world});
    }
    return out;
  }

 private:
  // ---- container and document ----

  void read_glb(std::string_view bytes) {
    // 12-byte header (magic, version 2, length), then chunks of (length, type, data): JSON
    // first, then at most one BIN.
    const auto u32 = [&](u64 at) {
      std::uint32_t v;
      std::memcpy(&v, bytes.data() + at, 4);
      return static_cast<u64>(v);
    };
    if (bytes.size() < 12) fail("", "a .glb shorter than its 12-byte header");
    if (u32(4) != 2) fail("", "a .glb of version " + std::to_string(u32(4)) + " (only 2 is read)");
    if (u32(8) > bytes.size()) fail("", "a .glb whose header says " + std::to_string(u32(8)) + " bytes, but the file has " + std::to_string(bytes.size()));
    const u64 total = u32(8);
    u64 at = 12;
    bool json = false, bin = false;
    while (at < total) {
      if (total - at < 8) fail("", "a truncated .glb chunk header at byte " + std::to_string(at));
      const u64 length = u32(at), type = u32(at + 4);
      if (length > total - at - 8) fail("", "a .glb chunk at byte " + std::to_string(at) + " longer than the file");
      const std::string_view chunk = bytes.substr(static_cast<std::size_t>(at + 8), static_cast<std::size_t>(length));
      if (!json) {
        if (type != 0x4E4F534Au) fail("", "a .glb whose first chunk is not JSON");
        if (length > limits_.max_json_bytes) fail("", "the JSON is larger than " + std::to_string(limits_.max_json_bytes) + " bytes");
        doc_ = Json::parse(chunk);
        json = true;
      } else if (type == 0x004E4942u) {
        if (bin) fail("", "a .glb with two BIN chunks");
        bin_ = chunk;
        bin = true;
      }  // other chunk types are skipped, as the spec asks
      at += 8 + length;
    }
    if (!json) fail("", "a .glb without a JSON chunk");
    glb_ = true;
    has_bin_ = bin;
  }

  void check_asset_and_extensions() {
    const Json& asset = required(doc_, "asset", "");
    object_at(asset, "asset");
    const std::string version = string_of(required(asset, "version", "asset"), "asset.version");
    if (version.rfind("2.", 0) != 0) fail("asset.version", io::quoted(version) + ": only glTF 2.x is read");
    const auto names = [&](const char* key) {
      std::vector<std::string> out;
      if (const Json* list = find(doc_, key)) {
        array_at(*list, key);
        for (std::size_t k = 0; k < list->size(); ++k) out.push_back(string_of((*list)[k], index_path(key, k)));
      }
      return out;
    };
    const std::vector<std::string> used = names("extensionsUsed"), required_ext = names("extensionsRequired");
    for (std::size_t k = 0; k < required_ext.size(); ++k)
      if (required_ext[k] != "KHR_mesh_quantization" && required_ext[k] != "KHR_materials_emissive_strength")
        fail(index_path("extensionsRequired", k), io::quoted(required_ext[k]) +
                 " is not supported (supported: KHR_mesh_quantization, KHR_materials_emissive_strength)");
    for (const auto* list : {&used, &required_ext})
      if (std::find(list->begin(), list->end(), "KHR_mesh_quantization") != list->end()) quantization_ = true;
    if (const Json* nodes = find(doc_, "nodes")) node_count_ = array_at(*nodes, "nodes").size();
  }

  // An element of a top-level array, referenced from `from`.
  const Json& element(const char* array, u64 index, const std::string& from) {
    const Json* list = find(doc_, array);
    if (list != nullptr) array_at(*list, array);
    const u64 size = list == nullptr ? 0 : list->size();
    if (index >= size) fail(from, std::string(array) + "[" + std::to_string(index) + "] does not exist (" + std::to_string(size) + " " + array + ")");
    return object_at((*list)[static_cast<std::size_t>(index)], index_path(array, index));
  }

  const Json& node(u64 n) { return (*find(doc_, "nodes"))[static_cast<std::size_t>(n)]; }

  // ---- the node graph ----

  std::vector<u64> scene_roots() {
    std::vector<u64> roots;
    const Json* scenes = find(doc_, "scenes");
    if (scenes != nullptr) array_at(*scenes, "scenes");
    if (const Json* s = find(doc_, "scene")) {
      const u64 index = unsigned_of(*s, "scene");
      element("scenes", index, "scene");
    }
    if (scenes != nullptr && !scenes->empty()) {
      const u64 index = unsigned_or(doc_, "scene", 0, "");
      const std::string path = index_path("scenes", index);
      const Json& scene = element("scenes", index, "scene");
      if (const Json* nodes = find(scene, "nodes")) {
        array_at(*nodes, member_path(path, "nodes"));
        for (std::size_t k = 0; k < nodes->size(); ++k) {
          const std::string from = index_path(member_path(path, "nodes"), k);
          const u64 n = unsigned_of((*nodes)[k], from);
          element("nodes", n, from);
          roots.push_back(n);
        }
      }
      return roots;
    }
    // No scene: every node that is no node's child.
    std::vector<bool> child(node_count_, false);
    for (u64 n = 0; n < node_count_; ++n)
      for (const u64 c : node_children(n)) child[c] = true;
    for (u64 n = 0; n < node_count_; ++n)
      if (!child[n]) roots.push_back(n);
    return roots;
  }

  std::vector<u64> node_children(u64 n) {
    const std::string path = index_path("nodes", n);
    const Json& obj = element("nodes", n, path);
    std::vector<u64> out;
    if (const Json* children = find(obj, "children")) {
      array_at(*children, member_path(path, "children"));
      for (std::size_t k = 0; k < children->size(); ++k) {
        const std::string from = index_path(member_path(path, "children"), k);
        const u64 c = unsigned_of((*children)[k], from);
        element("nodes", c, from);
        out.push_back(c);
      }
    }
    return out;
  }

  // The nodes reachable from the roots, parents before children (an iterative depth-first
  // search, so a long chain cannot overflow the stack); a cycle is refused. Fills children_
  // and locals_ for those nodes.
  std::vector<u64> topological_order(const std::vector<u64>& roots) {
    children_.assign(node_count_, {});
    locals_.assign(node_count_, kIdentity);
    std::vector<std::uint8_t> state(node_count_, 0);  // 0 unseen, 1 on the path, 2 done
    std::vector<u64> post;
    struct Frame {
      u64 node;
      std::size_t next;
    };
    std::vector<Frame> stack;
    for (const u64 root : roots) {
      if (state[root] != 0) continue;
      const auto enter = [&](u64 n) {
        state[n] = 1;
        children_[n] = node_children(n);
        locals_[n] = local_matrix(node(n), index_path("nodes", n));
        stack.push_back({n, 0});
      };
      enter(root);
      while (!stack.empty()) {
        Frame& f = stack.back();
        if (f.next < children_[f.node].size()) {
          const u64 c = children_[f.node][f.next++];
          if (state[c] == 1)
            fail(index_path("nodes", f.node) + ".children", "node " + std::to_string(c) + " is its own ancestor (a cycle)");
          if (state[c] == 0) enter(c);
        } else {
          state[f.node] = 2;
          post.push_back(f.node);
          stack.pop_back();
        }
      }
    }
    std::reverse(post.begin(), post.end());
    return post;
  }

  // ---- meshes, primitives, materials ----

  std::vector<Primitive> mesh_primitives(u64 mesh) {
    const std::string path = index_path("meshes", mesh);
    const Json& m = element("meshes", mesh, path);
    const Json& list = array_at(required(m, "primitives", path), member_path(path, "primitives"));
    std::vector<Primitive> out;
    for (std::size_t k = 0; k < list.size(); ++k) {
      Primitive p;
      p.path = index_path(member_path(path, "primitives"), k);
      const Json& prim = object_at(list[k], p.path);
      const u64 mode = unsigned_or(prim, "mode", 4, p.path);
      if (mode <= 3)
        fail(member_path(p.path, "mode"), std::to_string(mode) + " (" + (mode == 0 ? "points" : "lines") +
                                              ") has no surface: only triangles (4), strips (5) and fans (6) are read");
      if (mode > 6) fail(member_path(p.path, "mode"), std::to_string(mode) + " is not a glTF primitive mode");
      p.mode = static_cast<int>(mode);
      const std::string apath = member_path(p.path, "attributes");
      const Json& attributes = object_at(required(prim, "attributes", p.path), apath);
      const std::string ppath = member_path(apath, "POSITION");
      p.positions = layout(unsigned_of(required(attributes, "POSITION", apath), ppath), ppath, Role::Position);
      while (find(attributes, ("TEXCOORD_" + std::to_string(p.texcoord_sets)).c_str()) != nullptr) ++p.texcoord_sets;
      p.uv1_accessor = find(attributes, "TEXCOORD_1");
      p.normal_accessor = find(attributes, "NORMAL");
      u64 n = p.positions.count;
      if (const Json* i = find(prim, "indices")) {
        const std::string ipath = member_path(p.path, "indices");
        p.indices = layout(unsigned_of(*i, ipath), ipath, Role::Index);
        n = p.indices->count;
      }
      p.triangles = p.mode == 4 ? n / 3 : n >= 3 ? n - 2 : 0;
      if (const Json* mat = find(prim, "material")) {
        const std::string mpath = member_path(p.path, "material");
        const u64 index = unsigned_of(*mat, mpath);
        element("materials", index, mpath);
        if (index > static_cast<u64>(std::numeric_limits<std::int32_t>::max())) fail(mpath, "too large");
        material(index);  // checked now, before any work
        p.material = static_cast<std::int32_t>(index);
      }
      out.push_back(std::move(p));
    }
    return out;
  }

  GltfMaterial material(u64 index) {
    const std::string path = index_path("materials", index);
    const Json& m = element("materials", index, path);
    GltfMaterial out;
    out.label = path;
    if (const Json* name = find(m, "name")) out.label += " " + io::quoted(string_of(*name, member_path(path, "name")));
    out.albedo = {1, 1, 1};
    if (const Json* pbr = find(m, "pbrMetallicRoughness")) {
      const std::string ppath = member_path(path, "pbrMetallicRoughness");
      object_at(*pbr, ppath);
      if (const Json* f = find(*pbr, "baseColorFactor")) {
        const std::string fpath = member_path(ppath, "baseColorFactor");
        const std::array<double, 4> c = numbers_of<4>(*f, fpath);
        for (int k = 0; k < 4; ++k)
          if (c[k] < 0 || c[k] > 1) fail(index_path(fpath, k), "must be in [0, 1]");
        for (int k = 0; k < 3; ++k) out.albedo[k] = c[k];
      }
    }
    for (double& a : out.albedo) a = std::min(a, kGltfMaxAlbedo);
    double strength = 1;
    if (const Json* ext = find(m, "extensions"))
      if (const Json* s = find(*ext, "KHR_materials_emissive_strength"))
        if (const Json* v = find(*s, "emissiveStrength")) {
          strength = number_of(*v, member_path(path, "extensions.KHR_materials_emissive_strength.emissiveStrength"));
          if (strength < 0) fail(member_path(path, "extensions.KHR_materials_emissive_strength.emissiveStrength"), "must be >= 0");
        }
    if (const Json* e = find(m, "emissiveFactor")) {
      const std::string epath = member_path(path, "emissiveFactor");
      const std::array<double, 3> c = numbers_of<3>(*e, epath);
      for (int k = 0; k < 3; ++k) {
        if (c[k] < 0 || c[k] > 1) fail(index_path(epath, k), "must be in [0, 1]");
        out.emission[k] = c[k] * strength;
      }
    }
    return out;
  }

  // ---- buffers, views, accessors ----

  // The first byteLength bytes of a buffer, loaded once.
  std::string_view buffer(u64 index, const std::string& from) {
    const std::string path = index_path("buffers", index);
    const Json& b = element("buffers", index, from);
    const u64 length = unsigned_of(required(b, "byteLength", path), member_path(path, "byteLength"));
    auto it = loaded_.find(index);
    if (it == loaded_.end()) {
      std::string bytes;
      if (const Json* u = find(b, "uri")) {
        const std::string upath = member_path(path, "uri");
        const std::string uri = string_of(*u, upath);
        if (uri.rfind("data:", 0) == 0) {
          const std::size_t comma = uri.find(',');
          if (comma == std::string::npos || comma < 12 || uri.compare(comma - 7, 7, ";base64") != 0)
            fail(upath, "a data URI that is not base64");
          bytes = base64_decode(std::string_view(uri).substr(comma + 1), upath);
        } else {
          const fs::path file = resolve_uri(uri, folder_, upath);
          try {
            bytes = read_regular_file(file, limits_.max_file_bytes);
          } catch (const std::runtime_error& e) {
            fail(upath, e.what());
          }
        }
      } else if (glb_ && index == 0 && has_bin_) {
        bytes = std::string(bin_);
      } else {
        fail(path, glb_ ? "has no uri, and the .glb has no BIN chunk for it" : "has no uri (only a .glb's first buffer may omit it)");
      }
      loaded_bytes_ = saturating_add(loaded_bytes_, bytes.size());
      if (loaded_bytes_ > limits_.max_file_bytes)
        fail(path, "the buffers exceed the limit of " + std::to_string(limits_.max_file_bytes) + " bytes");
      it = loaded_.emplace(index, std::move(bytes)).first;
    }
    if (length > it->second.size())
      fail(member_path(path, "byteLength"), std::to_string(length) + " exceeds its data (" + std::to_string(it->second.size()) + " bytes)");
    return std::string_view(it->second).substr(0, static_cast<std::size_t>(length));
  }

  struct View {
    const unsigned char* data;
    u64 length, stride;  // stride 0: tightly packed
  };
  View buffer_view(u64 index, const std::string& from) {
    const std::string path = index_path("bufferViews", index);
    const Json& v = element("bufferViews", index, from);
    const u64 b = unsigned_of(required(v, "buffer", path), member_path(path, "buffer"));
    const u64 offset = unsigned_or(v, "byteOffset", 0, path);
    const u64 length = unsigned_of(required(v, "byteLength", path), member_path(path, "byteLength"));
    const u64 stride = unsigned_or(v, "byteStride", 0, path);
    const std::string_view bytes = buffer(b, member_path(path, "buffer"));
    const std::optional<u64> end = checked_add(offset, length);
    if (!end || *end > bytes.size())
      fail(path, "byteOffset " + std::to_string(offset) + " + byteLength " + std::to_string(length) + " exceeds buffers[" +
                     std::to_string(b) + "] (byteLength " + std::to_string(bytes.size()) + ")");
    return {reinterpret_cast<const unsigned char*>(bytes.data()) + offset, length, stride};
  }

  // `count` tightly packed elements of `element` bytes at byteOffset in a view (sparse parts).
  const unsigned char* packed_range(const Json& obj, const std::string& path, u64 count, u64 element) {
    const std::string vpath = member_path(path, "bufferView");
    const View v = buffer_view(unsigned_of(required(obj, "bufferView", path), vpath), vpath);
    const u64 offset = unsigned_or(obj, "byteOffset", 0, path);
    const std::optional<u64> bytes = checked_mul(count, element);
    const std::optional<u64> end = bytes ? checked_add(offset, *bytes) : std::nullopt;
    if (!end || *end > v.length)
      fail(path, "byteOffset " + std::to_string(offset) + " + " + std::to_string(count) + " elements of " +
                     std::to_string(element) + " bytes exceeds its buffer view (" + std::to_string(v.length) + " bytes)");
    return v.data + offset;
  }

  Layout layout(u64 index, const std::string& from, Role role) {
    Layout L;
    L.path = index_path("accessors", index);
    const Json& a = element("accessors", index, from);
    const std::string& path = L.path;
    const u64 type = unsigned_of(required(a, "componentType", path), member_path(path, "componentType"));
    L.type = type <= 0xFFFF ? static_cast<int>(type) : 0;
    const u64 csize = component_size(L.type);
    if (csize == 0) fail(member_path(path, "componentType"), std::to_string(type) + " is not a glTF component type");
    if (const Json* n = find(a, "normalized")) {
      if (!n->is_boolean()) fail(member_path(path, "normalized"), "must be true or false");
      L.normalized = n->get<bool>();
    }
    const std::string shape = string_of(required(a, "type", path), member_path(path, "type"));
    const auto refuse = [&](const char* what) {
      fail(path, std::string(what) + " of " + (L.normalized ? "normalized " : "") + component_name(L.type) + " is not allowed");
    };
    const auto needs_quantization = [&](const char* what) {
      fail(path, std::string(what) + " of " + (L.normalized ? "normalized " : "") + component_name(L.type) +
                     " needs the extension KHR_mesh_quantization");
    };
    if (role == Role::Position) {
      if (shape != "VEC3") fail(path, "POSITION must be VEC3, not " + io::quoted(shape));
      if (L.type == kUnsignedInt || (L.type == kFloat && L.normalized))
        fail(path, std::string("POSITION of ") + (L.normalized ? "normalized " : "") + component_name(L.type) + " is not allowed");
      if (L.type != kFloat && !quantization_)
        fail(path, std::string("POSITION of ") + component_name(L.type) + " needs the extension KHR_mesh_quantization");
      L.components = 3;
    } else if (role == Role::Texcoord) {
      // glTF 2.0, 3.7.2.1: float, or normalized UNSIGNED_BYTE / UNSIGNED_SHORT;
      // KHR_mesh_quantization adds (un)normalized BYTE / SHORT and unnormalized unsigned ones.
      if (shape != "VEC2") fail(path, "TEXCOORD_1 must be VEC2, not " + io::quoted(shape));
      if (L.type == kUnsignedInt || (L.type == kFloat && L.normalized)) refuse("TEXCOORD_1");
      const bool core = L.type == kFloat || ((L.type == kUnsignedByte || L.type == kUnsignedShort) && L.normalized);
      if (!core && !quantization_) needs_quantization("TEXCOORD_1");
      L.components = 2;
    } else if (role == Role::Normal) {
      // Float; KHR_mesh_quantization adds normalized BYTE / SHORT.
      if (shape != "VEC3") fail(path, "NORMAL must be VEC3, not " + io::quoted(shape));
      const bool quantized = (L.type == kByte || L.type == kShort) && L.normalized;
      if (!(L.type == kFloat && !L.normalized) && !quantized) refuse("NORMAL");
      if (quantized && !quantization_) needs_quantization("NORMAL");
      L.components = 3;
    } else {
      if (shape != "SCALAR") fail(path, "indices must be SCALAR, not " + io::quoted(shape));
      if (L.type != kUnsignedByte && L.type != kUnsignedShort && L.type != kUnsignedInt)
        fail(path, std::string("indices must be unsigned integers, not ") + component_name(L.type));
      if (L.normalized) fail(member_path(path, "normalized"), "indices cannot be normalized");
      L.components = 1;
    }
    L.element = csize * static_cast<u64>(L.components);
    L.count = unsigned_of(required(a, "count", path), member_path(path, "count"));
    if (L.count == 0) fail(member_path(path, "count"), "must be at least 1");
    if (const Json* bv = find(a, "bufferView")) {
      const std::string vpath = member_path(path, "bufferView");
      const View v = buffer_view(unsigned_of(*bv, vpath), vpath);
      const u64 offset = unsigned_or(a, "byteOffset", 0, path);
      L.stride = v.stride == 0 ? L.element : v.stride;
      if (L.stride < L.element)
        fail(vpath, "byteStride " + std::to_string(v.stride) + " is less than the element's " + std::to_string(L.element) + " bytes");
      // offset + (count - 1) * stride + element <= view length, every step checked.
      const std::optional<u64> span = checked_mul(L.count - 1, L.stride);
      const std::optional<u64> last = span ? checked_add(offset, *span) : std::nullopt;
      const std::optional<u64> end = last ? checked_add(*last, L.element) : std::nullopt;
      if (!end || *end > v.length)
        fail(path, "count " + std::to_string(L.count) + " (byteOffset " + std::to_string(offset) + ", byteStride " +
                       std::to_string(L.stride) + ") exceeds its buffer view (" + std::to_string(v.length) + " bytes)");
      L.data = v.data + offset;
    } else if (find(a, "byteOffset") != nullptr && unsigned_or(a, "byteOffset", 0, path) != 0) {
      fail(member_path(path, "byteOffset"), "must be 0 without a bufferView");
    }
    if (const Json* s = find(a, "sparse")) {
      const std::string spath = member_path(path, "sparse");
      object_at(*s, spath);
      L.sparse_count = unsigned_of(required(*s, "count", spath), member_path(spath, "count"));
      if (L.sparse_count == 0 || L.sparse_count > L.count)
        fail(member_path(spath, "count"), std::to_string(L.sparse_count) + " must be in 1.." + std::to_string(L.count));
      const std::string ipath = member_path(spath, "indices"), vpath = member_path(spath, "values");
      const Json& idx = object_at(required(*s, "indices", spath), ipath);
      const Json& val = object_at(required(*s, "values", spath), vpath);
      const u64 itype = unsigned_of(required(idx, "componentType", ipath), member_path(ipath, "componentType"));
      if (itype != kUnsignedByte && itype != kUnsignedShort && itype != kUnsignedInt)
        fail(member_path(ipath, "componentType"), std::to_string(itype) + ": sparse indices must be unsigned integers");
      L.sparse_index_type = static_cast<int>(itype);
      L.sparse_indices = packed_range(idx, ipath, L.sparse_count, component_size(L.sparse_index_type));
      L.sparse_values = packed_range(val, vpath, L.sparse_count, L.element);
    }
    return L;
  }

  // The accessor's values, count x components, sparse substitutions applied.
  std::vector<double> values(const Layout& L) {
    const std::size_t n = static_cast<std::size_t>(L.count) * static_cast<std::size_t>(L.components);
    std::vector<double> out(n, 0.0);
    const u64 csize = L.element / static_cast<u64>(L.components);
    if (L.data != nullptr)
      for (u64 k = 0; k < L.count; ++k)
        for (int c = 0; c < L.components; ++c)
          out[static_cast<std::size_t>(k) * L.components + c] = read_component(L.data + k * L.stride + c * csize, L.type, L.normalized);
    u64 previous = 0;
    for (u64 s = 0; s < L.sparse_count; ++s) {
      const auto i = static_cast<u64>(read_component(L.sparse_indices + s * component_size(L.sparse_index_type), L.sparse_index_type, false));
      if (i >= L.count) fail(L.path + ".sparse.indices", "index " + std::to_string(i) + " is beyond the accessor's count " + std::to_string(L.count));
      if (s > 0 && i <= previous) fail(L.path + ".sparse.indices", "must increase strictly (" + std::to_string(i) + " after " + std::to_string(previous) + ")");
      previous = i;
      for (int c = 0; c < L.components; ++c)
        out[static_cast<std::size_t>(i) * L.components + c] = read_component(L.sparse_values + s * L.element + c * csize, L.type, L.normalized);
    }
    return out;
  }

  // A primitive's TEXCOORD_1 or NORMAL accessor, checked as POSITION's is, with POSITION's count.
  Layout attribute_layout(const Primitive& p, const Json& index, const char* name, Role role) {
    const std::string from = member_path(member_path(p.path, "attributes"), name);
    Layout L = layout(unsigned_of(index, from), from, role);
    if (L.count != p.positions.count)
      fail(L.path, std::string(name) + " of " + p.path + " has count " + std::to_string(L.count) + ", but its POSITION (" +
                       p.positions.path + ") has " + std::to_string(p.positions.count));
    return L;
  }

  std::vector<double> decode_finite(const Layout& L, const char* name) {
    std::vector<double> v = values(L);
    for (std::size_t k = 0; k < v.size(); ++k)
      if (!std::isfinite(v[k]))
        fail(L.path, std::string(name) + " of vertex " + std::to_string(k / static_cast<std::size_t>(L.components)) + " is not finite");
    return v;
  }

  // Normals placed by `world`: by the inverse transpose of its 3x3 part, then made unit length.
  // The cofactor matrix (det x the inverse transpose) of the part scaled to entries of at most
  // 1 is used, times the sign of det, so no inverse is formed and nothing overflows; a normal
  // that comes out of zero length (a zero normal, or a singular transform) stays (0, 0, 0).
  static void place_normals(const Matrix4& world, const std::vector<double>& normals, std::vector<double>& out) {
    double a[3][3];  // a[row][col]
    double largest = 0;
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 3; ++col) {
        a[row][col] = world[col * 4 + row];
        largest = std::max(largest, std::fabs(a[row][col]));
      }
    if (largest > 0)
      for (auto& row : a)
        for (double& x : row) x /= largest;
    double c[3][3];  // cofactors: c[i][j] = (-1)^(i+j) minor(i, j)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        c[i][j] = a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1];
      }
    const double det = a[0][0] * c[0][0] + a[0][1] * c[0][1] + a[0][2] * c[0][2];
    const double sign = det < 0 ? -1.0 : 1.0;
    for (std::size_t k = 0; k + 2 < normals.size(); k += 3) {
      double n[3];
      for (int row = 0; row < 3; ++row)
        n[row] = sign * (c[row][0] * normals[k] + c[row][1] * normals[k + 1] + c[row][2] * normals[k + 2]);
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (const double x : n) out.push_back(length > 0 && std::isfinite(length) ? x / length : 0.0);
    }
  }

  std::vector<double> decode_positions(const Primitive& p) {
    std::vector<double> v = values(p.positions);
    for (std::size_t k = 0; k < v.size(); ++k)
      if (!std::isfinite(v[k])) fail(p.positions.path, "vertex " + std::to_string(k / 3) + " is not finite");
    return v;
  }

  // Three vertex numbers per triangle (glTF 2.0, section 3.7.2.1: strips and fans).
  std::vector<std::uint32_t> triangulate(const Primitive& p) {
    std::vector<std::uint32_t> order;
    if (p.indices) {
      const std::vector<double> v = values(*p.indices);
      order.reserve(v.size());
      for (const double i : v) {
        if (i >= static_cast<double>(p.positions.count))
          fail(p.indices->path, "index " + std::to_string(static_cast<u64>(i)) + " is beyond the " +
                                    std::to_string(p.positions.count) + " vertices of " + p.positions.path);
        order.push_back(static_cast<std::uint32_t>(i));
      }
    } else {
      order.resize(static_cast<std::size_t>(p.positions.count));
      for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::uint32_t>(k);
    }
    std::vector<std::uint32_t> out;
    out.reserve(static_cast<std::size_t>(p.triangles) * 3);
    for (std::size_t t = 0; t < p.triangles; ++t) {
      if (p.mode == 4) {
        out.insert(out.end(), {order[3 * t], order[3 * t + 1], order[3 * t + 2]});
      } else if (p.mode == 5) {  // {v_i, v_{i+(1+i%2)}, v_{i+(2-i%2)}}
        out.insert(out.end(), {order[t], order[t + 1 + t % 2], order[t + 2 - t % 2]});
      } else {  // fan: {v_{i+1}, v_{i+2}, v_0}
        out.insert(out.end(), {order[t + 1], order[t + 2], order[0]});
      }
    }
    return out;
  }

  fs::path folder_;
  GltfLimits limits_;
  Json doc_;
  bool glb_ = false, has_bin_ = false, quantization_ = false;
  std::string_view bin_;
  u64 node_count_ = 0, loaded_bytes_ = 0;
  std::map<u64, std::string> loaded_;  // buffer index -> bytes (a map: references stay valid)
  std::vector<std::vector<u64>> children_;
  std::vector<Matrix4> locals_;
};

}  // namespace

TriangleMesh read_gltf_bytes(std::string_view bytes, const fs::path& folder, const GltfLimits& limits, bool with_uv) {
  try {
    return Reader(bytes, folder, limits).read(with_uv);
  } catch (const Json::exception& e) {
    std::string what = e.what();
    for (char& c : what)
      if (c == '\n' || c == '\r') c = ' ';
    throw std::runtime_error("not valid glTF JSON: " + what);
  }
}

TriangleMesh read_gltf(const fs::path& path, const GltfLimits& limits, bool with_uv) {
  const std::string bytes = read_regular_file(path, limits.max_file_bytes);
  return read_gltf_bytes(bytes, path.parent_path(), limits, with_uv);
}

std::vector<MeshPart> split_by_material(const TriangleMesh& mesh) {
  std::vector<MeshPart> parts;
  const std::size_t triangles = mesh.indices.size() / 3, vertices = mesh.vertices.size() / 3;
  const bool uv1 = mesh.uv1.size() == 2 * vertices && vertices > 0;
  const bool normals = mesh.normals.size() == 3 * vertices && vertices > 0;
  for (std::int32_t m = -1; m < static_cast<std::int32_t>(mesh.materials.size()); ++m) {
    MeshPart part;
    part.material = m;
    std::vector<std::uint32_t> remap(mesh.vertices.size() / 3, std::numeric_limits<std::uint32_t>::max());
    for (std::size_t t = 0; t < triangles; ++t) {
      if ((t < mesh.triangle_material.size() ? mesh.triangle_material[t] : -1) != m) continue;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t i = mesh.indices[3 * t + k];
        if (remap[i] == std::numeric_limits<std::uint32_t>::max()) {
          remap[i] = static_cast<std::uint32_t>(part.vertices.size() / 3);
          part.vertices.insert(part.vertices.end(), mesh.vertices.begin() + 3 * i, mesh.vertices.begin() + 3 * i + 3);
          if (uv1) part.uv1.insert(part.uv1.end(), mesh.uv1.begin() + 2 * i, mesh.uv1.begin() + 2 * i + 2);
          if (normals) part.normals.insert(part.normals.end(), mesh.normals.begin() + 3 * i, mesh.normals.begin() + 3 * i + 3);
        }
        part.indices.push_back(remap[i]);
      }
    }
    if (!part.indices.empty()) parts.push_back(std::move(part));
  }
  return parts;
}

}  // namespace shpack::scene::detail
