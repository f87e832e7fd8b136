#include "shpack/study/scene_study.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "shpack/bake/bake.h"
#include "shpack/bake/lightmap_bake.h"
#include "shpack/scene/scene_loader.h"
#include "shpack/study/accuracy.h"
#include "shpack/study/draws.h"

namespace shpack::study {
namespace {

using bake::Effect;
constexpr std::array<Effect, 4> kRandomEffects = {Effect::Shadows, Effect::SkyOcclusion, Effect::Emission, Effect::Bounce};

// One bake's receivers: the probes, or every lightmap's texels (row by row, map after map),
// with each one's effect parts and sampling; `measured` marks those that count (every probe;
// the Baked texels: dilated and padded ones copy their neighbours and have no parts).
struct Receivers {
  std::vector<ShL2> radiance;
  std::vector<std::array<ShL2, bake::kEffectCount>> effects;
  std::vector<std::array<bake::EffectSampling, bake::kEffectCount>> sampling;
  std::vector<bool> measured;
  std::array<bake::EffectCost, bake::kEffectCount> costs{};
  double wall_ms = 0;  // the whole bake
  std::size_t count = 0;  // receivers measured
};

// The study's lightmaps: each at most `side` texels a side, its aspect kept (the reference
// bakes every point at reference_samples; per texel the estimators converge as at any size).
scene::Scene study_lightmaps(const scene::Scene& base, std::uint32_t side) {
  scene::Scene scene = base;
  scene.probes.clear();
  for (scene::LightmapTarget& t : scene.lightmaps) {
    const double scale = std::min(1.0, static_cast<double>(side) / std::max(t.width, t.height));
    t.width = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(t.width * scale)));
    t.height = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(t.height * scale)));
  }
  return scene;
}

io::IoStatus bake_with(const scene::Scene& base, Receiver kind, int samples, std::uint64_t seed, bool next_events,
                       bool fixed, unsigned threads, Receivers& out) {
  scene::Scene scene = base;
  scene.settings.seed = seed;
  if (fixed) {
    scene.settings.target_error_pct = 0;
    scene.settings.shadow_samples = scene.settings.sky_samples = scene.settings.bounce_samples = samples;
  }
  bake::BakeOptions options;
  options.threads = threads;
  options.keep_effects = true;
  options.next_events = next_events;
  const auto start = std::chrono::steady_clock::now();
  Receivers r;
  if (kind == Receiver::Probes) {
    bake::BakeResult baked;
    if (io::IoStatus st = bake::bake(scene, options, baked); !st.ok()) return st;
    r.radiance = std::move(baked.radiance);
    r.effects = std::move(baked.effects);
    r.sampling = std::move(baked.sampling);
    r.measured.assign(r.radiance.size(), true);
    r.costs = baked.costs;
  } else {
    bake::LightmapBakeResult baked;
    if (io::IoStatus st = bake::bake_lightmaps(scene, options, baked); !st.ok()) return st;
    for (bake::LightmapTexels& map : baked.maps) {
      r.radiance.insert(r.radiance.end(), map.radiance.begin(), map.radiance.end());
      r.effects.insert(r.effects.end(), map.effects.begin(), map.effects.end());
      r.sampling.insert(r.sampling.end(), map.sampling.begin(), map.sampling.end());
      for (const bake::TexelState state : map.state) r.measured.push_back(state == bake::TexelState::Baked);
    }
    r.costs = baked.costs;
  }
  r.wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  r.count = static_cast<std::size_t>(std::count(r.measured.begin(), r.measured.end(), true));
  out = std::move(r);
  return io::IoStatus::success();
}

// Whether receiver k counts in both bakes (validity is measured with the bake's seed, so a
// texel at the edge of a box's footprint may be baked in one and dilated in the other).
bool both(const Receivers& run, const Receivers& reference, std::size_t k) {
  return run.measured[k] && reference.measured[k];
}

// The worst receiver's error of one effect's part against the reference's, in % of the
// reference receiver's mean E/pi: measured as the reference total plus the part's difference.
double effect_error(const Receivers& run, const Receivers& reference, const std::vector<AccuracyMeter>& meters,
                    Effect e) {
  double worst = 0;
  const auto i = static_cast<std::size_t>(e);
  for (std::size_t k = 0; k < meters.size(); ++k) {
    if (!both(run, reference, k)) continue;
    ShL2 x = reference.radiance[k];
    for (int c = 0; c < kChannelCount; ++c)
      for (int j = 0; j < kShCount; ++j) x.c[c][j] += run.effects[k][i].c[c][j] - reference.effects[k][i].c[c][j];
    const double err = meters[k].measure(x).err_max_pct;
    if (std::isfinite(err)) worst = std::max(worst, err);
  }
  return worst;
}

double worst_estimate(const Receivers& run, Effect e) {
  double worst = 0;
  for (std::size_t k = 0; k < run.sampling.size(); ++k)
    if (run.measured[k]) worst = std::max(worst, run.sampling[k][static_cast<std::size_t>(e)].error_pct);
  return worst;
}

