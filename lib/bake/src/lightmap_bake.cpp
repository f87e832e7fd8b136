#include "shpack/bake/lightmap_bake.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "error_estimate.h"
#include "lightmap_fill.h"
#include "shpack/convolution.h"
#include "lightmap_raster.h"
#include "surface_points.h"

namespace shpack::bake {
namespace {

// Lifts a surface point off its surface along the normal by the engine's ray offset,
// epsilon (1 + max|x_k|) (bake.cpp), so that rays leaving it clear the surface in float.
Vec3 lifted(const Vec3& p, const Vec3& n) {
  const double eps = 1e-4 * (1.0 + std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
  return p + eps * n;
}

std::string texel_label(const scene::Scene& scene, const std::vector<LightmapRaster>& rasters, const TexelRef& ref) {
  const std::uint32_t w = rasters[ref.map].width;
  return scene.lightmaps[ref.map].label + "'s lightmap texel (" + std::to_string(ref.texel % w) + ", " +
         std::to_string(ref.texel / w) + ")";
}

// Point k's error estimate, every effect together (independent: in quadrature).
ChannelError point_error(const BakeResult& baked, std::size_t k) {
  ChannelError all{};
  for (const EffectSampling& s : baked.sampling[k]) all = combine_errors(all, s.error);
  return all;
}

// The mean of the points' values.
template <class Value>
ShL2 mean_of(const std::vector<std::size_t>& points, const Value& value) {
  ShL2 sum;
  for (const std::size_t k : points)
    for (int c = 0; c < kChannelCount; ++c)
      for (int i = 0; i < kShCount; ++i) sum.c[c][i] += value(k).c[c][i];
  return scaled(sum, 1.0 / static_cast<double>(points.size()));
}

// The error of a mean of K independent estimates, sqrt(sum e_k^2) / K per channel.
template <class Error>
ChannelError error_of_mean(const std::vector<std::size_t>& points, const Error& error) {
  ChannelError err2{};
  for (const std::size_t k : points) {
    const ChannelError e = error(k);
    for (int c = 0; c < kChannelCount; ++c) err2[c] += e[c] * e[c];
  }
  ChannelError err{};
  for (int c = 0; c < kChannelCount; ++c) err[c] = std::sqrt(err2[c]) / static_cast<double>(points.size());
  return err;
}

io::IoStatus rasterize(const scene::Scene& scene, std::vector<LightmapRaster>& rasters) {
  rasters.assign(scene.lightmaps.size(), {});
  for (std::size_t m = 0; m < scene.lightmaps.size(); ++m) {
    std::string why;
    if (!rasterize_lightmap(scene.lightmaps[m], scene.geometry, rasters[m], why))
      return io::IoStatus::error(io::IoErrc::BadDocument, scene.file, why);
  }
  return io::IoStatus::success();
}

// The used texels (those with points) of every map, map after map, each texel's number in
// its map's raster; and where each map's points start in one numbering of all maps' points.
struct UsedTexels {
  std::vector<TexelRef> texels;
  std::vector<std::uint64_t> first_point;  // per map
};

UsedTexels used_texels(const std::vector<LightmapRaster>& rasters) {
  UsedTexels used;
  std::uint64_t points = 0;
  for (std::size_t m = 0; m < rasters.size(); ++m) {
    const LightmapRaster& r = rasters[m];
    used.first_point.push_back(points);
    for (std::size_t t = 0; t + 1 < r.first.size(); ++t)
      if (r.first[t] != r.first[t + 1]) used.texels.push_back({static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(t)});
    points += r.first.back();
  }
  return used;
}

// A texel's value and error from the baked points [a, b) that count for it (bake_texels),
// its backface fraction the mean over all of its points. The value is the mean of the
// points; its error that of a mean of K independent estimates, sqrt(sum e_k^2) / K per
// channel, in % of the texel's own mean E/pi (error_estimate.h).
void gather_texel(const BakeResult& baked, std::size_t a, std::size_t b, double backface, bool invalid,
                  LightmapTexelPart& out) {
  std::vector<std::size_t> counted;
  for (std::size_t k = a; k < b; ++k) counted.push_back(k);
  const ShL2 radiance = mean_of(counted, [&](std::size_t k) -> const ShL2& { return baked.radiance[k]; });
  const ChannelError err = error_of_mean(counted, [&](std::size_t k) { return point_error(baked, k); });
  out.radiance.push_back(radiance);
  out.error_pct.push_back(static_cast<float>(error_pct(err, radiance)));
  out.backface.push_back(static_cast<float>(backface));
  out.invalid.push_back(invalid ? 1 : 0);
  if (baked.effects.empty()) return;
  std::array<ShL2, kEffectCount> effects;
  std::array<EffectSampling, kEffectCount> sampling;
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    effects[e] = mean_of(counted, [&](std::size_t k) -> const ShL2& { return baked.effects[k][e]; });
    EffectSampling& s = sampling[e];
    s.error = error_of_mean(counted, [&](std::size_t k) { return baked.sampling[k][e].error; });
    s.error_pct = error_pct(s.error, radiance);
    for (const std::size_t k : counted) {
      s.samples += baked.sampling[k][e].samples;
      s.capped = s.capped || baked.sampling[k][e].capped;
    }
    s.samples /= counted.size();
  }
  out.effects.push_back(effects);
  out.sampling.push_back(sampling);
}

void add_costs(std::array<EffectCost, kEffectCount>& into, const std::array<EffectCost, kEffectCount>& from) {
  for (std::size_t e = 0; e < kEffectCount; ++e) add_cost(into[e], from[e]);
}

// Every map's texels from the part of every used texel (in order), dilated and padded.
io::IoStatus finish_rasters(const scene::Scene& scene, const std::vector<LightmapRaster>& rasters,
                            const LightmapTexelPart& all, LightmapBakeResult& out) {
  const UsedTexels used = used_texels(rasters);
  if (all.texels != used.texels)
    return io::IoStatus::error(io::IoErrc::BadDocument, scene.file, "the lightmap texels baked are not the scene's");
  LightmapBakeResult result;
  std::vector<std::vector<bool>> invalid(rasters.size());
  for (std::size_t m = 0; m < rasters.size(); ++m) {
    const LightmapRaster& raster = rasters[m];
    const std::size_t texels = static_cast<std::size_t>(raster.width) * raster.height;
    LightmapTexels map;
    map.width = raster.width;
    map.height = raster.height;
    map.radiance.assign(texels, ShL2{});
    map.state.assign(texels, TexelState::Unused);
    map.coverage = raster.coverage;
    map.error_pct.assign(texels, 0.0f);
    map.backface.assign(texels, 0.0f);
    map.degenerate = raster.degenerate;
    map.shared = raster.shared;
    map.points = raster.first[texels];
    if (!all.effects.empty()) {
      map.effects.assign(texels, {});
      map.sampling.assign(texels, {});
    }
    invalid[m].assign(texels, false);
    result.maps.push_back(std::move(map));
  }
  for (std::size_t u = 0; u < all.texels.size(); ++u) {
    const auto [m, t] = all.texels[u];
    LightmapTexels& map = result.maps[m];
    map.radiance[t] = all.radiance[u];
    map.error_pct[t] = all.error_pct[u];
    map.backface[t] = all.backface[u];
    map.state[t] = TexelState::Baked;
    invalid[m][t] = all.invalid[u] != 0;
    ++map.used;
    if (!all.effects.empty()) {
      map.effects[t] = all.effects[u];
      map.sampling[t] = all.sampling[u];
    }
  }
  for (std::size_t m = 0; m < rasters.size(); ++m) {
    dilate_invalid_texels(result.maps[m], rasters[m].chart, invalid[m]);
    pad_charts(result.maps[m], rasters[m].chart, scene.lightmaps[m].padding);
  }
  result.costs = all.costs;
  result.geometry = all.geometry;
  result.validity_cost = all.validity_cost;
  result.time_ms = all.time_ms;
  out = std::move(result);
  return io::IoStatus::success();
}

// Every point of some texels, lifted off its surface, as the probes of one scene: they share
// the tracer and the environment. Surfaces are no probes to move: validity is measured and
// dilation done within charts.
struct TexelPoints {
  scene::Scene scene;
  SurfacePoints surface;            // normals and stream ids; choose_points adds the rest
  std::vector<std::size_t> first;   // per texel, its first point; one past the end
};

TexelPoints texel_points(const scene::Scene& scene, const std::vector<LightmapRaster>& rasters, const UsedTexels& used,
                         const std::vector<TexelRef>& texels) {
  TexelPoints out;
  out.scene = scene;
  out.scene.probes.clear();
  out.scene.lightmaps.clear();
  out.scene.settings.invalid_probes = scene::InvalidProbes::Keep;
  for (const auto& [m, t] : texels) {
    const LightmapRaster& r = rasters[m];
    out.first.push_back(out.surface.normals.size());
    for (std::size_t k = r.first[t]; k < r.first[t + 1]; ++k) {
      const Vec3 p = lifted(r.points[k].position, r.points[k].geometric);
      out.scene.probes.push_back({p.x, p.y, p.z});
      out.surface.normals.push_back(r.points[k].normal);
      out.surface.stream_ids.push_back(kSurfaceStreams + used.first_point[m] + k);
    }
  }
  out.first.push_back(out.surface.normals.size());
  return out;
}

// The points to bake, by validity. Points inside geometry (backface fraction above the
// threshold: the part of the floor a box stands on) are not baked while their texel has
// others: they would chase the error target in the dark to settings.max_samples for nothing.
// A texel with no other is invalid, for dilation, and bakes all of its points at the fixed
// counts: what a chart with no valid texel keeps (finish_lightmaps decides, needing the whole
// chart). Each chosen point is grouped by its texel (u).
TexelPoints choose_points(const TexelPoints& all, const std::vector<ProbeValidity>& validity, double threshold) {
  TexelPoints chosen;
  chosen.scene = all.scene;
  chosen.scene.probes.clear();
  const auto valid = [&](std::size_t k) { return validity[k].backface_fraction <= threshold; };
  for (std::size_t u = 0; u + 1 < all.first.size(); ++u) {
    bool any_valid = false;
    for (std::size_t k = all.first[u]; k < all.first[u + 1]; ++k) any_valid = any_valid || valid(k);
    for (std::size_t k = all.first[u]; k < all.first[u + 1]; ++k)
      if (!any_valid || valid(k)) {
        chosen.scene.probes.push_back(all.scene.probes[k]);
        chosen.surface.normals.push_back(all.surface.normals[k]);
        chosen.surface.group.push_back(static_cast<std::uint32_t>(u));
        chosen.surface.untargeted.push_back(!any_valid);
        chosen.surface.stream_ids.push_back(all.surface.stream_ids[k]);
      }
  }
  return chosen;
}

// The texels [first, first + count) of `used` from their rasters.
io::IoStatus bake_texels(const scene::Scene& scene, const BakeOptions& options,
                         const std::vector<LightmapRaster>& rasters, const UsedTexels& used, std::size_t first,
                         std::size_t count, LightmapTexelPart& out) {
  const auto start = std::chrono::steady_clock::now();
  LightmapTexelPart part;
  part.texels.assign(used.texels.begin() + static_cast<std::ptrdiff_t>(first),
                     used.texels.begin() + static_cast<std::ptrdiff_t>(first + count));
  // Progress names the lightmap's passes as such ("lightmap bounce"), counting points.
  BakeOptions lightmap_options = options;
  if (options.progress)
    lightmap_options.progress = [&options](const char* pass, std::size_t done, std::size_t total) {
      const std::string name = std::string("lightmap ") + pass;
      options.progress(name.c_str(), done, total);
    };
  const TexelPoints all = texel_points(scene, rasters, used, part.texels);
  std::vector<ProbeValidity> validity;
  if (io::IoStatus st = surface_validity(all.scene, all.surface.stream_ids, lightmap_options, validity,
                                         part.validity_cost, part.geometry);
      !st.ok())
    return st;
  TexelPoints chosen = choose_points(all, validity, scene.settings.validity_threshold);
  chosen.surface.label = [&](std::size_t k) {
    return texel_label(scene, rasters, part.texels[chosen.surface.group[k]]);
  };
  BakeResult baked;
  if (io::IoStatus st = bake_surface_points(chosen.scene, chosen.surface, lightmap_options, baked); !st.ok()) return st;
  // A texel's chosen points are consecutive, and every texel has some.
  for (std::size_t a = 0, u = 0; u < part.texels.size(); ++u) {
    std::size_t b = a;
    while (b < chosen.surface.group.size() && chosen.surface.group[b] == u) ++b;
    double backface = 0;
    for (std::size_t k = all.first[u]; k < all.first[u + 1]; ++k) backface += validity[k].backface_fraction;
    backface /= static_cast<double>(all.first[u + 1] - all.first[u]);
    gather_texel(baked, a, b, backface, chosen.surface.untargeted[a], part);
    a = b;
  }
  add_costs(part.costs, baked.costs);
  if (baked.geometry.built) part.geometry = baked.geometry;
  part.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  out = std::move(part);
  return io::IoStatus::success();
}

}  // namespace

io::IoStatus lightmap_texel_points(const scene::Scene& scene, std::vector<std::uint32_t>& points) {
  std::vector<LightmapRaster> rasters;
  if (io::IoStatus st = rasterize(scene, rasters); !st.ok()) return st;
  points.clear();
  for (const TexelRef& ref : used_texels(rasters).texels)
    points.push_back(rasters[ref.map].first[ref.texel + 1] - rasters[ref.map].first[ref.texel]);
  return io::IoStatus::success();
}

io::IoStatus bake_lightmap_texels(const scene::Scene& scene, const BakeOptions& options, std::size_t first,
                                  std::size_t count, LightmapTexelPart& out) {
  std::vector<LightmapRaster> rasters;
  if (io::IoStatus st = rasterize(scene, rasters); !st.ok()) return st;
  const UsedTexels used = used_texels(rasters);
  if (first > used.texels.size() || count > used.texels.size() - first)
    return io::IoStatus::error(io::IoErrc::BadDocument, scene.file, "the lightmap texels asked for are not the scene's");
  return bake_texels(scene, options, rasters, used, first, count, out);
}

io::IoStatus finish_lightmaps(const scene::Scene& scene, const LightmapTexelPart& all, LightmapBakeResult& out) {
  std::vector<LightmapRaster> rasters;
  if (io::IoStatus st = rasterize(scene, rasters); !st.ok()) return st;
  return finish_rasters(scene, rasters, all, out);
}

io::IoStatus bake_lightmaps(const scene::Scene& scene, const BakeOptions& options, LightmapBakeResult& out) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<LightmapRaster> rasters;
  if (io::IoStatus st = rasterize(scene, rasters); !st.ok()) return st;
  const UsedTexels used = used_texels(rasters);
  LightmapTexelPart all;
  if (io::IoStatus st = bake_texels(scene, options, rasters, used, 0, used.texels.size(), all); !st.ok()) return st;
  if (io::IoStatus st = finish_rasters(scene, rasters, all, out); !st.ok()) return st;
  out.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return io::IoStatus::success();
}

}  // namespace shpack::bake
