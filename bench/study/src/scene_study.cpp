#include "shpack/study/scene_study.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "shpack/bake/bake.h"
#include "shpack/scene/scene_loader.h"
#include "shpack/study/accuracy.h"

namespace shpack::study {
namespace {

using bake::Effect;
constexpr std::array<Effect, 4> kRandomEffects = {Effect::Shadows, Effect::SkyOcclusion, Effect::Emission, Effect::Bounce};

io::IoStatus bake_with(const scene::Scene& base, int samples, std::uint64_t seed, bool next_events, bool fixed,
                       unsigned threads, bake::BakeResult& out) {
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
  return bake::bake(scene, options, out);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// The worst probe's error of one effect's part against the reference's, in % of the
// reference probe's mean E/pi: measured as the reference total plus the part's difference.
double effect_error(const bake::BakeResult& run, const bake::BakeResult& reference,
                    const std::vector<AccuracyMeter>& meters, Effect e) {
  double worst = 0;
  const auto i = static_cast<std::size_t>(e);
  for (std::size_t k = 0; k < meters.size(); ++k) {
    ShL2 x = reference.radiance[k];
    for (int c = 0; c < kChannelCount; ++c)
      for (int j = 0; j < kShCount; ++j) x.c[c][j] += run.effects[k][i].c[c][j] - reference.effects[k][i].c[c][j];
    const double err = meters[k].measure(x).err_max_pct;
    if (std::isfinite(err)) worst = std::max(worst, err);
  }
  return worst;
}

double worst_estimate(const bake::BakeResult& run, Effect e) {
  double worst = 0;
  for (const auto& probe : run.sampling) worst = std::max(worst, probe[static_cast<std::size_t>(e)].error_pct);
  return worst;
}

double mean_samples(const bake::BakeResult& run, Effect e) {
  double sum = 0;
  for (const auto& probe : run.sampling) sum += static_cast<double>(probe[static_cast<std::size_t>(e)].samples);
  return run.sampling.empty() ? 0 : sum / static_cast<double>(run.sampling.size());
}

}  // namespace

io::IoStatus run_scene_study(const std::filesystem::path& scene_file, const SceneStudySettings& settings,
                             std::vector<SceneStudyRecord>& records,
                             const std::function<void(const SceneStudyRecord&)>& progress) {
  scene::Scene scene;
  if (io::IoStatus st = scene::load_scene(scene_file, scene); !st.ok()) return st;
  bake::BakeResult reference;
  if (io::IoStatus st = bake_with(scene, settings.reference_samples, 0x5eed0000u, true, true, settings.threads, reference);
      !st.ok())
    return st;
  std::vector<AccuracyMeter> meters;
  for (const ShL2& r : reference.radiance) meters.emplace_back(r);
  std::vector<Effect> effects;
  for (const Effect e : kRandomEffects)
    if (reference.costs[static_cast<std::size_t>(e)].rays > 0) effects.push_back(e);
  if (effects.empty())
    return io::IoStatus::error(io::IoErrc::InvalidArgument, scene_file,
                               "no effect of this scene samples anything (shadows, sky_occlusion, emission or bounce "
                               "with geometry in the way): nothing to measure");

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
      std::vector<double> estimates(effects.size(), 0.0), samples(effects.size(), 0.0);
      for (unsigned seed = 1; seed <= settings.seeds; ++seed) {
        bake::BakeResult run;
        if (io::IoStatus st = bake_with(scene, n, seed, s.next_events, s.fixed, settings.threads, run); !st.ok()) return st;
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
        r.effect = bake::effect_name(effects[k]);
        r.estimator = s.estimator;
        r.samples = s.fixed ? n : samples[k];
        r.seeds = settings.seeds;
        r.cpu_ms = median(times[k]);
        double sum = 0;
        for (const double e : errors[k]) sum += e * e;
        r.err_max_pct = std::sqrt(sum / static_cast<double>(errors[k].size()));
        r.err_worst_pct = *std::max_element(errors[k].begin(), errors[k].end());
        r.estimate_pct = estimates[k];
        if (progress) progress(r);
        by_effect[k].push_back(std::move(r));
      }
    }
  }
  for (auto& effect : by_effect) records.insert(records.end(), effect.begin(), effect.end());
  return io::IoStatus::success();
}

}  // namespace shpack::study
