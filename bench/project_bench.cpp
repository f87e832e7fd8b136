// Google Benchmark kernels of the equirect projection. Ratios between rows of one run are
// what to quote (the machine is shared and noisy); the speed targets (docs/accuracy.md) read,
// at 4096 x 2048:
//   exact/4096/1 over ReadSum/4096        (exact against a plain read of the same buffer)
//   Baseline/4096 over exact/4096/1       (the plain per-texel projection against exact)
//   exact/4096/1 over exact/4096/2        (what a second thread buys)
//   Negatives/1024/10/k over Negatives/1024/0/k  (a map with negative texels in most rows
//                                          against none, per policy: k = 0 keep, 1 clamp)
// All are wall-clock (UseRealTime), so the threaded row is comparable.
#include <benchmark/benchmark.h>

#include <map>
#include <random>
#include <utility>
#include <vector>

#include "baseline_projection.h"
#include "shpack/project.h"

namespace {

// One random float RGB image per width (height = width / 2), made once and shared, so that
// the read-sum floor, exact and the baseline read the same buffer at the same address.
const std::vector<float>& random_rgb(unsigned width) {
  static std::map<unsigned, std::vector<float>> images;
  std::vector<float>& rgb = images[width];
  if (rgb.empty()) {
    std::mt19937_64 rng(0x5eed);
    std::uniform_real_distribution<float> value(0.0f, 4.0f);
    rgb.resize(std::size_t{3} * width * (width / 2));
    for (float& v : rgb) v = value(rng);
  }
  return rgb;
}

// random_rgb(width) with the green value of about `per_mille` texels in 1000 negated, spread
// over the rows (10 per mille is the share of a real map that holds 5053 negative texels at
// 1024 x 512, which then touch most rows).
const std::vector<float>& rgb_with_negatives(unsigned width, unsigned per_mille) {
  static std::map<std::pair<unsigned, unsigned>, std::vector<float>> images;
  std::vector<float>& rgb = images[{width, per_mille}];
  if (rgb.empty()) {
    rgb = random_rgb(width);
    std::mt19937_64 rng(0x5eed);
    std::uniform_int_distribution<unsigned> draw(0, 999);
    for (std::size_t t = 0; t < rgb.size() / 3; ++t)
      if (draw(rng) < per_mille) rgb[3 * t + 1] = -rgb[3 * t + 1];
  }
  return rgb;
}

// The timed loop: the width x width/2 equirect map `rgb` projected once per iteration.
void project_each_iteration(benchmark::State& state, const std::vector<float>& rgb, unsigned width,
                            const shpack::ProjectOptions& options) {
  const unsigned height = width / 2;
  for (auto _ : state) {
    shpack::ShL2 sh;
    if (!shpack::project_equirect(shpack::make_view(rgb.data(), width, height, 3), options, sh).ok())
      state.SkipWithError("projection failed");
    benchmark::DoNotOptimize(sh);
  }
  state.SetItemsProcessed(state.iterations() * width * height);
}

void BM_ProjectEquirect(benchmark::State& state, shpack::SamplingMethod method) {
  const auto width = static_cast<unsigned>(state.range(0)), height = width / 2;
  const auto threads = static_cast<unsigned>(state.range(1));
  const std::vector<float>& rgb = random_rgb(width);
  shpack::ProjectOptions options;
  options.method = method;
  options.threads = threads;
  project_each_iteration(state, rgb, width, options);
  state.SetBytesProcessed(state.iterations() * width * height * 3 * sizeof(float));
}
BENCHMARK_CAPTURE(BM_ProjectEquirect, exact, shpack::SamplingMethod::Exact)
    ->Args({1024, 1})->Args({4096, 1})->Args({4096, 2})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ProjectEquirect, center, shpack::SamplingMethod::Center)
    ->Args({1024, 1})->Unit(benchmark::kMillisecond);

// The same projection of a map with and without negative texels, under each policy: the
// kernel's speed should not depend on how many there are.
void BM_Negatives(benchmark::State& state) {
  const auto width = static_cast<unsigned>(state.range(0));
  const std::vector<float>& rgb = rgb_with_negatives(width, static_cast<unsigned>(state.range(1)));
  shpack::ProjectOptions options;
  options.negative = state.range(2) == 0 ? shpack::Negative::Keep : shpack::Negative::Clamp;
  options.threads = 1;
  project_each_iteration(state, rgb, width, options);
}
BENCHMARK(BM_Negatives)
    ->ArgsProduct({{1024}, {0, 10, 250}, {0, 1}})->UseRealTime()->Unit(benchmark::kMillisecond);

// The floor: read and sum the same buffer once, in double.
void BM_ReadSum(benchmark::State& state) {
  const auto width = static_cast<unsigned>(state.range(0));
  const std::vector<float>& rgb = random_rgb(width);
  for (auto _ : state) {
    double sum = 0.0;
    for (float v : rgb) sum += v;
    benchmark::DoNotOptimize(sum);
  }
  state.SetBytesProcessed(state.iterations() * rgb.size() * sizeof(float));
}
BENCHMARK(BM_ReadSum)->Arg(1024)->Arg(4096)->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_Baseline(benchmark::State& state) {
  const auto width = static_cast<unsigned>(state.range(0)), height = width / 2;
  const std::vector<float>& rgb = random_rgb(width);
  for (auto _ : state) benchmark::DoNotOptimize(shpack::bench::baseline_project(rgb.data(), width, height));
  state.SetItemsProcessed(state.iterations() * width * height);
}
BENCHMARK(BM_Baseline)->Arg(1024)->Arg(4096)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
