#include "gltf_mesh.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace shpack::io::detail {
namespace {

using Json = nlohmann::json;
using Matrix4 = std::array<double, 16>;  // column-major, as glTF stores node.matrix
constexpr Matrix4 kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// RFC 4648 base64 (the body of a data URI).
std::string base64_decode(const std::string& text) {
  std::string out;
  unsigned value = 0;
  int bits = 0;
  for (const char ch : text) {
    int v;
    if (ch >= 'A' && ch <= 'Z') v = ch - 'A';
    else if (ch >= 'a' && ch <= 'z') v = ch - 'a' + 26;
    else if (ch >= '0' && ch <= '9') v = ch - '0' + 52;
    else if (ch == '+') v = 62;
    else if (ch == '/') v = 63;
    else if (ch == '=') break;
    else throw std::runtime_error("bad base64 in a data URI");
    value = (value << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((value >> bits) & 0xFF));
    }
  }
  return out;
}

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
  Matrix4 c{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) c[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
  return c;
}

// T * R * S of a node (glTF 2.0, section 5.25: rotation a unit quaternion [x, y, z, w]).
Matrix4 local_matrix(const Json& node) {
  if (node.contains("matrix")) {
    Matrix4 m;
    for (int k = 0; k < 16; ++k) m[k] = node.at("matrix").at(k).get<double>();
    return m;
  }
  const auto get3 = [&](const char* key, double fallback) {
    std::array<double, 3> v{fallback, fallback, fallback};
    if (node.contains(key))
      for (int k = 0; k < 3; ++k) v[k] = node.at(key).at(k).get<double>();
    return v;
  };
  const auto t = get3("translation", 0.0), s = get3("scale", 1.0);
  std::array<double, 4> q{0, 0, 0, 1};
  if (node.contains("rotation"))
    for (int k = 0; k < 4; ++k) q[k] = node.at("rotation").at(k).get<double>();
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

class Reader {
 public:
  Reader(const std::filesystem::path& path) : folder_(path.parent_path()) {
    std::string bytes = read_all(path);
    if (bytes.size() >= 12 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
      // .glb: 12-byte header, then chunks of (length, type, data), JSON first, BIN second.
      std::size_t at = 12;
      while (at + 8 <= bytes.size()) {
        std::uint32_t length, type;
        std::memcpy(&length, bytes.data() + at, 4);
        std::memcpy(&type, bytes.data() + at + 4, 4);
        if (at + 8 + length > bytes.size()) throw std::runtime_error("truncated .glb chunk");
        const std::string chunk = bytes.substr(at + 8, length);
        if (type == 0x4E4F534Au) doc_ = Json::parse(chunk);  // "JSON"
        else if (type == 0x004E4942u) bin_ = chunk;           // "BIN\0"
        at += 8 + length;
      }
      if (doc_.is_null()) throw std::runtime_error(".glb without a JSON chunk");
    } else {
      doc_ = Json::parse(bytes);
    }
  }

  TriangleMesh read() {
    TriangleMesh mesh;
    const std::size_t scene = doc_.value("scene", 0);
    if (doc_.contains("scenes") && scene < doc_.at("scenes").size()) {
      for (const Json& n : doc_.at("scenes").at(scene).value("nodes", Json::array())) visit(n.get<std::size_t>(), kIdentity, mesh, 0);
    } else if (doc_.contains("nodes")) {
      for (std::size_t n = 0; n < doc_.at("nodes").size(); ++n) visit(n, kIdentity, mesh, 0);  // no scene: all nodes
    }
    return mesh;
  }

 private:
  void visit(std::size_t index, const Matrix4& parent, TriangleMesh& mesh, int depth) {
    if (depth > 64) throw std::runtime_error("node tree deeper than 64 (a cycle?)");
    const Json& node = doc_.at("nodes").at(index);
    const Matrix4 world = multiply(parent, local_matrix(node));
    if (node.contains("mesh"))
      for (const Json& primitive : doc_.at("meshes").at(node.at("mesh").get<std::size_t>()).at("primitives"))
        add_primitive(primitive, world, mesh);
    for (const Json& child : node.value("children", Json::array())) visit(child.get<std::size_t>(), world, mesh, depth + 1);
  }

  void add_primitive(const Json& primitive, const Matrix4& m, TriangleMesh& mesh) {
    if (primitive.value("mode", 4) != 4) return;  // points and lines have no surface
    const auto base = static_cast<std::uint32_t>(mesh.vertices.size() / 3);
    const std::vector<double> positions = floats(primitive.at("attributes").at("POSITION").get<std::size_t>(), 3);
    for (std::size_t k = 0; k + 2 < positions.size(); k += 3) {
      const double x = positions[k], y = positions[k + 1], z = positions[k + 2];
      for (int row = 0; row < 3; ++row) mesh.vertices.push_back(m[row] * x + m[4 + row] * y + m[8 + row] * z + m[12 + row]);
    }
    const std::size_t count = positions.size() / 3;
    if (primitive.contains("indices")) {
      for (const std::uint32_t i : indices(primitive.at("indices").get<std::size_t>())) {
        if (i >= count) throw std::runtime_error("an index beyond the primitive's vertices");
        mesh.indices.push_back(base + i);
      }
    } else {
      for (std::size_t i = 0; i + 2 < count; i += 3)
        for (std::size_t k = 0; k < 3; ++k) mesh.indices.push_back(base + static_cast<std::uint32_t>(i + k));
    }
  }

  const std::string& buffer(std::size_t index) {
    if (index < loaded_.size() && !loaded_[index].empty()) return loaded_[index];
    loaded_.resize(std::max(loaded_.size(), index + 1));
    const Json& b = doc_.at("buffers").at(index);
    if (!b.contains("uri")) {
      loaded_[index] = bin_;  // the .glb binary chunk
    } else {
      const std::string uri = b.at("uri").get<std::string>();
      if (uri.rfind("data:", 0) == 0) {
        const std::size_t comma = uri.find(";base64,");
        if (comma == std::string::npos) throw std::runtime_error("a data URI that is not base64");
        loaded_[index] = base64_decode(uri.substr(comma + 8));
      } else {
        loaded_[index] = read_all(folder_ / uri);
      }
    }
    if (loaded_[index].size() < b.at("byteLength").get<std::size_t>()) throw std::runtime_error("a buffer shorter than its byteLength");
    return loaded_[index];
  }

  // The bytes of element k, component c of an accessor: (pointer, component size).
  struct View {
    const char* data;
    std::size_t count, stride;
    int component_type;
  };
  View view(std::size_t accessor_index, int components) {
    const Json& a = doc_.at("accessors").at(accessor_index);
    if (a.contains("sparse")) throw std::runtime_error("sparse accessors are not read");
    const int type = a.at("componentType").get<int>();
    const std::size_t size = type == 5126 || type == 5125 ? 4 : type == 5123 ? 2 : type == 5121 ? 1 : 0;
    if (size == 0) throw std::runtime_error("accessor component type " + std::to_string(type) + " is not read");
    const Json& bv = doc_.at("bufferViews").at(a.at("bufferView").get<std::size_t>());
    const std::string& bytes = buffer(bv.at("buffer").get<std::size_t>());
    const std::size_t offset = bv.value("byteOffset", std::size_t{0}) + a.value("byteOffset", std::size_t{0});
    const std::size_t count = a.at("count").get<std::size_t>();
    const std::size_t stride = bv.value("byteStride", size * components);
    if (count > 0 && offset + (count - 1) * stride + size * components > bytes.size())
      throw std::runtime_error("an accessor beyond its buffer");
    return {bytes.data() + offset, count, stride, type};
  }

  std::vector<double> floats(std::size_t accessor_index, int components) {
    const Json& a = doc_.at("accessors").at(accessor_index);
    if (a.at("type") != "VEC3" || a.at("componentType") != 5126) throw std::runtime_error("POSITION is not float VEC3");
    const View v = view(accessor_index, components);
    std::vector<double> out;
    for (std::size_t k = 0; k < v.count; ++k)
      for (int c = 0; c < components; ++c) {
        float f;
        std::memcpy(&f, v.data + k * v.stride + 4 * c, 4);
        out.push_back(f);
      }
    return out;
  }

  std::vector<std::uint32_t> indices(std::size_t accessor_index) {
    const View v = view(accessor_index, 1);
    std::vector<std::uint32_t> out;
    for (std::size_t k = 0; k < v.count; ++k) {
      const char* p = v.data + k * v.stride;
      if (v.component_type == 5121) {
        out.push_back(static_cast<unsigned char>(*p));
      } else if (v.component_type == 5123) {
        std::uint16_t i;
        std::memcpy(&i, p, 2);
        out.push_back(i);
      } else if (v.component_type == 5125) {
        std::uint32_t i;
        std::memcpy(&i, p, 4);
        out.push_back(i);
      } else {
        throw std::runtime_error("indices must be unsigned integers");
      }
    }
    return out;
  }

  std::filesystem::path folder_;
  Json doc_;
  std::string bin_;
  std::vector<std::string> loaded_;
};

}  // namespace

TriangleMesh read_gltf(const std::filesystem::path& path) { return Reader(path).read(); }

}  // namespace shpack::io::detail
