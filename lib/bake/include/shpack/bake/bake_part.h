// bake_part.h - a bake split into shards that run anywhere and merge into exactly the bake
// of one machine (docs/scale.md).
//
// Work items. A scene's work is its probes, in order, then its lightmaps' used texels, in
// the numbering of lightmap_bake.h. Each item's estimated cost is the rays it takes at the
// scene's fixed counts (estimated_rays: a texel costs its points' worth), and shard K of N
// holds the items whose cost midpoints fall in [(K - 1) C / N, K C / N) of the running total
// C of the cost: contiguous ranges of probes and of texels, balanced by cost, not by count.
//
// Exactness. A probe's and a texel point's random streams are keyed by their numbers in the
// whole scene (bake.h, lightmap_bake.h), and everything that needs other items (the invalid
// probes' dilation, the texels' dilation and padding within their charts, the probes'
// error measures) is done by merge_parts, over every item: merged parts give the one-machine
// bake's numbers bit for bit, for any N and any thread count (costs are summed; times too).
//
// The part file (encode_part): "SHPACKPART 1\n", a one-line JSON header (the scene's path
// and SHA-256, shpack's version, the settings, the shard K/N, the item ranges and the
// totals), then
// the items' numbers as little-endian binary records (the probes', then the texels'), then
// the SHA-256 of every byte before it. decode_part checks the hash first, so a truncated or
// altered part is refused before any count in it is trusted.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "shpack/bake/bake.h"
#include "shpack/bake/lightmap_bake.h"

namespace shpack::bake {

struct ShardSpec {
  std::uint32_t index = 1;  // K, 1 to count
  std::uint32_t count = 1;  // N
};

// "K/N" with 1 <= K <= N <= 1000000; false with `error` set otherwise.
bool parse_shard(std::string_view text, ShardSpec& out, std::string& error);
// "K/N".
std::string shard_text(ShardSpec shard);

// The rays one receiver takes at the scene's fixed counts: validity rays when the scene has
// geometry, one closed form per light, a shadow ray per delta light or settings.shadow_samples
// per extended one, settings.sky_samples for sky_occlusion and for emission, and
// settings.bounce_samples paths of (bounces + 1) segments with a shadow ray at each vertex.
double estimated_rays(const scene::Scene& scene);

// Items [first, first + count) of probes and texels.
struct ItemRange {
  std::uint64_t first = 0, count = 0;
  friend bool operator==(const ItemRange&, const ItemRange&) = default;
};

struct BakePart {
  std::string scene_file;  // the scene's path where the part was baked, absolute
  std::string scene_sha256;
  std::string version;  // shpack's
  std::string settings;  // settings_record of the scene's settings
  ShardSpec shard;
  std::uint64_t probes_total = 0, texels_total = 0;
  ItemRange probes, texels;
  BakeResult probe_result;      // bake_probe_range's, of `probes`
  LightmapTexelPart texel_result;  // bake_lightmap_texels's, of `texels`
};

// The scene's settings (every key of SceneSettings, the seed too) as one line of JSON, as a
// part records them; and the first key where a part's record differs from a scene's,
// "max_samples 1024, not the scene's 65536" (empty if none).
std::string settings_record(const scene::SceneSettings& settings);
std::string settings_difference(const std::string& part, const std::string& scene);

// The ranges of shard K/N (texel_points: lightmap_texel_points's).
void plan_shard(const scene::Scene& scene, const std::vector<std::uint32_t>& texel_points, ShardSpec shard,
                ItemRange& probes, ItemRange& texels);

// Bakes shard `shard` of the scene.
io::IoStatus bake_part(const scene::Scene& scene, const BakeOptions& options, ShardSpec shard, BakePart& out);

std::string encode_part(const BakePart& part);

// Refuses, with `error` one line (without the file's name): not a part, a hash that does not
// match (truncated or altered), a header that does not say what it holds, counts the bytes
// do not hold. Memory is bounded by the size of `bytes`.
bool decode_part(std::string_view bytes, BakePart& out, std::string& error);

// The parts of one bake, any order, into what bake() and bake_lightmaps() give. Refuses,
// naming the part by `names` (parallel to parts): a part of another version, other settings
// (naming the first that differs), another scene,
// parts of different N, a shard twice, a shard missing, ranges that do not tile the items.
io::IoStatus merge_parts(const scene::Scene& scene, std::vector<BakePart>& parts, const std::vector<std::string>& names,
                         BakeResult& probes, LightmapBakeResult& lightmaps);

}  // namespace shpack::bake
