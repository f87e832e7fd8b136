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

// Where each baked point belongs.
struct PointOwner {
  std::uint32_t map = 0;
  std::uint32_t texel = 0;
};

// Lifts a surface point off its surface along the normal by the engine's ray offset,
// epsilon (1 + max|x_k|) (bake.cpp), so that rays leaving it clear the surface in float.
Vec3 lifted(const Vec3& p, const Vec3& n) {
  const double eps = 1e-4 * (1.0 + std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
  return p + eps * n;
}

std::string texel_label(const scene::Scene& scene, const std::vector<LightmapRaster>& rasters, const PointOwner& o) {
  const std::uint32_t w = rasters[o.map].width;
  return scene.lightmaps[o.map].label + "'s lightmap texel (" + std::to_string(o.texel % w) + ", " +
         std::to_string(o.texel / w) + ")";
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

// A texel's value, error and validity from its points. Points inside geometry (backface
// fraction above the threshold: the part of the floor a box stands on) do not count while
// the texel has any other; a texel with none other is invalid, for dilation. The value is the
// mean of the points that count; its error that of a mean of K independent estimates,
// sqrt(sum e_k^2) / K per channel, in % of the texel's own mean E/pi (error_estimate.h).
void gather_texels(const scene::Scene& scene, const LightmapRaster& raster, const BakeResult& baked,
                   std::size_t first_point, LightmapTexels& map, std::vector<bool>& invalid) {
  const std::size_t texels = static_cast<std::size_t>(raster.width) * raster.height;
  map.width = raster.width;
  map.height = raster.height;
  map.radiance.assign(texels, ShL2{});
  map.state.assign(texels, TexelState::Unused);
  map.coverage = raster.coverage;
  map.error_pct.assign(texels, 0.0f);
  map.backface.assign(texels, 0.0f);
  map.degenerate = raster.degenerate;
  map.shared = raster.shared;
  invalid.assign(texels, false);
  const bool parts = !baked.effects.empty();
  if (parts) {
    map.effects.assign(texels, {});
    map.sampling.assign(texels, {});
  }
  const double threshold = scene.settings.validity_threshold;
  for (std::size_t t = 0; t < texels; ++t) {
    const std::size_t a = first_point + raster.first[t], b = first_point + raster.first[t + 1];
    if (a == b) continue;
    double backface = 0;
    bool any_valid = false;
    for (std::size_t k = a; k < b; ++k) {
      backface += baked.validity[k].backface_fraction;
      any_valid = any_valid || baked.validity[k].backface_fraction <= threshold;
    }
    std::vector<std::size_t> counted;
    for (std::size_t k = a; k < b; ++k)
      if (!any_valid || baked.validity[k].backface_fraction <= threshold) counted.push_back(k);
    map.radiance[t] = mean_of(counted, [&](std::size_t k) -> const ShL2& { return baked.radiance[k]; });
    const ChannelError err = error_of_mean(counted, [&](std::size_t k) { return point_error(baked, k); });
    map.error_pct[t] = static_cast<float>(error_pct(err, map.radiance[t]));
    if (parts)
      for (std::size_t e = 0; e < kEffectCount; ++e) {
        map.effects[t][e] = mean_of(counted, [&](std::size_t k) -> const ShL2& { return baked.effects[k][e]; });
        EffectSampling& s = map.sampling[t][e];
        s.error = error_of_mean(counted, [&](std::size_t k) { return baked.sampling[k][e].error; });
        s.error_pct = error_pct(s.error, map.radiance[t]);
        for (const std::size_t k : counted) {
          s.samples += baked.sampling[k][e].samples;
          s.capped = s.capped || baked.sampling[k][e].capped;
        }
        s.samples /= counted.size();
      }
    map.backface[t] = static_cast<float>(backface / static_cast<double>(b - a));
    map.state[t] = TexelState::Baked;
    invalid[t] = !any_valid;
    ++map.used;
  }
  map.points = raster.first[texels];
}

// Which points to bake: a texel's valid points; a texel with none, all of its points when its
// chart has no valid texel to dilate from (it keeps what was baked), else none (dilated).
std::vector<bool> points_to_bake(const scene::Scene& scene, const std::vector<LightmapRaster>& rasters,
                                 const std::vector<ProbeValidity>& validity) {
  const double threshold = scene.settings.validity_threshold;
  const auto valid = [&](std::size_t k) { return validity[k].backface_fraction <= threshold; };
  std::vector<bool> wanted(validity.size(), false);
  std::size_t first = 0;
  for (const LightmapRaster& r : rasters) {
    const std::size_t texels = r.first.size() - 1;
    std::vector<bool> texel_valid(texels, false);
    std::vector<std::int32_t> valid_charts;
    for (std::size_t t = 0; t < texels; ++t)
      for (std::size_t k = first + r.first[t]; k < first + r.first[t + 1]; ++k)
        if (valid(k)) {
          texel_valid[t] = true;
          wanted[k] = true;
          valid_charts.push_back(r.chart[t]);
        }
    std::sort(valid_charts.begin(), valid_charts.end());
    for (std::size_t t = 0; t < texels; ++t)
      if (!texel_valid[t] && r.first[t] != r.first[t + 1] &&
          !std::binary_search(valid_charts.begin(), valid_charts.end(), r.chart[t]))
        for (std::size_t k = first + r.first[t]; k < first + r.first[t + 1]; ++k) wanted[k] = true;
    first += r.first[texels];
  }
  return wanted;
}

// Where each map's texels start in one numbering of every map's texels.
std::vector<std::uint32_t> first_texels(const std::vector<LightmapRaster>& rasters) {
  std::vector<std::uint32_t> first;
  std::uint32_t next = 0;
  for (const LightmapRaster& r : rasters) {
    first.push_back(next);
    next += static_cast<std::uint32_t>(r.first.size() - 1);
  }
  return first;
}

void add_costs(std::array<EffectCost, kEffectCount>& into, const std::array<EffectCost, kEffectCount>& from) {
  for (std::size_t e = 0; e < kEffectCount; ++e) {
    into[e].enabled = into[e].enabled || from[e].enabled;
    into[e].time_ms += from[e].time_ms;
    into[e].cpu_ms += from[e].cpu_ms;
    into[e].rays += from[e].rays;
    into[e].samples += from[e].samples;
    into[e].analytic += from[e].analytic;
  }
}

}  // namespace

io::IoStatus bake_lightmaps(const scene::Scene& scene, const BakeOptions& options, LightmapBakeResult& out) {
  const auto start = std::chrono::steady_clock::now();
  LightmapBakeResult result;
  std::vector<LightmapRaster> rasters(scene.lightmaps.size());
  for (std::size_t m = 0; m < scene.lightmaps.size(); ++m) {
    std::string why;
    if (!rasterize_lightmap(scene.lightmaps[m], scene.geometry, rasters[m], why))
      return io::IoStatus::error(io::IoErrc::BadDocument, scene.file, why);
  }
  // Progress names the lightmap's passes as such ("lightmap bounce"), counting points.
  BakeOptions lightmap_options = options;
  if (options.progress)
    lightmap_options.progress = [&options](const char* pass, std::size_t done, std::size_t total) {
      const std::string name = std::string("lightmap ") + pass;
      options.progress(name.c_str(), done, total);
    };
  // Every map's points in one bake: they share the tracer and the environment.
  scene::Scene points = scene;
  points.probes.clear();
  points.lightmaps.clear();
  // Surfaces are no probes to move: validity is measured and dilation done within charts.
  points.settings.invalid_probes = scene::InvalidProbes::Keep;
  std::vector<Vec3> normals;
  std::vector<PointOwner> owners;
  for (std::size_t m = 0; m < rasters.size(); ++m) {
    const LightmapRaster& r = rasters[m];
    for (std::size_t t = 0; t + 1 < r.first.size(); ++t)
      for (std::size_t k = r.first[t]; k < r.first[t + 1]; ++k) {
        const Vec3 p = lifted(r.points[k].position, r.points[k].geometric);
        points.probes.push_back({p.x, p.y, p.z});
        normals.push_back(r.points[k].normal);
        owners.push_back({static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(t)});
      }
  }
  // Validity first; then only the points that count are baked (gather_texels): a point inside
  // geometry would chase its error target in the dark to settings.max_samples for nothing.
  std::vector<ProbeValidity> validity;
  if (io::IoStatus st = surface_validity(points, lightmap_options, validity, result.validity_cost, result.geometry); !st.ok())
    return st;
  const std::vector<bool> wanted = points_to_bake(scene, rasters, validity);
  scene::Scene chosen = points;
  chosen.probes.clear();
  std::vector<Vec3> chosen_normals;
  std::vector<std::size_t> index_of;  // chosen point -> point
  // The target is each texel's (gather_texels averages its baked points): a group per texel,
  // its points consecutive (texel by texel, map after map).
  std::vector<std::uint32_t> texel_of;
  const std::vector<std::uint32_t> first_texel = first_texels(rasters);
  for (std::size_t k = 0; k < points.probes.size(); ++k)
    if (wanted[k]) {
      chosen.probes.push_back(points.probes[k]);
      chosen_normals.push_back(normals[k]);
      index_of.push_back(k);
      texel_of.push_back(first_texel[owners[k].map] + owners[k].texel);
    }
  BakeResult part;
  const auto label = [&](std::size_t k) { return texel_label(scene, rasters, owners[index_of[k]]); };
  if (io::IoStatus st = bake_surface_points(chosen, chosen_normals, texel_of, label, lightmap_options, part); !st.ok())
    return st;
  BakeResult baked;  // every point: the chosen ones' results, zero for the others (never read)
  baked.radiance.assign(points.probes.size(), ShL2{});
  baked.sampling.assign(points.probes.size(), {});
  if (options.keep_effects) baked.effects.assign(points.probes.size(), {});
  for (std::size_t c = 0; c < index_of.size(); ++c) {
    baked.radiance[index_of[c]] = part.radiance[c];
    baked.sampling[index_of[c]] = part.sampling[c];
    if (options.keep_effects) baked.effects[index_of[c]] = part.effects[c];
  }
  baked.validity = std::move(validity);
  baked.costs = part.costs;
  baked.geometry = part.geometry.built ? part.geometry : result.geometry;
  std::size_t first_point = 0;
  for (std::size_t m = 0; m < rasters.size(); ++m) {
    LightmapTexels map;
    std::vector<bool> invalid;
    gather_texels(scene, rasters[m], baked, first_point, map, invalid);
    first_point += map.points;
    dilate_invalid_texels(map, rasters[m].chart, invalid);
    pad_charts(map, rasters[m].chart, scene.lightmaps[m].padding);
    result.maps.push_back(std::move(map));
  }
  add_costs(result.costs, baked.costs);
  result.geometry = baked.geometry;
  result.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  out = std::move(result);
  return io::IoStatus::success();
}

}  // namespace shpack::bake
