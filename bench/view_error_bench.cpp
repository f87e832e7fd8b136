// view_error_bench.cpp - what the view error (view_error.h) costs beside the projection it
// measures, on random equirect maps, one thread unless said, as ratios from one run:
//   BM_Project/W    project_equirect (exact), the projection every convert makes;
//   BM_Reference/W  the reference E/pi: begin_equirect, add_rows of the whole image, finish;
//   BM_Sample/W/T   the reference at the 512 normals (sample_view_reference) on T threads;
//   BM_Compare      unity_view_error on those samples (what --extract-lights repeats per trial).
#include <benchmark/benchmark.h>

#include "shpack/pipeline.h"
#include "shpack/project.h"
#include "shpack/view_error.h"
#include "shpack/view_reference.h"

namespace {

using namespace shpack;

struct Map {
  std::vector<float> rgb;
  ImageView view;
};

const Map& map_of(std::uint32_t width) {
  static std::vector<std::pair<std::uint32_t, Map>> cache;
  for (auto& [w, m] : cache)
    if (w == width) return m;
  Map m;
  const std::uint32_t height = width / 2;
  m.rgb.resize(std::size_t{3} * width * height);
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  for (float& v : m.rgb) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    v = static_cast<float>(state >> 40) / static_cast<float>(1 << 24);
  }
  m.view = make_view(m.rgb.data(), width, height, 3);
  if (!resolve_view(m.view).ok()) std::abort();
  cache.emplace_back(width, std::move(m));
  return cache.back().second;
}

ViewReference reference_of(const ImageView& view) {
  ViewReference ref;
  if (!ref.begin_equirect(view.width, view.height, {}).ok() || !ref.add_rows(view, 0).ok() || !ref.finish().ok())
    std::abort();
  return ref;
}

void BM_Project(benchmark::State& state) {
  const Map& m = map_of(static_cast<std::uint32_t>(state.range(0)));
  for (auto _ : state) {
    ShL2 radiance;
    if (!project_equirect(m.view, {}, radiance).ok()) std::abort();
    benchmark::DoNotOptimize(radiance);
  }
}

void BM_Reference(benchmark::State& state) {
  const Map& m = map_of(static_cast<std::uint32_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(reference_of(m.view));
}

void BM_Sample(benchmark::State& state) {
  const ViewReference ref = reference_of(map_of(static_cast<std::uint32_t>(state.range(0))).view);
  const auto threads = static_cast<unsigned>(state.range(1));
  for (auto _ : state) {
    ViewSamples samples;
    if (!sample_view_reference(ref, samples, threads).ok()) std::abort();
    benchmark::DoNotOptimize(samples);
  }
}

void BM_Compare(benchmark::State& state) {
  const Map& m = map_of(1024);
  ViewSamples samples;
  if (!sample_view_reference(reference_of(m.view), samples).ok()) std::abort();
  ShL2 radiance;
  FinishedSh sh;
  if (!project_equirect(m.view, {}, radiance).ok() || !finish_projection(radiance, {}, sh).ok()) std::abort();
  for (auto _ : state) benchmark::DoNotOptimize(unity_view_error(samples, {}, sh.shader, {}));
}

BENCHMARK(BM_Project)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Reference)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sample)->Args({1024, 1})->Args({1024, 2})->Args({4096, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Compare)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
