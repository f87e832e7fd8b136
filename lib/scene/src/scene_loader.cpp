#include "shpack/scene/scene_loader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <utility>

#include "bounded_read.h"
#include "generated/scene_schema.h"
#include "gltf_mesh.h"
#include "obj_mesh.h"
#include "scene_validate.h"
#include "shpack/io/file_checks.h"
#include "shpack/io/sha256.h"

namespace shpack::scene {

using io::IoErrc;
using io::IoStatus;

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr std::size_t kMaxProbes = 1'000'000;  // in a grid or a list
constexpr std::uint64_t kMaxLightmapSide = 8192;   // texels, a lightmap's width or height
// Arrays and objects nest at most this deep (a valid scene needs 4): deeper documents are
// refused before they are parsed, because valijson recurses once per level (a 200 KB file of
// 50,000 brackets overflows the stack).
constexpr int kMaxNesting = 64;
// The largest coordinate the ray tracer takes: Embree, in single precision, skips every
// primitive with a coordinate beyond +-1.844e18 (its FLT_LARGE), silently.
constexpr double kMaxCoordinate = 1.844e18;
// More effects than this cannot all differ (the schema allows six names, each at most once):
// refused before validation, whose uniqueItems compares every pair.
constexpr std::size_t kMaxEffects = 64;

// A problem at a JSON path; thrown inside this file only and turned into an IoStatus by
// load_scene, the boundary.
struct SceneError {
  std::string path;     // "lights[2].radius"
  std::string problem;  // "must be > 0"
};

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}
std::string index(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

std::string number_text(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string beyond_range(double v, const char* what = "is") {
  return number_text(v) + " " + what + " beyond " + number_text(kMaxCoordinate) + ", the ray tracer's range";
}

// ---- before parsing and validation ------------------------------------------------------

// True if arrays and objects in `text` nest deeper than `limit` (brackets outside strings;
// a malformed text is left to the parser).
bool nested_deeper_than(std::string_view text, int limit) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (in_string) {
      if (c == '\\') ++k;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

// ---- schema validation (scene_validate.h) ---------------------------------------------

// The lightmaps' texels together against kMaxLightmapTexels, before anything is read or
// allocated (the schema bounds each side; a 1e6 x 1e6 request is refused here too).
void check_lightmap_budget(const Json& doc) {
  const auto geometry = doc.find("geometry");
  if (geometry == doc.end() || !geometry->is_array()) return;
  std::uint64_t total = 0;
  for (std::size_t k = 0; k < geometry->size(); ++k) {
    const Json& g = (*geometry)[k];
    if (!g.is_object() || !g.contains("lightmap") || !g.at("lightmap").is_object()) continue;
    const Json& lm = g.at("lightmap");
    if (!lm.contains("resolution") || !lm.at("resolution").is_array() || lm.at("resolution").size() != 2) continue;
    const Json& r = lm.at("resolution");
    if (!r[0].is_number_unsigned() || !r[1].is_number_unsigned()) continue;  // the schema's error
    const std::uint64_t w = r[0].get<std::uint64_t>(), h = r[1].get<std::uint64_t>();
    const std::string path = join(index("geometry", k), "lightmap.resolution");
    if (w > kMaxLightmapSide || h > kMaxLightmapSide)
      throw SceneError{path, std::to_string(w) + " x " + std::to_string(h) + " exceeds " +
                                 std::to_string(kMaxLightmapSide) + " texels a side"};
    total += w * h;
    if (total > kMaxLightmapTexels)
      throw SceneError{path, "the lightmaps hold more than " + std::to_string(kMaxLightmapTexels) +
                                 " texels together (" + std::to_string(total) + " so far)"};
  }
}

// What valijson cannot check, or only slowly: run before it, on the parsed document.
//  - settings.seed, 0 to 2^64 - 1: valijson reads integers as int64, so a seed >= 2^63 would
//    fail the schema's "minimum": 0. Checked and taken out here, put back by the caller's
//    read_scene through `seed`.
//  - the number of probes and effects (uniqueItems compares every pair).
void check_before_validation(Json& doc, std::optional<std::uint64_t>& seed) {
  if (!doc.is_object()) return;
  if (const auto probes = doc.find("probes"); probes != doc.end() && probes->is_array() && probes->size() > kMaxProbes)
    throw SceneError{"probes", "more than " + std::to_string(kMaxProbes) + " probes"};
  if (const auto effects = doc.find("effects");
      effects != doc.end() && effects->is_array() && effects->size() > kMaxEffects)
    throw SceneError{"effects", "more than " + std::to_string(kMaxEffects) + " effects"};
  check_lightmap_budget(doc);
  const auto settings = doc.find("settings");
  if (settings == doc.end() || !settings->is_object()) return;
  const auto s = settings->find("seed");
  if (s == settings->end() || !s->is_number()) return;  // absent, or the schema's "wrong type"
  if (!s->is_number_unsigned())  // negative, fractional, or beyond 2^64 - 1 (read as a double)
    throw SceneError{"settings.seed", "must be an integer from 0 to " +
                                          std::to_string(std::numeric_limits<std::uint64_t>::max())};
  seed = s->get<std::uint64_t>();
  settings->erase(s);
}

void validate(const Json& doc) {
  std::string path, problem;
  if (!detail::validate_scene_json(doc, path, problem)) throw SceneError{path, problem};
}

// ---- values -----------------------------------------------------------------------------

double number(const Json& j, const std::string& path) {
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw SceneError{path, "must be a finite number"};
  return v;
}

Point3 point(const Json& j, const std::string& path) {
  return {number(j[0], path + "[0]"), number(j[1], path + "[1]"), number(j[2], path + "[2]")};
}

// A point of geometry: every coordinate within the ray tracer's range.
Point3 geometry_point(const Json& j, const std::string& path) {
  const Point3 p = point(j, path);
  const double c[3] = {p.x, p.y, p.z};
  for (std::size_t k = 0; k < 3; ++k)
    if (!(std::fabs(c[k]) <= kMaxCoordinate)) throw SceneError{index(path, k), beyond_range(c[k])};
  return p;
}

Dir3 direction(const Json& j, const std::string& path) {
  const Point3 p = point(j, path);
  const double len = std::hypot(p.x, p.y, p.z);
  if (!(len > 0) || !std::isfinite(len)) throw SceneError{path, "must be a non-zero direction"};
  return {p.x / len, p.y / len, p.z / len};
}

Rgb colour(const Json& j, const std::string& path) {
  if (j.is_number()) {
    const double v = number(j, path);
    return {v, v, v};
  }
  return {number(j[0], path + "[0]"), number(j[1], path + "[1]"), number(j[2], path + "[2]")};
}

template <class T>
T value_or(const Json& obj, const char* key, T fallback) {
  return obj.contains(key) ? obj.at(key).get<T>() : fallback;
}

std::string label(const std::string& path, const Json& obj) {
  return obj.contains("name") ? path + " '" + obj.at("name").get<std::string>() + "'" : path;
}

// A referenced file, relative to the scene's folder; must be a regular file.
fs::path referenced_file(const fs::path& scene_file, const Json& j, const std::string& path) {
  const fs::path file = scene_file.parent_path() / fs::path(j.get<std::string>());
  if (IoStatus st = io::detail::check_regular_file(file); !st.ok()) throw SceneError{path, st.message};
  return file;
}

// ---- sections ---------------------------------------------------------------------------

std::vector<Point3> read_probes(const Json& j) {
  std::vector<Point3> probes;
  if (j.is_array()) {
    if (j.size() > kMaxProbes) throw SceneError{"probes", "more than " + std::to_string(kMaxProbes) + " probes"};
    for (std::size_t k = 0; k < j.size(); ++k) probes.push_back(point(j[k], index("probes", k)));
    return probes;
  }
  const Point3 lo = point(j.at("min"), "probes.min"), hi = point(j.at("max"), "probes.max");
  const std::array<std::size_t, 3> n = {j.at("counts")[0].get<std::size_t>(), j.at("counts")[1].get<std::size_t>(),
                                        j.at("counts")[2].get<std::size_t>()};
  if (n[0] * n[1] * n[2] > kMaxProbes)
    throw SceneError{"probes.counts", "more than " + std::to_string(kMaxProbes) + " probes"};
  // counts[k] points from min to max, both included; x varies fastest, then y, then z.
  const auto at = [](double a, double b, std::size_t i, std::size_t count) {
    return count == 1 ? a : a + (b - a) * (static_cast<double>(i) / static_cast<double>(count - 1));
  };
  probes.reserve(n[0] * n[1] * n[2]);
  for (std::size_t iz = 0; iz < n[2]; ++iz)
    for (std::size_t iy = 0; iy < n[1]; ++iy)
      for (std::size_t ix = 0; ix < n[0]; ++ix)
        probes.push_back({at(lo.x, hi.x, ix, n[0]), at(lo.y, hi.y, iy, n[1]), at(lo.z, hi.z, iz, n[2])});
  return probes;
}

SceneEnvironment read_environment(const Json& j, const fs::path& scene_file) {
  SceneEnvironment env;
  const std::string type = j.at("type").get<std::string>();
  if (type == "map") {
    env.type = EnvironmentType::Map;
    env.path = referenced_file(scene_file, j.at("path"), "environment.path");
    env.layout = value_or<std::string>(j, "layout", "auto") == "equirect" ? Layout::Equirect : Layout::Auto;
    env.rotation_deg = j.contains("rotation_deg") ? number(j.at("rotation_deg"), "environment.rotation_deg") : 0.0;
    env.intensity = j.contains("intensity") ? number(j.at("intensity"), "environment.intensity") : 1.0;
  } else if (type == "preetham") {
    env.type = EnvironmentType::Preetham;
    const Dir3 sun = direction(j.at("to_sun"), "environment.to_sun");
    if (sun.y < 0) throw SceneError{"environment.to_sun", "the sun must be above the horizon (y >= 0)"};
    env.preetham.sun = sun;
    env.preetham.turbidity = number(j.at("turbidity"), "environment.turbidity");
    if (j.contains("ground")) env.preetham.ground = colour(j.at("ground"), "environment.ground");
    env.preetham.intensity = j.contains("intensity") ? number(j.at("intensity"), "environment.intensity") : 1.0;
  } else {
    env.type = EnvironmentType::Gradient;
    env.zenith = colour(j.at("zenith"), "environment.zenith");
    env.horizon = colour(j.at("horizon"), "environment.horizon");
    env.ground = colour(j.at("ground"), "environment.ground");
  }
  return env;
}

SceneLight read_light(const Json& j, const std::string& path) {
  SceneLight light;
  light.label = label(path, j);
  const std::string type = j.at("type").get<std::string>();
  // Intensity, or a power P radiated evenly: I = P / (4 pi).
  const auto intensity = [&] {
    if (j.contains("intensity")) return colour(j.at("intensity"), join(path, "intensity"));
    Rgb p = colour(j.at("power"), join(path, "power"));
    for (double& v : p) v /= 4.0 * std::numbers::pi;
    return p;
  };
  if (type == "directional") {
    light.type = LightType::Directional;
    light.direction = direction(j.at("direction"), join(path, "direction"));
    light.colour = colour(j.at("irradiance"), join(path, "irradiance"));
    light.angular_diameter = value_or(j, "angular_diameter_deg", 0.0) * kDegree;
  } else if (type == "point" || type == "sphere") {
    light.type = type == "point" ? LightType::Point : LightType::Sphere;
    light.position = point(j.at("position"), join(path, "position"));
    light.colour = intensity();
    light.radius = value_or(j, "radius", 0.0);
  } else if (type == "spot") {
    light.type = LightType::Spot;
    light.position = point(j.at("position"), join(path, "position"));
    light.direction = direction(j.at("direction"), join(path, "direction"));
    light.colour = colour(j.at("intensity"), join(path, "intensity"));
    light.outer_angle = number(j.at("outer_angle_deg"), join(path, "outer_angle_deg")) * kDegree;
    light.inner_angle = value_or(j, "inner_angle_deg", 0.0) * kDegree;
    if (light.inner_angle > light.outer_angle)
      throw SceneError{join(path, "inner_angle_deg"), "must be <= outer_angle_deg"};
  } else if (type == "rect") {
    light.type = LightType::Rect;
    light.position = point(j.at("position"), join(path, "position"));
    light.right = direction(j.at("right"), join(path, "right"));
    light.up = direction(j.at("up"), join(path, "up"));
    const double cos_angle = light.right.x * light.up.x + light.right.y * light.up.y + light.right.z * light.up.z;
    if (!(std::fabs(cos_angle) <= 1e-6)) throw SceneError{join(path, "up"), "must be orthogonal to right"};
    light.width = number(j.at("size")[0], join(path, "size[0]"));
    light.height = number(j.at("size")[1], join(path, "size[1]"));
    light.colour = colour(j.at("radiance"), join(path, "radiance"));
  } else if (type == "disk") {
    light.type = LightType::Disk;
    light.position = point(j.at("position"), join(path, "position"));
    light.direction = direction(j.at("direction"), join(path, "direction"));
    light.radius = number(j.at("radius"), join(path, "radius"));
    light.colour = colour(j.at("radiance"), join(path, "radiance"));
  } else if (type == "hemisphere") {
    light.type = LightType::Hemisphere;
    light.colour = colour(j.at("sky"), join(path, "sky"));
    light.ground = colour(j.at("ground"), join(path, "ground"));
  } else {
    light.type = LightType::Ambient;
    light.colour = colour(j.at("radiance"), join(path, "radiance"));
  }
  return light;
}

// Appends a vertex; a coordinate beyond the ray tracer's range is blamed on `blame`, the
// key that put it there, whose value is `value` ("geometry[0].size: 1e+20 puts vertices ...").
void add_vertex(SceneShape& shape, double x, double y, double z, const std::string& blame, double value) {
  for (const double c : {x, y, z})
    if (!(std::fabs(c) <= kMaxCoordinate)) throw SceneError{blame, beyond_range(value, "puts vertices")};
  shape.vertices.push_back(static_cast<float>(x));
  shape.vertices.push_back(static_cast<float>(y));
  shape.vertices.push_back(static_cast<float>(z));
}

// The rectangle c +- hu u +- hv v as two triangles whose normal (v1 - v0) x (v2 - v0), the
// front side (Embree's convention, tracer.h), is u x v.
void add_quad(SceneShape& shape, Point3 c, Dir3 u, Dir3 v, double hu, double hv, const std::string& blame,
              double value) {
  const auto base = static_cast<std::uint32_t>(shape.vertices.size() / 3);
  for (const auto& [su, sv] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
    add_vertex(shape, c.x + su * hu * u.x + sv * hv * v.x, c.y + su * hu * u.y + sv * hv * v.y,
               c.z + su * hu * u.z + sv * hv * v.z, blame, value);
  for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) shape.indices.push_back(base + i);
}

// A mesh's vertices placed by the entry's scale, mirror and offset into `shape`, with its
// triangles; `mesh_error` names the file.
template <class MeshError>
void place_mesh(SceneShape& shape, const std::vector<double>& positions, std::vector<std::uint32_t> indices,
                const Json& j, const std::string& path, bool right_handed, const MeshError& mesh_error) {
  if (indices.empty()) throw mesh_error("no triangles");
  const std::string scale_path = join(path, "scale");
  const double scale = j.contains("scale") ? number(j.at("scale"), scale_path) : 1.0;
  const std::string position_path = join(path, "position");
  const Point3 offset = j.contains("position") ? geometry_point(j.at("position"), position_path) : Point3{};
  const double z_sign = right_handed ? -1.0 : 1.0;
  shape.vertices.reserve(positions.size());
  for (std::size_t k = 0; k + 2 < positions.size(); k += 3) {
    const double* p = &positions[k];
    const double largest = std::max({std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])});
    if (!(largest <= kMaxCoordinate))  // OBJ's reader checks its own; glTF's are checked here
      throw mesh_error("vertex " + std::to_string(k / 3) + " (" + number_text(p[0]) + ", " + number_text(p[1]) +
                       ", " + number_text(p[2]) + ") is beyond " + number_text(kMaxCoordinate) +
                       ", the ray tracer's range");
    // A vertex pushed out of range by the scale, or else by the offset.
    const bool scaled_out = !(std::fabs(scale) * largest <= kMaxCoordinate);
    add_vertex(shape, offset.x + scale * p[0], offset.y + scale * p[1], offset.z + z_sign * scale * p[2],
               scaled_out ? scale_path : position_path,
               scaled_out ? scale : std::max({std::fabs(offset.x), std::fabs(offset.y), std::fabs(offset.z)}));
  }
  const std::size_t vertex_count = positions.size() / 3;
  for (const std::uint32_t i : indices)  // the readers check theirs; a last guard for Embree
    if (i >= vertex_count) throw mesh_error("a triangle refers to vertex " + std::to_string(i) + " of " +
                                            std::to_string(vertex_count));
  // The file's counter-clockwise triangles face front (OBJ's convention; glTF 2.0, "Meshes"): their
  // normal (v1 - v0) x (v2 - v0) is the front side. A mirror turns that normal inwards, so
  // mirrored triangles are listed in the reverse order to keep their front outside.
  if (right_handed)
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
  shape.indices = std::move(indices);
}

// A mesh's shading normals into the shape, made unit (a zero one stays zero: the lightmap
// raster then takes the triangle's) and mirrored as its positions are (a uniform scale keeps
// their direction, up to a sign the raster settles by each triangle's front).
void place_normals(SceneShape& shape, const std::vector<double>& normals, bool mirrored) {
  const double z_sign = mirrored ? -1.0 : 1.0;
  for (std::size_t k = 0; k + 2 < normals.size(); k += 3) {
    const double x = normals[k], y = normals[k + 1], z = z_sign * normals[k + 2];
    const double length = std::hypot(x, y, z);  // no overflow for huge components
    const double s = length > 0 ? 1.0 / length : 0.0;
    shape.normals.insert(shape.normals.end(), {static_cast<float>(s * x), static_cast<float>(s * y),
                                               static_cast<float>(s * z)});
  }
}

// OBJ through obj_mesh.h, glTF through gltf_mesh.h; then scale, mirror (OBJ: when asked;
// glTF: always, its frame being right-handed +Y up) and offset. A glTF mesh becomes one
// shape per material it uses (docs/scenes.md): the material's baseColorFactor is the
// albedo and its emissiveFactor the emission, unless the scene entry gives "albedo" or
// "emission", which then hold for every part.
std::vector<SceneShape> read_mesh(const SceneShape& entry, const Json& j, const std::string& path,
                                  const fs::path& scene_file) {
  const fs::path file = referenced_file(scene_file, j.at("path"), join(path, "path"));
  std::string ext = file.extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  const auto mesh_error = [&](const std::string& problem) {
    return SceneError{join(path, "path"), file.string() + ": " + problem};
  };
  std::vector<SceneShape> shapes;
  const bool lightmapped = j.contains("lightmap");
  if (ext == ".obj") {
    std::string text;
    if (IoStatus st = detail::read_bounded(file, detail::FileKind::Regular, detail::kMaxMeshBytes, text); !st.ok())
      throw SceneError{join(path, "path"), st.message};
    detail::ObjMesh mesh;
    std::string why;
    if (!detail::parse_obj(text, kMaxCoordinate, mesh, why, lightmapped)) throw mesh_error(why);
    if (lightmapped && mesh.uv.empty())
      throw mesh_error(mesh.uv_missing_line ? "line " + std::to_string(mesh.uv_missing_line) +
                                                  ": a face without texture coordinates; a lightmap needs UVs on every face"
                                            : "has no texture coordinates (vt); a lightmap needs UVs");
    shapes.push_back(entry);
    const bool mirrored = value_or(j, "mirror_z", false);
    place_mesh(shapes.back(), mesh.vertices, std::move(mesh.indices), j, path, mirrored, mesh_error);
    if (lightmapped) {
      shapes.back().uv.assign(mesh.uv.begin(), mesh.uv.end());  // OBJ's v runs up, as Unity's
      place_normals(shapes.back(), mesh.normals, mirrored);
    }
    return shapes;
  }
  if (ext != ".gltf" && ext != ".glb") throw mesh_error("meshes are read from .obj, .gltf and .glb files");
  detail::TriangleMesh mesh;
  try {
    mesh = detail::read_gltf(file, {}, lightmapped);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw mesh_error(e.what());
  }
  if (mesh.indices.empty()) throw mesh_error("no triangles");
  if (lightmapped && mesh.uv1.empty())
    throw mesh_error(mesh.texcoord_sets == 0
                         ? "has no UV set; a lightmap needs TEXCOORD_1, a second UV set unwrapped without overlaps"
                         : "has only one UV set (TEXCOORD_0); a lightmap needs TEXCOORD_1, a second UV set "
                           "unwrapped without overlaps (TEXCOORD_0 is not used: its charts may overlap)");
  const bool right_handed = value_or(j, "mirror_z", true);
  std::vector<detail::MeshPart> parts = detail::split_by_material(mesh);
  for (detail::MeshPart& part : parts) {
    SceneShape shape = entry;
    if (part.material >= 0) {
      const detail::GltfMaterial& material = mesh.materials[static_cast<std::size_t>(part.material)];
      if (parts.size() > 1) shape.label += " " + material.label;
      if (!j.contains("albedo")) shape.albedo = material.albedo;
      if (!j.contains("emission")) shape.emission = material.emission;
    }
    place_mesh(shape, part.vertices, std::move(part.indices), j, path, right_handed, mesh_error);
    if (lightmapped) {  // glTF's v runs down from the image's top, Unity's up from its bottom
      for (std::size_t k = 0; k + 1 < part.uv1.size(); k += 2)
        shape.uv.insert(shape.uv.end(), {static_cast<float>(part.uv1[k]), static_cast<float>(1.0 - part.uv1[k + 1])});
      place_normals(shape, part.normals, right_handed);
    }
    shapes.push_back(std::move(shape));
  }
  return shapes;
}

// The lightmap of geometry entry k, whose shapes are geometry[first, end) (ranges checked by
// the schema, the budget by check_lightmap_budget).
LightmapTarget read_lightmap(const Json& entry, std::size_t k, std::size_t first, std::size_t end) {
  const Json& lm = entry.at("lightmap");
  LightmapTarget target;
  target.label = label(index("geometry", k), entry);
  // The name is the stem of the lightmap's files: kept to letters, digits, '-' and '_', so that
  // no name can reach out of the output folder or hide a file.
  target.name = entry.contains("name") ? entry.at("name").get<std::string>() : "geometry" + std::to_string(k);
  for (char& c : target.name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  target.width = lm.at("resolution")[0].get<std::uint32_t>();
  target.height = lm.at("resolution")[1].get<std::uint32_t>();
  target.l2 = value_or(lm, "l2", false);
  target.padding = value_or(lm, "padding", target.padding);
  for (std::size_t s = first; s < end; ++s) target.shapes.push_back(static_cast<std::uint32_t>(s));
  return target;
}

// The shape of one "geometry" entry: one, or one per material of a glTF mesh.
std::vector<SceneShape> read_shape(const Json& j, const std::string& path, const fs::path& scene_file) {
  SceneShape shape;
  shape.label = label(path, j);
  if (j.contains("albedo")) shape.albedo = colour(j.at("albedo"), join(path, "albedo"));
  if (j.contains("emission")) shape.emission = colour(j.at("emission"), join(path, "emission"));
  const std::string type = j.at("type").get<std::string>();
  if (type == "plane") {
    shape.type = ShapeType::Plane;
    const Dir3 u = direction(j.at("right"), join(path, "right")), v = direction(j.at("up"), join(path, "up"));
    if (!(std::fabs(u.x * v.x + u.y * v.y + u.z * v.z) <= 1e-6))
      throw SceneError{join(path, "up"), "must be orthogonal to right"};
    const double w = number(j.at("size")[0], join(path, "size[0]")), h = number(j.at("size")[1], join(path, "size[1]"));
    add_quad(shape, geometry_point(j.at("position"), join(path, "position")), u, v, 0.5 * w, 0.5 * h,
             join(path, "size"), std::max(w, h));
    if (j.contains("lightmap")) shape.uv = {0, 0, 1, 0, 1, 1, 0, 1};  // u along right, v along up (add_quad's corners)
  } else if (type == "sphere") {
    shape.type = ShapeType::Sphere;
    shape.centre = geometry_point(j.at("position"), join(path, "position"));
    shape.radius = number(j.at("radius"), join(path, "radius"));
    const double far = std::max({std::fabs(shape.centre.x), std::fabs(shape.centre.y), std::fabs(shape.centre.z)});
    if (!(far + shape.radius <= kMaxCoordinate))
      throw SceneError{join(path, "radius"), beyond_range(shape.radius, "puts the sphere")};
  } else if (type == "box") {
    shape.type = ShapeType::Box;
    const Point3 lo = geometry_point(j.at("min"), join(path, "min")), hi = geometry_point(j.at("max"), join(path, "max"));
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) throw SceneError{join(path, "max"), "must exceed min on every axis"};
    const Point3 c{0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y), 0.5 * (lo.z + hi.z)};
    const double hx = 0.5 * (hi.x - lo.x), hy = 0.5 * (hi.y - lo.y), hz = 0.5 * (hi.z - lo.z);
    // Six faces: centre of the face, two in-plane axes u, v, their half-sizes. u x v points
    // out of the box on every face, so that the triangles' front faces are outside (add_quad).
    add_quad(shape, {c.x + hx, c.y, c.z}, {0, 1, 0}, {0, 0, 1}, hy, hz, join(path, "max"), hi.x);
    add_quad(shape, {c.x - hx, c.y, c.z}, {0, 0, 1}, {0, 1, 0}, hz, hy, join(path, "max"), hi.x);
    add_quad(shape, {c.x, c.y + hy, c.z}, {0, 0, 1}, {1, 0, 0}, hz, hx, join(path, "max"), hi.x);
    add_quad(shape, {c.x, c.y - hy, c.z}, {1, 0, 0}, {0, 0, 1}, hx, hz, join(path, "max"), hi.x);
    add_quad(shape, {c.x, c.y, c.z + hz}, {1, 0, 0}, {0, 1, 0}, hx, hy, join(path, "max"), hi.x);
    add_quad(shape, {c.x, c.y, c.z - hz}, {0, 1, 0}, {1, 0, 0}, hy, hx, join(path, "max"), hi.x);
  } else {
    shape.type = ShapeType::Mesh;
    return read_mesh(shape, j, path, scene_file);
  }
  return {shape};
}

