// Tests of sharded bakes (bake_part.h): merged parts are the one-machine bake bit for bit,
// for any N and thread count; the plan tiles the items by cost; the part file round-trips and
// every wrong part is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "scene/scene_files.h"
#include "shpack/bake/bake_part.h"
#include "shpack/io/sha256.h"
#include "shpack/io/version.h"
#include "shpack/scene/scene_loader.h"

namespace shpack::bake {
namespace {

// A floor with a lightmap under a sun and a sky, a box standing on it (texels under it are
// invalid and dilated), probes around and one inside the box (invalid, dilated), every
// effect that traces rays, and a target: the pilot pools over texels, so a shard that split
// a texel or reordered its points would change its numbers.
const char* kScene = R"({
  "environment": {"type": "gradient", "zenith": [0.2, 0.3, 0.8], "horizon": 0.7, "ground": 0.2},
  "lights": [{"type": "directional", "direction": [-0.4, -0.8, -0.3], "irradiance": 5, "angular_diameter_deg": 4},
             {"type": "point", "position": [1, 1.5, 1], "intensity": 2}],
  "geometry": [
    {"type": "plane", "name": "floor", "position": [0, 0, 0], "right": [0, 0, 1], "up": [1, 0, 0],
     "size": [4, 4], "albedo": 0.5, "lightmap": {"resolution": [8, 8]}},
    {"type": "box", "min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5], "albedo": 0.6}],
  "probes": [[0, 0.5, 0], [1.5, 0.5, 1.5], [-1.5, 1, 0.5], [0.8, 2, -1.2], [-1, 0.3, -1.5]],
  "effects": ["direct", "environment", "shadows", "sky_occlusion", "bounce:1"],
  "settings": {"shadow_samples": 16, "sky_samples": 64, "bounce_samples": 64, "target_error_pct": 5,
               "max_samples": 1024}})";

scene::Scene load(const std::string& name, const std::string& json) {
  scene::Scene scene;
  const io::IoStatus st = scene::load_scene(shpack_test::write_scene(name + ".json", json), scene);
  EXPECT_TRUE(st.ok()) << st.message;
  return scene;
}

BakeOptions threads(unsigned n) {
  BakeOptions options;
  options.threads = n;
  return options;
}

std::vector<BakePart> shards(const scene::Scene& scene, std::uint32_t n, unsigned thread_count) {
  std::vector<BakePart> parts(n);
  for (std::uint32_t k = 1; k <= n; ++k) {
    const io::IoStatus st = bake_part(scene, threads(thread_count), {k, n}, parts[k - 1]);
    EXPECT_TRUE(st.ok()) << st.message;
  }
  return parts;
}

std::vector<std::string> names(std::size_t n) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back("part" + std::to_string(i + 1));
  return out;
}

// Every number of a probe and a texel that the outputs hold, compared exactly.
void expect_same_bake(const BakeResult& a, const BakeResult& b, const LightmapBakeResult& la,
                      const LightmapBakeResult& lb) {
  ASSERT_EQ(a.radiance.size(), b.radiance.size());
  for (std::size_t k = 0; k < a.radiance.size(); ++k) {
    EXPECT_EQ(a.radiance[k], b.radiance[k]) << "probe " << k;
    EXPECT_EQ(a.error_estimate_pct[k], b.error_estimate_pct[k]) << "probe " << k;
    EXPECT_EQ(a.validity[k].backface_fraction, b.validity[k].backface_fraction);
    EXPECT_EQ(a.validity[k].dilated, b.validity[k].dilated);
    for (std::size_t e = 0; e < kEffectCount; ++e) {
      EXPECT_EQ(a.sampling[k][e].samples, b.sampling[k][e].samples);
      EXPECT_EQ(a.sampling[k][e].error, b.sampling[k][e].error);
    }
  }
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    EXPECT_EQ(a.costs[e].rays + la.costs[e].rays, b.costs[e].rays + lb.costs[e].rays) << effect_name(Effect(e));
    EXPECT_EQ(a.costs[e].samples + la.costs[e].samples, b.costs[e].samples + lb.costs[e].samples);
  }
  EXPECT_EQ(a.validity_counts.dilated, b.validity_counts.dilated);
  ASSERT_EQ(la.maps.size(), lb.maps.size());
  for (std::size_t m = 0; m < la.maps.size(); ++m) {
    const LightmapTexels& x = la.maps[m];
    const LightmapTexels& y = lb.maps[m];
    EXPECT_EQ(x.radiance, y.radiance);
    EXPECT_EQ(x.state, y.state);
    EXPECT_EQ(x.error_pct, y.error_pct);
    EXPECT_EQ(x.backface, y.backface);
    EXPECT_EQ(x.coverage, y.coverage);
    EXPECT_EQ(x.used, y.used);
    EXPECT_EQ(x.dilated, y.dilated);
    EXPECT_EQ(x.padded, y.padded);
  }
}

struct OneMachine {
  BakeResult probes;
  LightmapBakeResult maps;
};

