#include "lightmap_fill.h"

#include <limits>

#include "shpack/convolution.h"

namespace shpack::bake {
namespace {

struct Update {
  std::size_t texel;
  std::int32_t chart;
  ShL2 value;
};

// The mean of texel t's 8-neighbours that `source` accepts and whose chart is `want` (any
// chart when `want` < 0: the lowest one found is taken). False when none is.
template <class Source>
bool neighbour_mean(const LightmapTexels& map, const std::vector<std::int32_t>& chart, std::size_t t,
                    std::int32_t want, Source&& source, Update& out) {
  const std::int64_t W = map.width, H = map.height;
  const std::int64_t i = static_cast<std::int64_t>(t) % W, j = static_cast<std::int64_t>(t) / W;
  std::int32_t pick = want;
  if (pick < 0) {
    pick = std::numeric_limits<std::int32_t>::max();
    for (std::int64_t dj = -1; dj <= 1; ++dj)
      for (std::int64_t di = -1; di <= 1; ++di) {
        const std::int64_t x = i + di, y = j + dj;
        if ((di || dj) && x >= 0 && y >= 0 && x < W && y < H && source(static_cast<std::size_t>(y * W + x)))
          pick = std::min(pick, chart[static_cast<std::size_t>(y * W + x)]);
      }
  }
  ShL2 sum;
  int count = 0;
  for (std::int64_t dj = -1; dj <= 1; ++dj)
    for (std::int64_t di = -1; di <= 1; ++di) {
      const std::int64_t x = i + di, y = j + dj;
      if (!(di || dj) || x < 0 || y < 0 || x >= W || y >= H) continue;
      const std::size_t n = static_cast<std::size_t>(y * W + x);
      if (!source(n) || chart[n] != pick) continue;
      for (int c = 0; c < kChannelCount; ++c)
        for (int k = 0; k < kShCount; ++k) sum.c[c][k] += map.radiance[n].c[c][k];
      ++count;
    }
  if (count == 0) return false;
  out = {t, pick, scaled(sum, 1.0 / count)};
  return true;
}

}  // namespace

void dilate_invalid_texels(LightmapTexels& map, const std::vector<std::int32_t>& chart,
                           const std::vector<bool>& invalid) {
  std::vector<bool> pending = invalid;
  const auto filled = [&](std::size_t n) { return map.state[n] != TexelState::Unused && !pending[n]; };
  for (;;) {
    std::vector<Update> ring;
    for (std::size_t t = 0; t < pending.size(); ++t) {
      Update u;
      if (pending[t] && neighbour_mean(map, chart, t, chart[t], filled, u)) ring.push_back(u);
    }
    if (ring.empty()) break;
    for (const Update& u : ring) {
      map.radiance[u.texel] = u.value;
      map.state[u.texel] = TexelState::Dilated;
      pending[u.texel] = false;
      ++map.dilated;
    }
  }
  for (const bool p : pending) map.invalid_kept += p ? 1 : 0;
}

void pad_charts(LightmapTexels& map, std::vector<std::int32_t> chart, std::uint32_t rings) {
  const auto filled = [&](std::size_t n) { return map.state[n] != TexelState::Unused; };
  for (std::uint32_t r = 0; r < rings; ++r) {
    std::vector<Update> ring;
    for (std::size_t t = 0; t < map.state.size(); ++t) {
      Update u;
      if (map.state[t] == TexelState::Unused && neighbour_mean(map, chart, t, -1, filled, u)) ring.push_back(u);
    }
    if (ring.empty()) return;
    for (const Update& u : ring) {
      map.radiance[u.texel] = u.value;
      map.state[u.texel] = TexelState::Padded;
      chart[u.texel] = u.chart;
      ++map.padded;
    }
  }
}

}  // namespace shpack::bake
