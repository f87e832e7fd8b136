// free_texels.h (private) - the texels the light search (light_candidates.h) may still grow a
// region over, and the brightest of them, its next seed.
//
// The brightest free texel is kept per tile of kTile x kTile texels and recomputed only for
// the tiles whose texels were taken since, so a search of S seeds costs one pass over the map,
// S passes over the tiles and a pass over each tile a seed's region touched, instead of S
// passes over the map. Memory: one byte a texel and a few bytes a tile.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "extraction/equirect_texels.h"

namespace shpack::detail {

class FreeTexels {
 public:
  // Every texel free. May throw std::bad_alloc.
  explicit FreeTexels(const EquirectTexels& texels);

  bool free(LightTexel t) const { return taken_[index(t)] == 0; }
  void take(LightTexel t);

  struct Seed {
    LightTexel texel;
    double luminance;
  };
  // The free texel of largest Y, the first in row-major order among equal ones; none when no
  // texel is free.
  std::optional<Seed> brightest();

 private:
  static constexpr std::uint32_t kTile = 64;
  // A tile's brightest free texel (index y W + x), or luminance -inf when it has none.
  struct Best {
    double luminance = -std::numeric_limits<double>::infinity();
    std::uint64_t index = 0;
  };
  std::uint64_t index(LightTexel t) const { return std::uint64_t{t.y} * texels_.width() + t.x; }
  std::size_t tile_of(LightTexel t) const { return std::size_t{t.y / kTile} * tiles_x_ + t.x / kTile; }
  Best scan_tile(std::size_t tile) const;

  const EquirectTexels& texels_;
  std::uint32_t tiles_x_;
  std::vector<std::uint8_t> taken_;
  std::vector<Best> best_;
  std::vector<std::uint8_t> stale_;  // per tile: a texel was taken since best_ was computed
  std::vector<std::size_t> stale_tiles_;
};

}  // namespace shpack::detail