OneMachine one_machine(const scene::Scene& scene) {
  OneMachine out;
  EXPECT_TRUE(bake(scene, threads(2), out.probes).ok());
  EXPECT_TRUE(bake_lightmaps(scene, threads(2), out.maps).ok());
  return out;
}

TEST(BakePart, MergedShardsAreTheOneMachineBakeForAnyNAndThreads) {
  const scene::Scene scene = load("shards", kScene);
  const OneMachine one = one_machine(scene);
  ASSERT_GT(one.probes.validity_counts.dilated, 0u);  // the probe in the box
  ASSERT_GT(one.maps.maps[0].dilated, 0u);            // the texels under it
  // 5 probes + 64 texels = 69 items: 100 shards hold more shards than items (some are empty).
  for (const std::uint32_t n : {1u, 2u, 3u, 7u, 100u}) {
    std::vector<BakePart> parts = shards(scene, n, n % 2 + 1);  // 1 or 2 threads, against 2
    std::reverse(parts.begin(), parts.end());                   // any order
    BakeResult probes;
    LightmapBakeResult maps;
    const io::IoStatus st = merge_parts(scene, parts, names(n), probes, maps);
    ASSERT_TRUE(st.ok()) << st.message;
    SCOPED_TRACE("N = " + std::to_string(n));
    expect_same_bake(one.probes, probes, one.maps, maps);
  }
}

TEST(BakePart, PartFileRoundTripsEveryNumber) {
  const scene::Scene scene = load("shards_file", kScene);
  for (BakePart& part : shards(scene, 3, 2)) {
    BakePart back;
    std::string error;
    ASSERT_TRUE(decode_part(encode_part(part), back, error)) << error;
    EXPECT_EQ(back.probes, part.probes);
    EXPECT_EQ(back.texels, part.texels);
    EXPECT_EQ(back.probe_result.radiance, part.probe_result.radiance);
    EXPECT_EQ(back.texel_result.radiance, part.texel_result.radiance);
    EXPECT_EQ(back.texel_result.texels, part.texel_result.texels);
    EXPECT_EQ(back.texel_result.invalid, part.texel_result.invalid);
    EXPECT_EQ(back.probe_result.costs[2].rays, part.probe_result.costs[2].rays);
    EXPECT_EQ(encode_part(back), encode_part(part));
  }
}

TEST(BakePart, AShardCountsTheShadowRaysTheBakeTraces) {
  // A light the bake treats as a delta (scene_lights.h: a point, a spot, a sharp directional
  // light, a sphere of radius 0) has one shadow ray, any other shadow_samples. A sphere light of
  // radius 0 (the point light's limit; the scene file refuses it, the library takes it) is
  // then the point light in the plan's cost: the plan once had its own copy of the rule,
  // without the sphere, and counted 16 shadow rays for it.
  scene::Scene scene = load("plan_delta", kScene);
  const double with_point = estimated_rays(scene);
  scene.lights[1].type = scene::LightType::Sphere;
  scene.lights[1].radius = 0;
  EXPECT_EQ(estimated_rays(scene), with_point);
  scene.lights[1].radius = 0.1;
  EXPECT_EQ(estimated_rays(scene), with_point - 1 + scene.settings.shadow_samples);
}

TEST(BakePart, PlanTilesTheItemsBalancedByCost) {
  // Each texel of the floor costs its points (4 when whole) times a probe's rays, so by cost
  // a shard holds fewer texels than probes would make it. Every shard's cost is within one
  // item's (4 probes' worth) of C / N, the runs tile [0, probes) and [0, texels).
  const scene::Scene scene = load("plan", kScene);
  std::vector<std::uint32_t> points;
  ASSERT_TRUE(lightmap_texel_points(scene, points).ok());
  ASSERT_EQ(points.size(), 64u);
  const double per = estimated_rays(scene);
  double total = per * static_cast<double>(scene.probes.size());
  for (const std::uint32_t p : points) total += per * p;
  for (const std::uint32_t n : {2u, 5u, 13u}) {
    std::uint64_t next_probe = 0, next_texel = 0;
    for (std::uint32_t k = 1; k <= n; ++k) {
      ItemRange probes, texels;
      plan_shard(scene, points, {k, n}, probes, texels);
      EXPECT_EQ(probes.first, next_probe);
      EXPECT_EQ(texels.first, next_texel);
      if (texels.count > 0) {
        EXPECT_EQ(probes.first + probes.count, scene.probes.size());
      }
      next_probe += probes.count;
      next_texel += texels.count;
      double cost = per * static_cast<double>(probes.count);
      for (std::uint64_t u = texels.first; u < texels.first + texels.count; ++u) cost += per * points[u];
      EXPECT_LE(std::abs(cost - total / n), 4 * per) << k << "/" << n;
    }
    EXPECT_EQ(next_probe, scene.probes.size());
    EXPECT_EQ(next_texel, points.size());
  }
}