SceneEffects read_effects(const Json& j, bool has_environment) {
  SceneEffects e;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const std::string name = j[k].get<std::string>();
    if (name == "direct") e.direct = true;
    else if (name == "environment") e.environment = true;
    else if (name == "shadows") e.shadows = true;
    else if (name == "sky_occlusion") e.sky_occlusion = true;
    else if (name == "emission") e.emission = true;
    else {
      if (e.bounces != 0) throw SceneError{index("effects", k), "a second bounce:N"};
      e.bounces = std::stoi(name.substr(7));  // "bounce:N", N checked by the schema
    }
  }
  if (e.shadows && !e.direct) throw SceneError{"effects", "shadows needs direct"};
  if (e.sky_occlusion && !e.environment) throw SceneError{"effects", "sky_occlusion needs environment"};
  if (e.environment && !has_environment) throw SceneError{"effects", "environment needs an 'environment' section"};
  return e;
}

// The Monte Carlo effects' target and cap (ranges checked by the schema).
void read_accuracy_settings(const Json& s, SceneSettings& settings) {
  if (s.contains("target_error_pct"))
    settings.target_error_pct = number(s.at("target_error_pct"), "settings.target_error_pct");
  settings.max_samples = value_or(s, "max_samples", settings.max_samples);
}

// Probe validity (docs/scenes.md): threshold, policy and reach (ranges checked by the schema).
void read_validity_settings(const Json& s, SceneSettings& settings) {
  if (s.contains("validity_threshold"))
    settings.validity_threshold = number(s.at("validity_threshold"), "settings.validity_threshold");
  if (s.contains("max_offset")) settings.max_offset = number(s.at("max_offset"), "settings.max_offset");
  if (s.contains("invalid_probes")) {
    const std::string policy = s.at("invalid_probes").get<std::string>();
    settings.invalid_probes = policy == "keep"     ? InvalidProbes::Keep
                              : policy == "error"  ? InvalidProbes::Error
                              : policy == "offset" ? InvalidProbes::Offset
                                                   : InvalidProbes::Dilate;
  }
}

