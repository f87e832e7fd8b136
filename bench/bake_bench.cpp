// bake_bench.cpp - what `shpack bake` costs (docs/scenes.md), as ratios from one run.
// Times are the process's CPU time (all threads), so a loaded machine or a library's own
// worker threads do not distort the ratios.
//
//  - BM_BakeAnalytic/10000: 10,000 probes x 8 analytic lights, no visibility effect, one
//    thread, I/O excluded: the whole bake (closed forms, then Unity form and the 27 floats).
//  - BM_DecodeExr: decoding one 1024 x 512 float RGB EXR (ZIP, OpenImageIO through
//    shpack_io's read_image_file, one thread), the yardstick: an analytic bake must beat it.
//  - BM_ShadowRays: `shadows` against a ~1M-triangle mesh (a perforated canopy between the
//    probes and four lights), one thread: rays per CPU second (the "rays/s" counter).
//  - BM_BakeGrowth/probes/lights/bounces: how the time grows with each.
#include <benchmark/benchmark.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

#include "shpack/bake/bake.h"
#include "shpack/convolution.h"
#include "shpack/io/image_file.h"
#include "shpack/unity_pack.h"

namespace {

using namespace shpack;

std::vector<Point3> probe_grid(int count) {
  std::vector<Point3> probes;
  const int side = static_cast<int>(std::ceil(std::cbrt(count)));
  for (int k = 0; k < count; ++k)
    probes.push_back({-2.0 + 4.0 * (k % side) / side, 0.5 + 1.0 * ((k / side) % side) / side,
                      -2.0 + 4.0 * (k / (side * side)) / side});
  return probes;
}

// Eight lights, one of every kind.
std::vector<scene::SceneLight> eight_lights() {
  std::vector<scene::SceneLight> lights(8);
  lights[0].type = scene::LightType::Directional;
  lights[0].direction = {0.29, -0.95, 0.1};
  lights[0].colour = {900, 880, 850};
  lights[0].angular_diameter = 0.53 * std::numbers::pi / 180;
  lights[1].type = scene::LightType::Sphere;
  lights[1].position = {0, 4, 0};
  lights[1].radius = 0.2;
  lights[1].colour = {20, 20, 20};
  lights[2].type = scene::LightType::Point;
  lights[2].position = {3, 3.5, -1};
  lights[2].colour = {5, 4, 3};
  lights[3].type = scene::LightType::Spot;
  lights[3].position = {-3, 3.5, 1};
  lights[3].direction = {0.6, -0.8, 0};
  lights[3].outer_angle = 0.7;
  lights[3].inner_angle = 0.4;
  lights[3].colour = {9, 9, 9};
  lights[4].type = scene::LightType::Rect;
  lights[4].position = {0, 2, 4};
  lights[4].right = {-1, 0, 0};
  lights[4].up = {0, 1, 0};
  lights[4].width = 1.2;
  lights[4].height = 1;
  lights[4].colour = {40, 40, 40};
  lights[5].type = scene::LightType::Disk;
  lights[5].position = {0, 3.9, -3};
  lights[5].direction = {0, -1, 0};
  lights[5].radius = 0.3;
  lights[5].colour = {30, 30, 30};
  lights[6].type = scene::LightType::Hemisphere;
  lights[6].colour = {0.3, 0.4, 0.6};
  lights[6].ground = {0.1, 0.1, 0.1};
  lights[7].type = scene::LightType::Ambient;
  lights[7].colour = {0.02, 0.02, 0.02};
  for (std::size_t k = 0; k < lights.size(); ++k) lights[k].label = "lights[" + std::to_string(k) + "]";
  return lights;
}

void BM_BakeAnalytic(benchmark::State& state) {
  scene::Scene scene;
  scene.file = "bench.json";
  scene.probes = probe_grid(static_cast<int>(state.range(0)));
  scene.lights = eight_lights();
  scene.effects.direct = true;
  bake::BakeOptions options;
  options.threads = 1;
  for (auto _ : state) {
    bake::BakeResult result;
    if (!bake::bake(scene, options, result).ok()) state.SkipWithError("bake failed");
    float checksum = 0;
    for (const ShL2& radiance : result.radiance) checksum += to_unity_sh(radiance_to_unity_form(radiance))[0][0];
    benchmark::DoNotOptimize(checksum);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BakeAnalytic)->Arg(10000)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

std::filesystem::path exr_1024x512() {
  const auto path = std::filesystem::temp_directory_path() / "shpack_bench_1024x512.exr";
  if (std::filesystem::exists(path)) return path;
  std::vector<float> pixels(1024 * 512 * 3);
  for (std::size_t k = 0; k < pixels.size(); ++k) pixels[k] = 0.5f + 0.4f * std::sin(0.001f * static_cast<float>(k));
  auto out = OIIO::ImageOutput::create(path.string());
  OIIO::ImageSpec spec(1024, 512, 3, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  out->open(path.string(), spec);
  out->write_image(OIIO::TypeDesc::FLOAT, pixels.data());
  out->close();
  return path;
}

// One thread, like the bake it is compared with (OpenImageIO would otherwise decode EXR
// tiles on all cores).
void BM_DecodeExr(benchmark::State& state) {
  OIIO::attribute("threads", 1);
  OIIO::attribute("exr_threads", 1);
  const auto path = exr_1024x512();
  for (auto _ : state) {
    io::ImageFile image;
    if (!io::read_image_file(path, image).ok()) state.SkipWithError("cannot read the EXR");
    benchmark::DoNotOptimize(image.pixels.data());
  }
}
BENCHMARK(BM_DecodeExr)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// A canopy at y = 3 over [-10, 10]^2: an n x n vertex grid, gently waved, with every fourth
// 8 x 8 block of cells left open so that some shadow rays get through.
scene::SceneShape canopy(int n) {
  scene::SceneShape shape;
  shape.type = scene::ShapeType::Mesh;
  shape.label = "canopy";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -10.0 + 20.0 * i / (n - 1), z = -10.0 + 20.0 * j / (n - 1);
      shape.vertices.insert(shape.vertices.end(),
                            {static_cast<float>(x), static_cast<float>(3.0 + 0.1 * std::sin(x) * std::cos(z)),
                             static_cast<float>(z)});
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if (((i / 8) + (j / 8)) % 4 == 0) continue;
      const auto v = static_cast<std::uint32_t>(j * n + i), w = static_cast<std::uint32_t>(n);
      shape.indices.insert(shape.indices.end(), {v, v + 1, v + w + 1, v, v + w + 1, v + w});
    }
  return shape;
}

scene::Scene shadow_scene(int probes, int lights, int bounces) {
  scene::Scene scene;
  scene.file = "bench.json";
  scene.probes = probe_grid(probes);
  const std::vector<scene::SceneLight> all = eight_lights();
  for (const int k : {1, 4, 5, 2, 0, 3}) {  // sphere, rect, disk, point, sun, spot
    if (static_cast<int>(scene.lights.size()) == lights) break;
    scene.lights.push_back(all[k]);
    scene.lights.back().position.y = std::max(scene.lights.back().position.y, 4.5);
  }
  scene.geometry.push_back(canopy(817));  // 2 x 816^2 x 3/4 = 998,784 triangles
  scene.geometry.back().albedo = {0.5, 0.5, 0.5};
  // A floor under the probes, so that bounce paths go back and forth.
  scene::SceneShape floor;
  floor.type = scene::ShapeType::Box;
  floor.albedo = {0.5, 0.5, 0.5};
  floor.vertices = {-10, -0.1f, -10, 10, -0.1f, -10, 10, 0, -10, -10, 0, -10,
                    -10, -0.1f, 10,  10, -0.1f, 10,  10, 0, 10,  -10, 0, 10};
  floor.indices = {0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 3, 2, 6, 3, 6, 7,
                   0, 5, 1, 0, 4, 5, 0, 3, 7, 0, 7, 4, 1, 5, 6, 1, 6, 2};
  scene.geometry.push_back(floor);
  scene.effects.direct = true;
  scene.effects.shadows = true;
  scene.effects.bounces = bounces;
  // Fixed counts (no target): the growth measured is that of a fixed amount of work. The
  // hand-made floor's faces are not all wound outwards, so validity would find every probe
  // "inside" it: keep them as baked (validity is not what this measures).
  scene.settings.target_error_pct = 0;
  scene.settings.invalid_probes = scene::InvalidProbes::Keep;
  scene.settings.shadow_samples = 64;
  scene.settings.bounce_samples = 64;
  return scene;
}

void BM_ShadowRays(benchmark::State& state) {
  const scene::Scene scene = shadow_scene(64, 4, 0);
  bake::BakeOptions options;
  options.threads = 1;
  std::uint64_t rays = 0;
  double seconds = 0;
  for (auto _ : state) {
    bake::BakeResult result;
    if (!bake::bake(scene, options, result).ok()) state.SkipWithError("bake failed");
    const bake::EffectCost& c = result.costs[static_cast<std::size_t>(bake::Effect::Shadows)];
    rays += c.rays;
    seconds += c.cpu_ms / 1000;
    state.counters["triangles"] = static_cast<double>(result.geometry.triangles);
    state.counters["bvh_ms"] = result.geometry.time_ms;
  }
  state.counters["rays/s"] = static_cast<double>(rays) / seconds;
}
BENCHMARK(BM_ShadowRays)->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_BakeGrowth(benchmark::State& state) {
  const scene::Scene scene = shadow_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
                                       static_cast<int>(state.range(2)));
  bake::BakeOptions options;
  options.threads = 1;
  for (auto _ : state) {
    bake::BakeResult result;
    if (!bake::bake(scene, options, result).ok()) state.SkipWithError("bake failed");
    double passes = 0, rays = 0;
    for (const bake::EffectCost& c : result.costs) {
      passes += c.cpu_ms;
      rays += static_cast<double>(c.rays);
    }
    state.counters["passes_cpu_ms"] = passes;  // without the BVH build
    state.counters["rays"] = rays;
  }
}
BENCHMARK(BM_BakeGrowth)
    ->Args({256, 1, 0})->Args({512, 1, 0})->Args({1024, 1, 0})
    ->Args({256, 2, 0})->Args({256, 4, 0})
    ->Args({256, 1, 1})->Args({256, 1, 2})->Args({256, 1, 4})
    ->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