double mean_samples(const Receivers& run, Effect e) {
  double sum = 0;
  for (std::size_t k = 0; k < run.sampling.size(); ++k)
    if (run.measured[k]) sum += static_cast<double>(run.sampling[k][static_cast<std::size_t>(e)].samples);
  return run.count ? sum / static_cast<double>(run.count) : 0;
}

// The study of one kind of receiver of the scene (records in the order effect, estimator,
// count), or nothing when no random effect of it samples anything.
io::IoStatus study_receivers(const std::filesystem::path& scene_file, const scene::Scene& scene, Receiver kind,
                             const SceneStudySettings& settings, std::vector<SceneStudyRecord>& records,
                             const std::function<void(const SceneStudyRecord&)>& progress) {
  Receivers reference;
  if (io::IoStatus st = bake_with(scene, kind, settings.reference_samples, 0x5eed0000u, true, true, settings.threads,
                                  reference);
      !st.ok())
    return st;
  std::vector<AccuracyMeter> meters;
  for (const ShL2& r : reference.radiance) meters.emplace_back(r);
  std::vector<Effect> effects;
  for (const Effect e : kRandomEffects)
    if (reference.costs[static_cast<std::size_t>(e)].rays > 0) effects.push_back(e);

  struct Series {
    const char* estimator;
    bool next_events, fixed;
  };
  const std::vector<Series> series = {{"next-events", true, true}, {"directions", false, true}, {"settings", true, false}};
  // One bake per (series, count, seed) gives every effect's part: keep them per effect.
  std::vector<std::vector<SceneStudyRecord>> by_effect(effects.size());
  for (const Series& s : series) {
    const std::vector<int> counts = s.fixed ? settings.counts : std::vector<int>{0};
    for (const int n : counts) {
      std::vector<std::vector<double>> times(effects.size()), errors(effects.size());
      std::vector<double> estimates(effects.size(), 0.0), samples(effects.size(), 0.0), rates;
      std::size_t measured = 0;
      for (unsigned seed = 1; seed <= settings.seeds; ++seed) {
        Receivers run;
        if (io::IoStatus st = bake_with(scene, kind, n, seed, s.next_events, s.fixed, settings.threads, run); !st.ok())
          return st;
        measured = run.count;
        rates.push_back(run.wall_ms > 0 ? 1000.0 * static_cast<double>(run.count) / run.wall_ms : 0.0);
        for (std::size_t k = 0; k < effects.size(); ++k) {
          times[k].push_back(run.costs[static_cast<std::size_t>(effects[k])].cpu_ms);
          errors[k].push_back(effect_error(run, reference, meters, effects[k]));
          estimates[k] += worst_estimate(run, effects[k]) / settings.seeds;
          samples[k] += mean_samples(run, effects[k]) / settings.seeds;
        }
      }
      for (std::size_t k = 0; k < effects.size(); ++k) {
        SceneStudyRecord r;
        r.scene = scene_file.filename().string();
        r.receivers = kind == Receiver::Probes ? "probes" : "texels";
        r.count = measured;
        r.effect = bake::effect_name(effects[k]);
        r.estimator = s.estimator;
        r.samples = s.fixed ? n : samples[k];
        r.seeds = settings.seeds;
        r.cpu_ms = median(times[k]);
        r.per_s = median(rates);
        double sum = 0;
        for (const double e : errors[k]) sum += e * e;
        r.err_max_pct = std::sqrt(sum / static_cast<double>(errors[k].size()));
        r.err_worst_pct = *std::max_element(errors[k].begin(), errors[k].end());
        r.estimate_pct = estimates[k];
        r.reference_estimate_pct = worst_estimate(reference, effects[k]);
        if (progress) progress(r);
        by_effect[k].push_back(std::move(r));
      }
    }
  }
  for (auto& effect : by_effect) records.insert(records.end(), effect.begin(), effect.end());
  return io::IoStatus::success();
}

}  // namespace

io::IoStatus run_scene_study(const std::filesystem::path& scene_file, const SceneStudySettings& settings,
                             std::vector<SceneStudyRecord>& records,
                             const std::function<void(const SceneStudyRecord&)>& progress) {
  scene::Scene scene;
  if (io::IoStatus st = scene::load_scene(scene_file, scene); !st.ok()) return st;
  const std::size_t before = records.size();
  if (!scene.probes.empty()) {
    scene::Scene probes = scene;
    probes.lightmaps.clear();
    if (io::IoStatus st = study_receivers(scene_file, probes, Receiver::Probes, settings, records, progress); !st.ok())
      return st;
  }
  if (!scene.lightmaps.empty())
    if (io::IoStatus st = study_receivers(scene_file, study_lightmaps(scene, settings.lightmap_side), Receiver::Texels,
                                          settings, records, progress);
        !st.ok())
      return st;
  if (records.size() == before)
    return io::IoStatus::error(io::IoErrc::InvalidArgument, scene_file,
                               "no effect of this scene samples anything (shadows, sky_occlusion, emission or bounce "
                               "with geometry in the way): nothing to measure");
  return io::IoStatus::success();
}

}  // namespace shpack::study
