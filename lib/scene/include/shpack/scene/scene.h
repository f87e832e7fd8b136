// scene.h - a scene for `shpack bake`, as read from its JSON file (docs/scenes.md).
//
// Plain data in Unity's frame, metres, linear RGB, angles in radians. The loader
// (scene_loader.h) validates the file against docs/scene.schema.json and then checks what a
// schema cannot (orthogonal axes, finite numbers, readable files); the engine (lib/bake)
// takes the scene as it is.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "shpack/layout.h"
#include "shpack/lights.h"
#include "shpack/sky.h"

namespace shpack::scene {

enum class EnvironmentType : std::uint8_t { None, Map, Gradient, Preetham };

struct SceneEnvironment {
  EnvironmentType type = EnvironmentType::None;
  // Map: an environment map, read as `shpack convert` reads it.
  std::filesystem::path path;  // resolved against the scene file's folder
  Layout layout = Layout::Auto;
  double rotation_deg = 0;     // yaw about +Y, as Skybox/Panoramic's _Rotation (rotate.h)
  double intensity = 1;        // linear factor on the radiance
  // Gradient: radiance horizon + (zenith - horizon) y above the horizon, ground below
  // (lights.h, add_gradient_sky).
  Rgb zenith{}, horizon{}, ground{};
  // Preetham: the clear sky of sky.h (sun, turbidity, ground, intensity).
  PreethamSky preetham;
};

enum class LightType : std::uint8_t { Directional, Point, Sphere, Spot, Rect, Disk, Hemisphere, Ambient };

// One light; which members count depends on `type` (docs/scenes.md).
struct SceneLight {
  LightType type = LightType::Directional;
  std::string label;       // "lights[2]" or "lights[2] 'lamp'": how messages name it
  // Directional: irradiance at normal incidence. Point, sphere, spot: intensity (W/sr; a
  // `power` in the file is divided by 4 pi). Rect, disk, ambient: radiance. Hemisphere: sky.
  Rgb colour{};
  Rgb ground{};            // hemisphere
  Point3 position;         // point, sphere, spot, rect and disk centre
  Dir3 direction;          // unit: directional and spot, the way light travels; disk, its normal
  double angular_diameter = 0;  // directional
  double radius = 0;            // sphere, disk
  double inner_angle = 0, outer_angle = 0;  // spot half-angles
  Dir3 right, up;               // rect, unit and orthogonal
  double width = 0, height = 0; // rect
};

enum class ShapeType : std::uint8_t { Plane, Sphere, Box, Mesh };

// One piece of geometry. Every shape is a triangle mesh for the ray tracer except spheres,
// which it intersects exactly. Meshes come from OBJ (obj_mesh.h) or glTF (gltf_mesh.h).
struct SceneShape {
  ShapeType type = ShapeType::Plane;
  std::string label;            // "geometry[1] 'floor'"
  Rgb albedo{};                 // diffuse reflectance, each channel in [0, 1)
  Rgb emission{};               // emitted radiance, both sides, uniform
  Point3 centre;                // sphere
  double radius = 0;            // sphere
  // Plane, box and mesh, as triangles: xyz per vertex, three indices per triangle.
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
  // The lightmap UVs (u, v per vertex, Unity's convention: (0, 0) the image's bottom left),
  // when a lightmap is asked for on this shape; empty otherwise.
  std::vector<float> uv;
  // Unit shading normals (xyz per vertex) of a lightmapped mesh whose file has them (glTF
  // NORMAL, OBJ vn on every face corner), in Unity's frame; empty: the triangles' own normals.
  std::vector<float> normals;
};

// The most texels all of a scene's lightmaps may hold together, checked before any is
// allocated (each costs about 3 KB while it bakes).
inline constexpr std::uint64_t kMaxLightmapTexels = std::uint64_t{1} << 20;

// A lightmap asked for on one geometry entry (docs/lightmaps.md): every shape the entry became
// (a glTF mesh: one per material) shares its texels.
struct LightmapTarget {
  std::string name;                   // the entry's name, or "geometry[2]": the files' stem
  std::string label;                  // "geometry[2] 'floor'", for messages
  std::uint32_t width = 0, height = 0;
  bool l2 = false;                    // also the L2 coefficients (else L1)
  std::uint32_t padding = 2;          // texels of dilation around each chart
  std::vector<std::uint32_t> shapes;  // indices into Scene::geometry
};

struct SceneEffects {
  bool direct = false;         // lights, in closed form
  bool environment = false;    // the environment, projected once
  bool shadows = false;        // lights hidden by geometry (needs direct)
  bool sky_occlusion = false;  // the environment hidden by geometry (needs environment)
  bool emission = false;       // emissive geometry seen from the probe
  int bounces = 0;             // diffuse interreflections of what the other effects light
};

// What a probe inside geometry gets (docs/scenes.md, "Probe validity").
enum class InvalidProbes : std::uint8_t {
  Dilate,  // the distance-weighted mean of its nearest valid probes
  Keep,    // what was baked there
  Error,   // the bake fails, naming the probe and the shape around it
  Offset,  // baked at the nearest valid point within max_offset; dilated if there is none
};

struct SceneSettings {
  std::uint64_t seed = 1;
  int shadow_samples = 256;   // points per extended light per probe (rounded up to a full grid)
  int sky_samples = 1024;     // directions per probe for sky_occlusion and emission
  int bounce_samples = 1024;  // paths per probe for bounce
  // Monte Carlo effects sample each probe until their error estimate is below this share of
  // its mean E/pi (%), or max_samples; 0: the fixed counts above.
  double target_error_pct = 1;
  int max_samples = 65536;    // the cap per probe, per effect, per light
  // Probe validity: a probe is invalid when more than this share of its rays first hit a
  // back face (Unity APV's dilation validity threshold, default 0.25).
  double validity_threshold = 0.25;
  InvalidProbes invalid_probes = InvalidProbes::Dilate;
  double max_offset = 0.2;    // metres, for InvalidProbes::Offset
};

struct Scene {
  std::filesystem::path file;
  std::string sha256;           // of the scene file
  std::vector<Point3> probes;
  SceneEnvironment environment;
  std::vector<SceneLight> lights;
  std::vector<SceneShape> geometry;
  std::vector<LightmapTarget> lightmaps;
  SceneEffects effects;
  SceneSettings settings;
};

// The label of probe k, for messages: "probes[3] (1, 0.5, 2)".
std::string probe_label(const Scene& scene, std::size_t k);

}  // namespace shpack::scene