TEST(BakePart, WrongPartsAreRefusedNamingThePart) {
  const scene::Scene scene = load("refuse", kScene);
  const std::vector<BakePart> good = shards(scene, 3, 2);
  BakeResult probes;
  LightmapBakeResult maps;
  const auto refused = [&](std::vector<BakePart> parts, const std::string& want) {
    const io::IoStatus st = merge_parts(scene, parts, names(parts.size()), probes, maps);
    EXPECT_FALSE(st.ok()) << want;
    EXPECT_NE(st.message.find(want), std::string::npos) << st.message;
    EXPECT_EQ(st.message.find('\n'), std::string::npos);
  };
  refused({good[0], good[2]}, "shard 2/3 is missing");
  refused({good[0], good[1], good[1]}, "part3: shard 2/3 twice (also part2)");
  std::vector<BakePart> other = good;
  other[1].scene_sha256 = std::string(64, '0');
  refused(other, "part2: a part of another scene");
  other = good;
  scene::SceneSettings settings = scene.settings;
  settings.seed += 1;
  other[2].settings = settings_record(settings);
  refused(other, "part3: baked with other settings: seed 2, not the scene's 1");
  settings = scene.settings;
  settings.max_samples = 2048;
  other[2].settings = settings_record(settings);
  refused(other, "part3: baked with other settings: max_samples 2048, not the scene's 1024");
  other = good;
  other[0].version = "0.0.0";
  refused(other, std::string("part1: made by shpack 0.0.0, not by this shpack ") + io::shpack_version());
  other = good;
  other[1].shard.count = 4;
  refused(other, "part2: shard 2/4 is not one of 3");
  other = good;
  std::swap(other[0].probes, other[1].probes);
  refused(other, "its items are not shard");
}

TEST(BakePart, TruncatedOrAlteredPartFilesAreRefused) {
  const scene::Scene scene = load("truncate", kScene);
  const std::string bytes = encode_part(shards(scene, 2, 2)[0]);
  BakePart part;
  std::string error;
  // Every cut: the hash (the last 32 bytes) no longer matches, or the file is too short.
  for (std::size_t cut = 0; cut < bytes.size(); cut += 97) {
    EXPECT_FALSE(decode_part(std::string_view(bytes).substr(0, cut), part, error)) << cut;
    EXPECT_FALSE(error.empty());
  }
  std::string altered = bytes;
  altered[altered.size() / 2] ^= 1;
  EXPECT_FALSE(decode_part(altered, part, error));
  EXPECT_NE(error.find("SHA-256 does not match"), std::string::npos) << error;
  EXPECT_FALSE(decode_part("SHPACK", part, error));
  EXPECT_NE(error.find("not a shpack bake part"), std::string::npos) << error;
  // A well-sealed part holding a NaN (found by fuzz_part): a bake writes none, and the merge
  // would pass it on to every output.
  BakePart nan = shards(scene, 2, 2)[0];
  ASSERT_FALSE(nan.probe_result.radiance.empty());
  nan.probe_result.radiance[0].c[1][2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(decode_part(encode_part(nan), part, error));
  EXPECT_NE(error.find("a NaN or an infinite coefficient"), std::string::npos) << error;
}

// `bytes` (a part without its hash) sealed with its SHA-256, as encode_part does.
std::string sealed(std::string bytes) {
  io::Sha256 hash;
  hash.update(std::as_bytes(std::span(bytes.data(), bytes.size())));
  const io::Sha256Digest digest = hash.finish();
  return bytes.append(reinterpret_cast<const char*>(digest.data()), digest.size());
}

TEST(BakePart, AHeaderCountThatIsNoWholeNumberIsRefused) {
  // A well-sealed header whose probe range starts at 3.9e80 or -1 (found by fuzz_part: read as
  // an unsigned count, a float beyond its range was undefined behaviour).
  const scene::Scene scene = load("header", kScene);
  std::string bytes = encode_part(shards(scene, 2, 2)[0]);
  bytes.resize(bytes.size() - 32);
  const std::size_t at = bytes.find("\"probes\":[") + 10;
  for (const char* bad : {"3.9e80", "-1", "0.5", "\"0\""}) {
    std::string altered = bytes;
    altered.replace(at, 1, bad);  // the first's 0
    BakePart part;
    std::string error;
    EXPECT_FALSE(decode_part(sealed(altered), part, error)) << bad;
    EXPECT_NE(error.find("its header is not a part's"), std::string::npos) << error;
  }
}

TEST(BakePart, ShardTextIsKOfN) {
  ShardSpec s;
  std::string error;
  EXPECT_TRUE(parse_shard("2/8", s, error));
  EXPECT_EQ(s.index, 2u);
  EXPECT_EQ(s.count, 8u);
  for (const char* bad : {"0/3", "4/3", "1/0", "3", "a/b", "1/2/3", "-1/2", "1/1000001", ""})
    EXPECT_FALSE(parse_shard(bad, s, error)) << bad;
}

}  // namespace
}  // namespace shpack::bake
