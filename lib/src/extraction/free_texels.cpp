#include "extraction/free_texels.h"

#include <algorithm>

namespace shpack::detail {
namespace {

constexpr std::uint32_t tiles(std::uint32_t texels, std::uint32_t tile) { return (texels + tile - 1) / tile; }

}  // namespace

FreeTexels::FreeTexels(const EquirectTexels& texels)
    : texels_(texels),
      tiles_x_(tiles(texels.width(), kTile)),
      taken_(std::size_t{texels.width()} * texels.height(), 0),
      best_(std::size_t{tiles_x_} * tiles(texels.height(), kTile)),
      stale_(best_.size(), 0) {
  for (std::size_t k = 0; k < best_.size(); ++k) best_[k] = scan_tile(k);
}

void FreeTexels::take(LightTexel t) {
  taken_[index(t)] = 1;
  const std::size_t tile = tile_of(t);
  if (stale_[tile] == 0) stale_tiles_.push_back(tile);
  stale_[tile] = 1;
}

FreeTexels::Best FreeTexels::scan_tile(std::size_t tile) const {
  const auto x0 = static_cast<std::uint32_t>(tile % tiles_x_ * kTile);
  const auto y0 = static_cast<std::uint32_t>(tile / tiles_x_ * kTile);
  const std::uint32_t x1 = std::min(texels_.width(), x0 + kTile), y1 = std::min(texels_.height(), y0 + kTile);
  Best best;
  for (std::uint32_t y = y0; y < y1; ++y)
    for (std::uint32_t x = x0; x < x1; ++x)
      if (free({x, y}))
        if (const double l = texels_.luminance(x, y); l > best.luminance) best = {l, index({x, y})};
  return best;
}

std::optional<FreeTexels::Seed> FreeTexels::brightest() {
  for (std::size_t tile : stale_tiles_) {
    best_[tile] = scan_tile(tile);
    stale_[tile] = 0;
  }
  stale_tiles_.clear();
  // Within a tile the scan keeps the first of equal texels in row-major order; across tiles
  // the smaller index wins a tie, so the rule holds for the whole map.
  const Best* best = nullptr;
  for (const Best& b : best_)
    if (b.luminance > -std::numeric_limits<double>::infinity() &&
        (best == nullptr || b.luminance > best->luminance ||
         (b.luminance == best->luminance && b.index < best->index)))
      best = &b;
  if (best == nullptr) return std::nullopt;
  const auto w = std::uint64_t{texels_.width()};
  return Seed{{static_cast<std::uint32_t>(best->index % w), static_cast<std::uint32_t>(best->index / w)},
              best->luminance};
}

}  // namespace shpack::detail
