// window_bench.cpp - the nearest non-negative fit (`--window optimal`, window.h) against
// sloan on the bundled maps (data/hdri/*.exr, exact projection, no other option), as ratios
// from one run.
//
// Printed first, per map and channel, against the unwindowed projection: the RMS and the
// maximum over the sphere of the change of E/pi, both in % of the mean E/pi (L00 of the
// unwindowed Unity form), the exact minimum of E/pi before and after (in % of the mean),
// and the planes optimal used. The maximum of |delta| is exact: max(-min delta, -min -delta)
// by sh_minimum.h.
// Timed: BM_Window/<map>/<window>: one apply_window call (three channels) per iteration.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sh/nonnegative_fit.h"
#include "shpack/io/convert.h"
#include "shpack/sh_minimum.h"
#include "shpack/window.h"

namespace {

using namespace shpack;

struct Map {
  std::string name;
  ShL2 unity_form;  // unwindowed
};

std::vector<Map> bundled_maps() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(SHPACK_HDRI_DIR))
    if (entry.path().extension() == ".exr") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<Map> maps;
  for (const auto& file : files) {
    Conversion conversion;
    if (!io::convert_file(file, io::ConvertSettings{}, conversion).ok()) {
      std::fprintf(stderr, "window_bench: cannot convert %s\n", file.string().c_str());
      continue;
    }
    maps.push_back({file.stem().string(), conversion.sh.unity_form});
  }
  return maps;
}

Window named(const char* text) {
  Window w;
  if (!parse_window(text, w).ok()) std::abort();
  return w;
}

// RMS over the sphere of channel c of a - b: sqrt(sum_i w_i delta_i^2) (nonnegative_fit.h).
double rms_difference(const ShL2& a, const ShL2& b, int c) {
  double sum = 0;
  for (int i = 0; i < kShCount; ++i) sum += rms_weight(i) * (a.c[c][i] - b.c[c][i]) * (a.c[c][i] - b.c[c][i]);
  return std::sqrt(sum);
}

double max_difference(const ShL2& a, const ShL2& b, int c) {
  ShL2 delta, negated;
  for (int i = 0; i < kShCount; ++i) delta.c[c][i] = a.c[c][i] - b.c[c][i], negated.c[c][i] = -delta.c[c][i];
  return std::max(-minimum_on_sphere(delta, c).value, -minimum_on_sphere(negated, c).value);
}

void print_accuracy(const std::vector<Map>& maps) {
  std::printf("%-10s %2s %8s | %7s %7s %7s | %7s %7s %7s %6s   (%% of the mean E/pi)\n", "map", "ch", "min", "sloan",
              "max", "min", "optimal", "max", "min", "planes");
  double worst[2][2] = {};  // [sloan, optimal][rms, max]
  for (const Map& map : maps) {
    ShL2 by[2];
    WindowResult result[2];
    if (!apply_window(map.unity_form, named("sloan"), by[0], &result[0]).ok() ||
        !apply_window(map.unity_form, named("optimal"), by[1], &result[1]).ok())
      std::abort();
    for (int c = 0; c < kChannelCount; ++c) {
      const double mean = map.unity_form.c[c][0] / 100;  // so that values print in %
      std::printf("%-10s %2d %8.3f |", map.name.c_str(), c, minimum_on_sphere(map.unity_form, c).value / mean);
      for (int k = 0; k < 2; ++k) {
        const double rms = rms_difference(by[k], map.unity_form, c) / mean;
        const double max = max_difference(by[k], map.unity_form, c) / mean;
        worst[k][0] = std::max(worst[k][0], rms);
        worst[k][1] = std::max(worst[k][1], max);
        std::printf(" %7.3f %7.3f %7.1e", rms, max, minimum_on_sphere(by[k], c).value / mean);
      }
      std::printf(" %6d\n", result[1].planes[c]);
    }
  }
  std::printf("worst over the maps: sloan RMS %.3f %%, max %.3f %%; optimal RMS %.3f %%, max %.3f %%\n\n",
              worst[0][0], worst[0][1], worst[1][0], worst[1][1]);
}

void window_call(benchmark::State& state, const ShL2& unity_form, Window window) {
  ShL2 out;
  WindowResult result;
  for (auto _ : state) {
    benchmark::DoNotOptimize(apply_window(unity_form, window, out, &result));
    benchmark::DoNotOptimize(out);
  }
  state.counters["planes"] = result.planes[0] + result.planes[1] + result.planes[2];
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<Map> maps = bundled_maps();
  print_accuracy(maps);
  for (const Map& map : maps)
    for (const char* window : {"sloan", "optimal"}) {
      std::string name = "BM_Window/";
      name += map.name;
      name += '/';
      name += window;
      benchmark::RegisterBenchmark(name.c_str(), window_call, map.unity_form, named(window));
    }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