Scene read_scene(const Json& doc, const fs::path& file, std::optional<std::uint64_t> seed) {
  Scene scene;
  scene.file = file;
  if (doc.contains("probes")) scene.probes = read_probes(doc.at("probes"));
  if (doc.contains("environment")) scene.environment = read_environment(doc.at("environment"), file);
  if (doc.contains("lights"))
    for (std::size_t k = 0; k < doc.at("lights").size(); ++k)
      scene.lights.push_back(read_light(doc.at("lights")[k], index("lights", k)));
  if (doc.contains("geometry"))
    for (std::size_t k = 0; k < doc.at("geometry").size(); ++k) {
      const Json& entry = doc.at("geometry")[k];
      const std::size_t first = scene.geometry.size();
      for (SceneShape& shape : read_shape(entry, index("geometry", k), file)) scene.geometry.push_back(std::move(shape));
      if (!entry.contains("lightmap")) continue;
      scene.lightmaps.push_back(read_lightmap(entry, k, first, scene.geometry.size()));
      for (std::size_t m = 0; m + 1 < scene.lightmaps.size(); ++m)
        if (scene.lightmaps[m].name == scene.lightmaps.back().name)
          throw SceneError{join(index("geometry", k), "name"), "'" + scene.lightmaps.back().name +
                                                                   "' names another lightmap already (" +
                                                                   scene.lightmaps[m].label + "): names are file stems"};
    }
  if (scene.probes.empty() && scene.lightmaps.empty())
    throw SceneError{"probes", "a scene needs probes or a lightmap"};
  scene.effects = read_effects(doc.at("effects"), doc.contains("environment"));
  if (doc.contains("settings")) {
    const Json& s = doc.at("settings");
    scene.settings.shadow_samples = value_or(s, "shadow_samples", scene.settings.shadow_samples);
    scene.settings.sky_samples = value_or(s, "sky_samples", scene.settings.sky_samples);
    scene.settings.bounce_samples = value_or(s, "bounce_samples", scene.settings.bounce_samples);
    read_accuracy_settings(s, scene.settings);
    read_validity_settings(s, scene.settings);
  }
  if (seed) scene.settings.seed = *seed;  // taken out before validation
  return scene;
}

