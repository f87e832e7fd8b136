#include "output_check.h"

#include <sys/stat.h>

#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>

#include "shpack/io/atomic_write.h"

namespace shpack::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// The parsed JSON of `path`, or null (the loader has read these files already and reported
// any problem; a file that changed since then is simply not looked into).
Json read_json(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return nullptr;
  return Json::parse(in, nullptr, false);
}

const Json* member(const Json& j, const char* key) {
  if (!j.is_object()) return nullptr;
  const auto it = j.find(key);
  return it == j.end() ? nullptr : &*it;
}

// A glTF buffer URI names a file unless it is a data: URI; %XX escapes are decoded.
void add_gltf_buffers(const fs::path& gltf, std::vector<fs::path>& files) {
  const Json doc = read_json(gltf);
  const Json* buffers = member(doc, "buffers");
  if (buffers == nullptr || !buffers->is_array()) return;
  for (const Json& buffer : *buffers) {
    const Json* uri = member(buffer, "uri");
    if (uri == nullptr || !uri->is_string()) continue;
    const std::string text = uri->get<std::string>();
    if (text.rfind("data:", 0) == 0) continue;
    std::string decoded;
    for (std::size_t k = 0; k < text.size(); ++k) {
      if (text[k] == '%' && k + 2 < text.size() && std::isxdigit(static_cast<unsigned char>(text[k + 1])) &&
          std::isxdigit(static_cast<unsigned char>(text[k + 2]))) {
        decoded += static_cast<char>(std::stoi(text.substr(k + 1, 2), nullptr, 16));
        k += 2;
      } else {
        decoded += text[k];
      }
    }
    files.push_back(gltf.parent_path() / decoded);
  }
}

}  // namespace

std::string check_output_not_input(const std::string& output, const std::vector<fs::path>& inputs) {
  if (output.empty() || io::output_descriptor(output) >= 0) return {};
  struct stat out {};
  if (::stat(output.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) return {};
  for (const fs::path& input : inputs) {
    struct stat in {};
    if (::stat(input.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino)
      return output + ": is both an input and the output";
  }
  return {};
}

std::vector<fs::path> scene_input_files(const scene::Scene& scene) {
  std::vector<fs::path> files = {scene.file};
  if (scene.environment.type == scene::EnvironmentType::Map) files.push_back(scene.environment.path);
  // The loaded scene keeps the triangles, not the names of the mesh files: they are read
  // again from the scene file, which load_scene has validated.
  const Json doc = read_json(scene.file);
  const Json* geometry = member(doc, "geometry");
  if (geometry == nullptr || !geometry->is_array()) return files;
  for (const Json& shape : *geometry) {
    const Json* type = member(shape, "type");
    const Json* path = member(shape, "path");
    if (type == nullptr || *type != "mesh" || path == nullptr || !path->is_string()) continue;
    const fs::path mesh = scene.file.parent_path() / fs::path(path->get<std::string>());
    files.push_back(mesh);
    if (mesh.extension() == ".gltf") add_gltf_buffers(mesh, files);
  }
  return files;
}

}  // namespace shpack::cli