// "line L, column C" of a byte offset (nlohmann reports bytes read, 1-based).
std::string line_column(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t k = 0; k + 1 < byte && k < text.size(); ++k) {
    if (text[k] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

}  // namespace

std::string probe_label(const Scene& scene, std::size_t k) {
  const Point3& p = scene.probes[k];
  std::ostringstream os;
  os << "probes[" << k << "] (" << p.x << ", " << p.y << ", " << p.z << ")";
  return os.str();
}

const char* scene_schema_text() noexcept { return detail::kSceneSchemaText; }

IoStatus load_scene(const fs::path& file, Scene& out) {
  // "-": the scene on stdin, named so, the files it names relative to the current folder.
  const bool from_stdin = file == "-";
  const fs::path path = from_stdin ? fs::path("stdin") : file;
  try {
    std::string text;
    if (IoStatus st = detail::read_bounded(from_stdin ? fs::path("/dev/stdin") : file, detail::FileKind::Stream,
                                           detail::kMaxSceneBytes, text);
        !st.ok())
      return from_stdin ? IoStatus{st.code, std::string("stdin").append(st.message, std::string("/dev/stdin").size())}
                        : st;
    if (nested_deeper_than(text, kMaxNesting))
      return IoStatus::error(IoErrc::BadDocument, path, "nested deeper than " + std::to_string(kMaxNesting) + " levels");
    Json doc;
    try {
      doc = Json::parse(text);
    } catch (const Json::parse_error& e) {
      // nlohmann's what() is "[json.exception.parse_error.101] parse error at line 2,
      // column 1: syntax error ..."; keep what follows "parse error at " when it is there.
      const std::string what = e.what();
      const std::size_t at = what.find("parse error at ");
      return IoStatus::error(IoErrc::Unreadable, path,
                             "not valid JSON: " + (at == std::string::npos ? line_column(text, e.byte) + ": " + what
                                                                           : what.substr(at + 15)));
    } catch (const Json::exception& e) {
      return IoStatus::error(IoErrc::Unreadable, path, std::string("not valid JSON: ") + e.what());
    }
    std::optional<std::uint64_t> seed;
    check_before_validation(doc, seed);
    validate(doc);
    Scene scene = read_scene(doc, path, seed);
    io::Sha256 hash;
    hash.update(std::as_bytes(std::span(text.data(), text.size())));
    scene.sha256 = io::to_hex(hash.finish());
    out = std::move(scene);
    return IoStatus::success();
  } catch (const SceneError& e) {
    return IoStatus::error(IoErrc::BadDocument, path, e.path + ": " + e.problem);
  } catch (const std::bad_alloc&) {
    return IoStatus::error(IoErrc::Unreadable, path, "out of memory reading the scene");
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::BadDocument, path, e.what());
  } catch (...) {
    return IoStatus::error(IoErrc::BadDocument, path, "unexpected error reading the scene");
  }
}

}  // namespace shpack::scene
