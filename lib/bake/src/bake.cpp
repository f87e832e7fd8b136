#include "shpack/bake/bake.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <system_error>
#include <thread>

#include "batch_sampling.h"
#include "emitters.h"
#include "environment.h"
#include "error_estimate.h"
#include "probe_validity.h"
#include "sampling.h"
#include "shpack/convolution.h"
#include "sobol.h"
#include "scene_lights.h"
#include "surface_domain.h"
#include "surface_points.h"
#include "tracer.h"

namespace shpack::bake {
namespace {

using Clock = std::chrono::steady_clock;
using io::IoErrc;
using io::IoStatus;
constexpr std::size_t kChunk = 16;  // probes handed to a worker at a time

struct Counters {
  std::uint64_t rays = 0, samples = 0, analytic = 0;
};

bool is_black(const Rgb& c) noexcept { return c[0] == 0 && c[1] == 0 && c[2] == 0; }

void add_scaled(ShL2& acc, const ShL2& x, double s) noexcept {
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) acc.c[c][i] += s * x.c[c][i];
}

// Runs body(probe, counters) over all probes on `threads` threads (the caller is one of them
// and reports progress). Per-thread counters are summed after the pass; integers, so the
// order does not matter. Each probe's result depends on the probe alone.
template <class Body>
void run_pass(std::size_t count, unsigned threads, const char* name, const BakeOptions& options, Body&& body,
              EffectCost& cost) {
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();  // process CPU time: this pass's threads only
  std::atomic<std::size_t> next{0}, done{0};
  std::vector<Counters> per_thread(threads);
  Clock::time_point last = start;
  const auto run_chunks = [&](unsigned t) {
    for (;;) {
      const std::size_t begin = next.fetch_add(kChunk);
      if (begin >= count) return;
      const std::size_t end = std::min(count, begin + kChunk);
      for (std::size_t k = begin; k < end; ++k) body(k, per_thread[t]);
      done.fetch_add(end - begin);
      if (t == 0 && options.progress) {  // only the calling thread reports
        if (Clock::now() - last > std::chrono::milliseconds(100)) {
          last = Clock::now();
          options.progress(name, done.load(), count);
        }
      }
    }
  };
  std::mutex failure_mutex;
  std::exception_ptr failure;  // the first exception of any thread (bad_alloc), rethrown below
  const auto work = [&](unsigned t) noexcept {
    try {
      run_chunks(t);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next.store(count);  // the others stop at their next chunk
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) {
    try {
      pool.emplace_back(work, t);
    } catch (const std::system_error&) {
      break;  // fewer threads: the same result, later
    }
  }
  work(0);
  for (std::thread& th : pool) th.join();
  if (failure) std::rethrow_exception(failure);
  if (options.progress) options.progress(name, count, count);
  cost.enabled = true;
  cost.time_ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  cost.cpu_ms += 1000.0 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  for (const Counters& c : per_thread) {
    cost.rays += c.rays;
    cost.samples += c.samples;
    cost.analytic += c.analytic;
  }
}

struct Engine {
  const scene::Scene& scene;
  const BakeOptions& options;
  unsigned threads;
  std::vector<ShL2> total;                             // per probe, the parts summed in pass order
  std::vector<std::array<ShL2, kEffectCount>> parts;  // per probe and effect, if kept
  EnvironmentSource environment;
  std::vector<std::array<EffectSampling, kEffectCount>> sampling;  // per probe and effect
  // With a target, every effect first takes kPilotSamples at every probe, only to estimate
  // the probe's whole light (`pilot`), which each effect's target is then measured against:
  // measured against the light of the effects before it alone, an early effect (a room's
  // sky_occlusion, before its emission and bounce) would chase a target of a mean too small.
  static constexpr std::uint64_t kPilotSamples = 64;
  bool piloting = false;
  std::vector<ShL2> pilot;
  std::unique_ptr<Tracer> tracer;
  std::unique_ptr<EmitterSampler> emitters;
  std::vector<Bounds> bounds;
  // Ray offset off a surface point x: epsilon (1 + max|x_k|). Embree works in float (relative
  // rounding 6e-8) and its sphere roots lose more near tangency; 1e-4 clears both.
  static constexpr double epsilon = 1e-4;

  // Surface receivers (surface_points.h): one unit normal per probe position, each gathering
  // light over the hemisphere about it; null for probes, which gather the whole sphere.
  const std::vector<Vec3d>* normals = nullptr;
  std::function<std::string(std::size_t)> receiver_label;  // how messages name receiver k
  std::vector<ShL2> environment_part;  // surfaces: each one's environment over its hemisphere
  // Surface points averaged into one value (a texel's): per receiver, its group; null: each
  // its own. The target is the group mean's: with K points each meeting sqrt(K) times the
  // target against the group's mean light m (the pilot's, pooled by pool_pilot), the mean's
  // error is sqrt(sum e_k^2) / K <= sqrt(K (sqrt(K) t m)^2) / K = t m. Against each point's
  // own light instead, a texel across a shadow's edge would miss it: sqrt(K sum m_k^2) /
  // sum m_k > 1 by Cauchy-Schwarz unless the points' lights are equal.
  const std::vector<std::uint32_t>* groups = nullptr;
  std::vector<double> target_scale;  // per receiver, sqrt(K) of its group; empty: 1
  // Receivers the target does not hold (they take the fixed counts); null: none.
  const std::vector<bool>* untargeted = nullptr;
  // The key of receiver k's streams (sampling.h): its number in the whole bake, so that its
  // numbers do not depend on which slice of the receivers an engine bakes; null: k.
  const std::vector<std::uint64_t>* stream_ids = nullptr;
  std::uint64_t stream_id(std::size_t k) const { return stream_ids ? (*stream_ids)[k] : k; }

  // After the pilot: each grouped receiver's pilot becomes its group's mean, and its target
  // scale sqrt(K). A group's receivers are consecutive (bake_surface_points).
  void pool_pilot() {
    if (!groups) return;
    target_scale.resize(groups->size());
    for (std::size_t a = 0, b = 0; a < groups->size(); a = b) {
      ShL2 sum;
      for (b = a; b < groups->size() && (*groups)[b] == (*groups)[a]; ++b) add_scaled(sum, pilot[b], 1.0);
      const double members = static_cast<double>(b - a);
      for (std::size_t k = a; k < b; ++k) {
        pilot[k] = scaled(sum, 1.0 / members);
        target_scale[k] = std::sqrt(members);
      }
    }
  }

  Engine(const scene::Scene& s, const BakeOptions& o, unsigned t) : scene(s), options(o), threads(t) {}

  bool surfaces() const noexcept { return normals != nullptr; }
  Domain domain(std::size_t k) const noexcept { return surfaces() ? Domain{true, (*normals)[k]} : Domain{}; }

  // Adds one probe's part of one effect to its total (passes run in a fixed order, so every
  // total is summed in the same order) and keeps it if asked.
  void commit(std::size_t probe, Effect e, const ShL2& part) {
    if (piloting) {
      add_scaled(pilot[probe], part, 1.0);
      return;
    }
    add_scaled(total[probe], part, 1.0);
    if (options.keep_effects) parts[probe][static_cast<std::size_t>(e)] = part;
  }
  Vec3d probe_at(std::size_t k) const { return vec(scene.probes[k]); }
  std::uint64_t seed() const { return scene.settings.seed; }

  IoStatus error_at(std::size_t probe, std::size_t light, const Status& st) const {
    const std::string where = receiver_label ? receiver_label(probe) : scene::probe_label(scene, probe);
    if (st.code == Errc::ProbeInsideLight)
      return IoStatus::error(IoErrc::BadDocument, scene.file,
                             where + " is inside " + scene.lights[light].label + " (" + st.what + ")");
    return IoStatus::error(IoErrc::BadDocument, scene.file, scene.lights[light].label + " at " + where + ": " + st.what);
  }

  // direct: every light's closed form. The first failing (probe, light), in probe order.
  IoStatus direct(EffectCost& cost) {
    std::vector<std::pair<Status, std::size_t>> failure(scene.probes.size());
    run_pass(scene.probes.size(), threads, "direct", options, [&](std::size_t k, Counters& n) {
      ShL2 out;
      for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        ShL2 light;
        const Status st = add_light(scene.lights[l], scene.probes[k], light);
        ++n.analytic;
        if (!st.ok() && failure[k].first.ok()) failure[k] = {st, l};
        if (st.ok()) add_scaled(out, surfaces() ? above_horizon(k, l, light, n, true) : light, 1.0);
      }
      commit(k, Effect::Direct, out);
    }, cost);
    for (std::size_t k = 0; k < failure.size(); ++k)
      if (!failure[k].first.ok()) return error_at(k, failure[k].second, failure[k].first);
    return IoStatus::success();
  }

  void add_environment(EffectCost& cost) {
    if (surfaces()) environment_part.assign(scene.probes.size(), ShL2{});
    run_pass(scene.probes.size(), threads, "environment", options, [&](std::size_t k, Counters& n) {
      ++n.analytic;
      if (!surfaces()) {
        commit(k, Effect::Environment, environment.sh());
        return;
      }
      const Estimate est = hemisphere_estimate(k, environment.sh(), guide(), Effect::Environment, 0,
                                               [&](const Vec3d& w) { return environment.radiance(w); }, n);
      record(k, Effect::Environment, est, n);
      environment_part[k] = est.value;
      commit(k, Effect::Environment, est.value);
    }, cost);
  }

  // ---- Surface receivers: the hemisphere about the normal (surface_domain.h) ----

  // The part over receiver k's hemisphere of a distant radiance R (the environment, a
  // hemisphere or ambient light) whose whole-sphere SH is `sh`: M(n) sh exactly for the
  // band-limited part, plus the residual int_{hemisphere} (R - sh) Y by Monte Carlo (uniform
  // over the hemisphere and, with `guide`, by the radiance's brightness, combined by the
  // power heuristic). Zero residual (R band-limited, as a uniform sky) makes it exact.
  struct ResidualState {
    Domain domain;
    const DirectionDistribution& guide;
    const ShL2& sh;
    std::function<Rgb(const Vec3d&)> radiance;
    Counters& n;
    std::array<SobolSet, kBatches> uniform, guided;
    std::array<ShL2, kBatches> sum{};
    void add(int b, const Vec3d& w, double factor) {
      const Rgb l = radiance(w), s = eval_radiance(sh, w);
      add_basis(sum[b], w, {factor * (l[0] - s[0]), factor * (l[1] - s[1]), factor * (l[2] - s[2])});
    }
    void extend(int b, std::uint32_t from, std::uint32_t to) {
      for (std::uint32_t i = from; i < to; ++i) {
        const auto [u1, u2] = uniform[b].point(i);
        const Vec3d w = domain.sample(u1, u2);
        add(b, w, mis_factor(domain.pdf(w), guide.pdf(w)));
        if (guide.empty()) continue;
        const auto [v1, v2] = guided[b].point(i);
        const DirectionSample s = guide.sample(v1, v2);
        if (domain.contains(s.dir)) add(b, s.dir, mis_factor(s.pdf, domain.pdf(s.dir)));
      }
    }
    ShL2 value(int b, std::uint32_t m) const { return scaled(sum[b], 1.0 / m); }
  };
  template <class Radiance>
  Estimate hemisphere_estimate(std::size_t k, const ShL2& sh, const DirectionDistribution& guide_of, Effect e,
                               std::size_t light, Radiance&& radiance, Counters& n) const {
    const Domain d = domain(k);
    const ShL2 exact = hemisphere_part(hemisphere_gram(d.normal), sh);
    ResidualState state{d, guide_of, sh, radiance, n, {}, {}};
    for (int b = 0; b < kBatches; ++b) {
      state.uniform[b] = sobol(e, k, light, b, 0);
      state.guided[b] = sobol(e, k, light, b, 1);
    }
    Estimate est = run_batches(plan(scene.settings.sky_samples, k), exact, state);
    add_scaled(est.value, exact, 1.0);
    return est;
  }

  // The direct pass records a light's horizon estimate; the shadows pass, asking again, only counts its samples.
  void count(std::size_t k, const Estimate& est, Counters& n, bool record_it) {
    if (record_it)
      record(k, Effect::Direct, est, n);
    else
      n.samples += est.samples;
  }

  // Light l's part above receiver k's horizon, its whole-sphere closed form `closed`: all of
  // it, none of it, or (a light across the horizon) the closed form less the part below, by
  // its points (the shadow estimator with the horizon as the only occluder). Distant lights
  // through hemisphere_estimate. Deterministic in (k, l): the shadows pass asks again.
  ShL2 above_horizon(std::size_t k, std::size_t l, const ShL2& closed, Counters& n, bool record_it) {
    const scene::SceneLight& light = scene.lights[l];
    if (is_distant(light)) {
      if (light.type == scene::LightType::Ambient)  // constant: band-limited, M(n) is exact
        return hemisphere_part(hemisphere_gram((*normals)[k]), closed);
      static const DirectionDistribution none;
      const Estimate est = hemisphere_estimate(k, closed, none, Effect::Direct, l,
                                               [&](const Vec3d& w) { return distant_radiance(light, w); }, n);
      count(k, est, n, record_it);
      return est.value;
    }
    switch (horizon_of(light, probe_at(k), (*normals)[k])) {
      case Horizon::Above: return closed;
      case Horizon::Below: return {};
      case Horizon::Straddles: break;
    }
    if (is_delta(light)) return closed;  // only a point light on the plane itself: measure zero
    std::vector<ShadowedLight> one(1);
    one[0].light = l;
    one[0].closed = closed;
    one[0].radiance = light_radiance(light);
    for (int b = 0; b < kBatches; ++b) one[0].points[b] = sobol(Effect::Direct, k, l, b);
    ShadowState state{*this, probe_at(k), domain(k), true, one, n};
    Estimate est = run_batches(plan(scene.settings.shadow_samples, k), closed, state);
    count(k, est, n, record_it);
    add_scaled(est.value, closed, 1.0);
    return est.value;
  }

  // The sample plan of an effect: its fixed count, or the scene's target and cap; in the
  // pilot, kPilotSamples.
  SamplePlan plan(int fixed, std::size_t k) const {
    if (piloting) return {0, kPilotSamples, kPilotSamples, false};
    const double target = untargeted && (*untargeted)[k]
                              ? 0.0
                              : scene.settings.target_error_pct * (target_scale.empty() ? 1.0 : target_scale[k]);
    return {target, static_cast<std::uint64_t>(std::max(1, fixed)),
            static_cast<std::uint64_t>(std::max(1, scene.settings.max_samples))};
  }
  // What a target is measured against: the probe's whole light, as the pilot estimated it.
  const ShL2& denominator(std::size_t probe) const { return pilot.empty() ? total[probe] : pilot[probe]; }
  // The Sobol set of one batch of one (effect, probe, light, strategy): keyed, never shared.
  SobolSet sobol(Effect e, std::size_t probe, std::size_t light, int batch, int strategy = 0) const {
    const std::size_t key = light * 64 + static_cast<std::size_t>(batch) * 2 + static_cast<std::size_t>(strategy);
    return SobolSet(stream(seed(), static_cast<std::uint64_t>(e), stream_id(probe), key).bits());
  }
  void record(std::size_t probe, Effect e, const Estimate& est, Counters& n) {
    n.samples += est.samples;
    if (piloting) return;
    EffectSampling& s = sampling[probe][static_cast<std::size_t>(e)];
    s.samples = std::max(s.samples, est.samples);
    s.capped = s.capped || est.capped;
    s.error = combine_errors(s.error, est.error);
  }
  // The environment's importance sampling, or none without next events (BakeOptions).
  const DirectionDistribution& guide() const {
    static const DirectionDistribution none;
    return options.next_events ? environment.distribution() : none;
  }
  double offset_at(const Vec3d& x) const {
    return epsilon * (1.0 + std::max({std::fabs(x.x), std::fabs(x.y), std::fabs(x.z)}));
  }

  // shadows: the closed form minus what the geometry hides (bake.h). An extended light's
  // batch b estimates the visible part from its points (uniform in solid angle or by area,
  // sobol.h) with the rule's own error on the whole light spread in proportion to the visible
  // weight: all visible gives the closed form and all hidden 0, exactly.
  struct ShadowedLight {
    std::size_t light = 0;
    ShL2 closed;
    Rgb radiance{};
    std::array<SobolSet, kBatches> points{};
    std::array<ShL2, kBatches> visible{}, full{};
    std::array<double, kBatches> w_visible{}, w_total{};
  };
  // With `horizon`, the only occluder is the receiver's tangent plane (above_horizon: no
  // rays); otherwise points below the horizon are not the light's to shadow (its `closed` is
  // already the part above) and the rest are traced.
  struct ShadowState {
    const Engine& engine;
    Vec3d p;
    Domain domain;
    bool horizon;
    std::vector<ShadowedLight>& lights;
    Counters& n;
    bool visible(const LightSample& s) const {
      if (horizon) return domain.contains(s.dir);
      ++n.rays;
      return !engine.tracer->occluded(p, s.dir, 0.0, s.distance * (1.0 - 1e-7));
    }
    void extend(int b, std::uint32_t from, std::uint32_t to) {
      for (ShadowedLight& sl : lights)
        for (std::uint32_t i = from; i < to; ++i) {
          const auto [u1, u2] = sl.points[b].point(i);
          const LightSample s = light_point(engine.scene.lights[sl.light], p, u1, u2);
          if (s.weight == 0 || (!horizon && !domain.contains(s.dir))) continue;
          const Rgb w = {s.weight * sl.radiance[0], s.weight * sl.radiance[1], s.weight * sl.radiance[2]};
          add_basis(sl.full[b], s.dir, w);
          sl.w_total[b] += s.weight;
          if (visible(s)) {
            add_basis(sl.visible[b], s.dir, w);
            sl.w_visible[b] += s.weight;
          }
        }
    }
    ShL2 value(int b, std::uint32_t m) const {
      ShL2 out;
      for (const ShadowedLight& sl : lights) {
        if (sl.w_visible[b] == sl.w_total[b]) continue;
        if (sl.w_visible[b] == 0) {
          add_scaled(out, sl.closed, -1.0);
          continue;
        }
        const double f = sl.w_visible[b] / sl.w_total[b];
        add_scaled(out, sl.visible[b], 1.0 / m);
        add_scaled(out, sl.closed, f - 1.0);
        add_scaled(out, sl.full[b], -f / m);
      }
      return out;
    }
  };
  void shadows(EffectCost& cost) {
    run_pass(scene.probes.size(), threads, "shadows", options, [&](std::size_t k, Counters& n) {
      const Vec3d p = probe_at(k);
      ShL2 out;
      std::vector<ShadowedLight> extended;
      for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const scene::SceneLight& light = scene.lights[l];
        const bool any = std::any_of(bounds.begin(), bounds.end(),
                                     [&](const Bounds& b) { return can_shadow(light, p, b); });
        if (!any) {
          if (!piloting) ++n.analytic;  // no shape can touch the rays: the closed form stands
          continue;
        }
        ShL2 closed;
        if (!add_light(light, scene.probes[k], closed).ok() || closed == ShL2{}) continue;
        if (surfaces()) {  // the part above the horizon is what can be shadowed
          closed = above_horizon(k, l, closed, n, false);
          if (closed == ShL2{}) continue;
        }
        if (is_delta(light)) {  // one ray, exact
          const LightSample s = light_point(light, p, 0, 0);
          ++n.rays;
          ++n.samples;
          if (tracer->occluded(p, s.dir, 0.0, s.distance * (1.0 - 1e-7))) add_scaled(out, closed, -1.0);
          continue;
        }
        ShadowedLight sl;
        sl.light = l;
        sl.closed = closed;
        sl.radiance = light_radiance(light);
        for (int b = 0; b < kBatches; ++b) sl.points[b] = sobol(Effect::Shadows, k, l, b);
        extended.push_back(std::move(sl));
      }
      if (!extended.empty()) {
        ShadowState state{*this, p, domain(k), false, extended, n};
        const Estimate est = run_batches(plan(scene.settings.shadow_samples, k), denominator(k), state);
        add_scaled(out, est.value, 1.0);
        record(k, Effect::Shadows, est, n);
      }
      commit(k, Effect::Shadows, out);
    }, cost);
  }

  // One probe of an effect over directions from two strategies (sky_occlusion, emission): each
  // batch's two point sets, then its samples, recorded and committed.
  template <class State>
  void sample_directions(Effect e, std::size_t k, int fixed, State& state, Counters& n) {
    for (int b = 0; b < kBatches; ++b) {
      state.uniform[b] = sobol(e, k, 0, b, 0);
      state.guided[b] = sobol(e, k, 0, b, 1);
    }
    const Estimate est = run_batches(plan(fixed, k), denominator(k), state);
    record(k, e, est, n);
    commit(k, e, est.value);
  }

  // sky_occlusion: the environment hidden by geometry, removed. Directions come from two
  // strategies, uniform on the sphere and by the environment's brightness, combined by the
  // power heuristic (sampling.h): sample x of strategy s adds f(x) p_s / (m (p_u^2 + p_e^2)).
  // The hidden part H and the whole F are estimated from the same directions, and the rule's
  // error on the whole (env - F) is spread by the hidden share h of their weight: out =
  // -H - h (env - F), so nothing hidden gives 0 and everything hidden -env, exactly.
  struct SkyState {
    const Engine& engine;
    Vec3d p;
    Domain domain;
    const ShL2& env;  // the environment over the domain (a surface's: its environment pass)
    Counters& n;
    std::array<SobolSet, kBatches> uniform, guided;
    std::array<ShL2, kBatches> hidden{}, full{};
    std::array<double, kBatches> w_hidden{}, w_total{};
    void add(int b, const Vec3d& w, double inv_pdf) {
      const Rgb l = engine.environment.radiance(w);
      const Rgb wl = {inv_pdf * l[0], inv_pdf * l[1], inv_pdf * l[2]};
      const double weight = (wl[0] + wl[1] + wl[2]) / 3.0;
      ++n.rays;
      add_basis(full[b], w, wl);
      w_total[b] += weight;
      if (engine.tracer->occluded(p, w, 0.0)) {
        add_basis(hidden[b], w, wl);
        w_hidden[b] += weight;
      }
    }
    void extend(int b, std::uint32_t from, std::uint32_t to) {
      const DirectionDistribution& sky = engine.guide();
      for (std::uint32_t i = from; i < to; ++i) {
        const auto [u1, u2] = uniform[b].point(i);
        const Vec3d w = domain.sample(u1, u2);
        add(b, w, mis_factor(domain.pdf(w), sky.pdf(w)));
        if (sky.empty()) continue;
        const auto [v1, v2] = guided[b].point(i);
        const DirectionSample s = sky.sample(v1, v2);
        if (domain.contains(s.dir)) add(b, s.dir, mis_factor(s.pdf, domain.pdf(s.dir)));
      }
    }
    ShL2 value(int b, std::uint32_t m) const {
      ShL2 out;
      if (w_hidden[b] == 0 || w_total[b] == 0) return out;
      if (w_hidden[b] == w_total[b] && hidden[b] == full[b]) {
        add_scaled(out, env, -1.0);
        return out;
      }
      const double h = w_hidden[b] / w_total[b];
      add_scaled(out, hidden[b], -1.0 / m);
      add_scaled(out, env, -h);
      add_scaled(out, full[b], h / m);
      return out;
    }
  };
  void sky_occlusion(EffectCost& cost) {
    run_pass(scene.probes.size(), threads, "sky_occlusion", options, [&](std::size_t k, Counters& n) {
      SkyState state{*this, probe_at(k), domain(k), surfaces() ? environment_part[k] : environment.sh(), n, {}, {}};
      sample_directions(Effect::SkyOcclusion, k, scene.settings.sky_samples, state, n);
    }, cost);
  }

  // emission: emissive geometry seen from the probe, by uniform directions and by points of
  // the emitters (emitters.h), combined by the power heuristic; an emitter hides the
  // environment behind it unless sky_occlusion has already removed that.
  struct EmissionState {
    const Engine& engine;
    Vec3d p;
    Domain domain;
    Counters& n;
    bool hides_sky;
    std::array<SobolSet, kBatches> uniform, guided;
    std::array<ShL2, kBatches> sum{};
    void add(int b, const Vec3d& w, std::uint32_t shape, double inv_pdf) {
      Rgb value = engine.scene.geometry[shape].emission;
      if (hides_sky) {
        const Rgb sky = engine.environment.radiance(w);
        for (int c = 0; c < 3; ++c) value[c] -= sky[c];
      }
      add_basis(sum[b], w, {inv_pdf * value[0], inv_pdf * value[1], inv_pdf * value[2]});
    }
    void extend(int b, std::uint32_t from, std::uint32_t to) {
      const EmitterSampler& emitters = *engine.emitters;
      for (std::uint32_t i = from; i < to; ++i) {
        const auto [u1, u2] = uniform[b].point(i);
        const Vec3d w = domain.sample(u1, u2);
        ++n.rays;
        const Hit hit = engine.tracer->intersect(p, w, 0.0);
        if (hit.hit && !is_black(engine.scene.geometry[hit.shape].emission))
          add(b, w, hit.shape, mis_factor(domain.pdf(w), emitters.pdf(p, w, hit)));
        if (emitters.empty()) continue;
        const auto [v1, v2] = guided[b].point(i);
        const EmitterSample s = emitters.sample(p, v1, v2);
        if (!(s.pdf > 0) || !domain.contains(s.dir)) continue;
        ++n.rays;
        if (!engine.tracer->occluded(p, s.dir, 0.0, s.distance - engine.offset_at(p + s.distance * s.dir)))
          add(b, s.dir, s.shape, mis_factor(s.pdf, domain.pdf(s.dir)));
      }
    }
    ShL2 value(int b, std::uint32_t m) const { return scaled(sum[b], 1.0 / m); }
  };
  void emission(EffectCost& cost) {
    const bool hides_sky = scene.effects.environment && !scene.effects.sky_occlusion;
    run_pass(scene.probes.size(), threads, "emission", options, [&](std::size_t k, Counters& n) {
      EmissionState state{*this, probe_at(k), domain(k), n, hides_sky, {}, {}};
      sample_directions(Effect::Emission, k, scene.settings.sky_samples, state, n);
    }, cost);
  }

  // The light a surface point x (unit normal n facing the path) sends back along a path of
  // throughput beta (albedo already in it), by next-event estimation: every light (one
  // sample and a shadow ray each), an emitter point and an environment direction, the last
  // two weighed against the cosine-sampled continuation by the power heuristic.
  void next_events(const Vec3d& x, const Vec3d& normal, double eps, const Rgb& beta, PathPoints& points, Rgb& radiance,
                   Counters& n) const {
    const auto add = [&](const Rgb& l, double scale) {
      for (int c = 0; c < 3; ++c) radiance[c] += beta[c] * l[c] * scale;
    };
    if (scene.effects.direct)
      for (const scene::SceneLight& light : scene.lights) {
        const auto [u1, u2] = points.next();
        add(light_irradiance(light, x, normal, eps, *tracer, u1, u2, n.rays), 1.0 / std::numbers::pi);
      }
    if (scene.effects.emission && !emitters->empty()) {
      const auto [u1, u2] = points.next();
      const EmitterSample s = emitters->sample(x, u1, u2);
      const double cos = dot(normal, s.dir);
      if (s.pdf > 0 && cos > 0) {
        ++n.rays;
        if (!tracer->occluded(x, s.dir, eps, s.distance - offset_at(x + s.distance * s.dir)))
          add(scene.geometry[s.shape].emission, cos / std::numbers::pi * mis_factor(s.pdf, cos / std::numbers::pi));
      }
    }
    const DirectionDistribution& sky = guide();
    if (scene.effects.environment && !sky.empty()) {
      const auto [u1, u2] = points.next();
      const DirectionSample s = sky.sample(u1, u2);
      const double cos = dot(normal, s.dir);
      if (cos > 0) {
        ++n.rays;
        if (!tracer->occluded(x, s.dir, eps))
          add(environment.radiance(s.dir), cos / std::numbers::pi * mis_factor(s.pdf, cos / std::numbers::pi));
      }
    }
  }

  // What a path that left x along w (cosine-sampled, p_c = cos / pi) finds: the environment
  // and distant lights where it escapes, emission where it hits (both weighed against next
  // events as above). Returns the hit, to continue from.
  Hit continue_path(const Vec3d& x, const Vec3d& w, double p_c, double eps, const Rgb& beta, Rgb& radiance,
                    Counters& n) const {
    ++n.rays;
    const Hit hit = tracer->intersect(x, w, eps);
    Rgb found{0, 0, 0};
    if (!hit.hit) {
      if (scene.effects.environment) {
        const DirectionDistribution& sky = guide();
        const Rgb l = environment.radiance(w);
        const double weight = mis_weight(p_c, sky.pdf(w));
        for (int c = 0; c < 3; ++c) found[c] += weight * l[c];
      }
      if (scene.effects.direct)
        for (const scene::SceneLight& light : scene.lights)
          if (is_distant(light)) {
            const Rgb d = distant_radiance(light, w);
            for (int c = 0; c < 3; ++c) found[c] += d[c];
          }
    } else if (scene.effects.emission) {
      const Rgb& le = scene.geometry[hit.shape].emission;
      if (!is_black(le)) {
        const double weight = mis_weight(p_c, emitters->pdf(x, w, hit));
        for (int c = 0; c < 3; ++c) found[c] += weight * le[c];
      }
    }
    for (int c = 0; c < 3; ++c) radiance[c] += beta[c] * found[c];
    return hit;
  }

  // One path from the probe along w0: the light reflected 1..depth times.
  Rgb path(const Vec3d& p, const Vec3d& w0, PathPoints& points, Counters& n) const {
    Rgb beta{1, 1, 1}, radiance{0, 0, 0};
    ++n.rays;
    Hit hit = tracer->intersect(p, w0, 0.0);
    Vec3d x = p + hit.t * w0;
    for (int b = 1; b <= scene.effects.bounces && hit.hit; ++b) {
      const Rgb& albedo = scene.geometry[hit.shape].albedo;
      for (int c = 0; c < 3; ++c) beta[c] *= albedo[c];
      if (is_black(beta)) break;
      const Vec3d normal = hit.normal;
      const double eps = offset_at(x);
      next_events(x, normal, eps, beta, points, radiance, n);
      // Continue: cosine-weighted, so the estimator of (albedo / pi) int L cos is albedo L.
      const auto [u1, u2] = points.next();
      const Vec3d w = cosine_direction(normal, u1, u2);
      hit = continue_path(x, w, std::fmax(0.0, dot(normal, w)) / std::numbers::pi, eps, beta, radiance, n);
      x = x + hit.t * w;
    }
    return radiance;
  }

  // bounce:N: light reflected 1..N times by the geometry's diffuse albedo (bake.h); the first
  // directions are uniform on the sphere and every later pair of numbers a padding pair (sobol.h).
  struct BounceState {
    const Engine& engine;
    Vec3d p;
    Domain domain;
    Counters& n;
    std::array<SobolSet, kBatches> first;
    std::array<std::uint64_t, kBatches> padding{};  // keys of each batch's PathPoints
    std::array<ShL2, kBatches> sum{};
    void extend(int b, std::uint32_t from, std::uint32_t to) {
      for (std::uint32_t i = from; i < to; ++i) {
        const auto [u1, u2] = first[b].point(i);
        const Vec3d w0 = domain.sample(u1, u2);
        const double pdf = domain.pdf(w0);
        if (!(pdf > 0)) continue;
        PathPoints points(padding[b], i);
        const Rgb l = engine.path(p, w0, points, n);
        add_basis(sum[b], w0, {l[0] / pdf, l[1] / pdf, l[2] / pdf});
      }
    }
    ShL2 value(int b, std::uint32_t m) const { return scaled(sum[b], 1.0 / m); }
  };
  void bounce(EffectCost& cost) {
    run_pass(scene.probes.size(), threads, "bounce", options, [&](std::size_t k, Counters& n) {
      BounceState state{*this, probe_at(k), domain(k), n, {}};
      for (int b = 0; b < kBatches; ++b) {
        state.first[b] = sobol(Effect::Bounce, k, 0, b);
        const std::size_t key = 1000 + static_cast<std::size_t>(b);  // apart from sobol()'s keys
        state.padding[b] = stream(seed(), static_cast<std::uint64_t>(Effect::Bounce), stream_id(k), key).bits();
      }
      const Estimate est = run_batches(plan(scene.settings.bounce_samples, k), denominator(k), state);
      record(k, Effect::Bounce, est, n);
      commit(k, Effect::Bounce, est.value);
    }, cost);
  }

  IoStatus build_tracer(GeometryCost& cost) {
    const auto start = Clock::now();
    tracer = std::make_unique<Tracer>(scene.geometry);
    if (!tracer->ok()) return IoStatus::error(IoErrc::Core, scene.file, tracer->error());
    static const std::vector<scene::SceneShape> no_emitters;
    emitters = std::make_unique<EmitterSampler>(options.next_events ? scene.geometry : no_emitters);
    for (const scene::SceneShape& shape : scene.geometry) {
      bounds.push_back(shape_bounds(shape));
      if (shape.type == scene::ShapeType::Sphere)
        ++cost.spheres;
      else
        cost.triangles += shape.indices.size() / 3;
    }
    cost.built = true;
    cost.time_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return IoStatus::success();
  }
};

// Each probe's error estimate in % of its own mean E/pi, per effect and all effects together
// (independent: combined in quadrature, error_estimate.h).
void measure_errors(BakeResult& result) {
  result.error_estimate_pct.assign(result.radiance.size(), 0.0);
  for (std::size_t k = 0; k < result.radiance.size(); ++k) {
    ChannelError all{};
    for (EffectSampling& s : result.sampling[k]) {
      s.error_pct = error_pct(s.error, result.radiance[k]);
      all = combine_errors(all, s.error);
    }
    result.error_estimate_pct[k] = error_pct(all, result.radiance[k]);
  }
}

}  // namespace

void add_cost(EffectCost& into, const EffectCost& from) noexcept {
  into.enabled = into.enabled || from.enabled;
  into.time_ms += from.time_ms;
  into.cpu_ms += from.cpu_ms;
  into.rays += from.rays;
  into.samples += from.samples;
  into.analytic += from.analytic;
}

const char* effect_name(Effect effect) noexcept {
  switch (effect) {
    case Effect::Direct: return "direct";
    case Effect::Environment: return "environment";
    case Effect::Shadows: return "shadows";
    case Effect::SkyOcclusion: return "sky_occlusion";
    case Effect::Emission: return "emission";
    case Effect::Bounce: return "bounce";
  }
  return "unknown";
}

namespace {

// The effects' passes over an engine's receivers, in bake.h's order, into `result` (radiance,
// sampling, effects, costs; the tracer's cost when it builds one).
IoStatus run_effects(Engine& engine, BakeResult& result) {
  const scene::Scene& scene = engine.scene;
  const std::size_t count = scene.probes.size();
  engine.total.assign(count, ShL2{});
  engine.sampling.assign(count, {});
  if (engine.options.keep_effects) engine.parts.assign(count, {});
  auto& costs = result.costs;
  const auto cost = [&](Effect e) -> EffectCost& { return costs[static_cast<std::size_t>(e)]; };
  const scene::SceneEffects& fx = scene.effects;
  if (fx.direct)
    if (IoStatus st = engine.direct(cost(Effect::Direct)); !st.ok()) return st;
  if (fx.environment) {
    const auto start = Clock::now();
    // Surfaces look the environment up for the part of their hemisphere the SH misses.
    const bool lookup = fx.sky_occlusion || fx.bounces > 0 || fx.emission || engine.surfaces();
    if (IoStatus st = engine.environment.load(scene, lookup, engine.threads); !st.ok()) return st;
    cost(Effect::Environment).time_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    engine.add_environment(cost(Effect::Environment));
  }
  const bool traces = fx.shadows || fx.sky_occlusion || fx.emission || fx.bounces > 0;
  if (traces && !scene.geometry.empty()) {
    if (!engine.tracer)  // built before for validity
      if (IoStatus st = engine.build_tracer(result.geometry); !st.ok()) return st;
    const auto sample_effects = [&] {
      if (fx.shadows) engine.shadows(cost(Effect::Shadows));
      if (fx.sky_occlusion) engine.sky_occlusion(cost(Effect::SkyOcclusion));
      if (fx.emission) engine.emission(cost(Effect::Emission));
      if (fx.bounces > 0) engine.bounce(cost(Effect::Bounce));
    };
    if (scene.settings.target_error_pct > 0) {  // the pilot (Engine::kPilotSamples)
      engine.pilot = engine.total;
      engine.piloting = true;
      sample_effects();
      engine.piloting = false;
      engine.pool_pilot();
    }
    sample_effects();
  } else {
    // No geometry: nothing to hide, emit or reflect; the effects cost nothing.
    cost(Effect::Shadows).enabled = fx.shadows;
    cost(Effect::SkyOcclusion).enabled = fx.sky_occlusion;
    cost(Effect::Emission).enabled = fx.emission;
    cost(Effect::Bounce).enabled = fx.bounces > 0;
  }
  result.radiance = std::move(engine.total);
  result.sampling = std::move(engine.sampling);
  result.effects = std::move(engine.parts);
  return IoStatus::success();
}

unsigned thread_count(const BakeOptions& options) {
  return options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace

IoStatus bake_probe_range(const scene::Scene& scene, const BakeOptions& options, std::size_t first, std::size_t count,
                          BakeResult& out) {
  try {
    const unsigned threads = thread_count(options);
    BakeResult result;
    // A slice is baked as a scene of its probes alone, each keyed and named by its number in
    // the whole scene.
    const bool whole = first == 0 && count == scene.probes.size();
    std::optional<scene::Scene> slice;
    std::vector<std::uint64_t> ids(count);
    for (std::size_t k = 0; k < count; ++k) ids[k] = first + k;
    if (!whole) {
      slice.emplace(scene);
      slice->probes.assign(scene.probes.begin() + static_cast<std::ptrdiff_t>(first),
                           scene.probes.begin() + static_cast<std::ptrdiff_t>(first + count));
    }
    const scene::Scene& probes = slice ? *slice : scene;
    const auto label = [&](std::size_t k) { return scene::probe_label(scene, first + k); };
    // Probe validity (probe_validity.h) first: it needs the ray tracer whenever the scene has
    // geometry, even if no effect traces rays, and "offset" moves probes before any pass (the
    // passes then bake a copy of the scene holding the moved probes, with its own tracer).
    Engine first_engine(probes, options, threads);
    first_engine.stream_ids = &ids;
    first_engine.receiver_label = label;
    result.validity.assign(count, ProbeValidity{});
    if (!probes.geometry.empty()) {
      if (IoStatus st = first_engine.build_tracer(result.geometry); !st.ok()) return st;
      run_pass(count, threads, "validity", options, [&](std::size_t k, Counters& n) {
        result.validity[k] = check_probe(*first_engine.tracer, probes, k, ids[k], n.rays);
        ++n.samples;
      }, result.validity_cost);
    }
    if (IoStatus st = check_invalid_probes(scene, result.validity, first, whole); !st.ok()) return st;
    const std::optional<scene::Scene> moved = offset_scene(probes, result.validity);
    std::optional<Engine> second;
    if (moved) {
      first_engine.tracer.reset();
      second.emplace(*moved, options, threads);
      second->stream_ids = &ids;
      second->receiver_label = label;
      result.geometry = {};
      if (IoStatus st = second->build_tracer(result.geometry); !st.ok()) return st;
    }
    if (IoStatus st = run_effects(second ? *second : first_engine, result); !st.ok()) return st;
    out = std::move(result);
    return IoStatus::success();
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Core, scene.file, std::string("bake failed: ") + e.what());
  }
}

IoStatus finish_probes(const scene::Scene& scene, BakeResult& result) {
  if (IoStatus st = check_invalid_probes(scene, result.validity, 0, true); !st.ok()) return st;
  dilate_invalid_probes(scene, result.validity, result.radiance, result.effects, result.sampling);
  measure_errors(result);
  result.validity_counts = count_validity(result.validity);
  return IoStatus::success();
}

IoStatus bake(const scene::Scene& scene, const BakeOptions& options, BakeResult& out) {
  BakeResult result;
  if (IoStatus st = bake_probe_range(scene, options, 0, scene.probes.size(), result); !st.ok()) return st;
  if (IoStatus st = finish_probes(scene, result); !st.ok()) return st;
  out = std::move(result);
  return IoStatus::success();
}

IoStatus surface_validity(const scene::Scene& points, const std::vector<std::uint64_t>& stream_ids,
                          const BakeOptions& options, std::vector<ProbeValidity>& out, EffectCost& cost,
                          GeometryCost& geometry) {
  try {
    out.assign(points.probes.size(), ProbeValidity{});
    if (points.geometry.empty()) return IoStatus::success();
    Engine engine(points, options, thread_count(options));
    if (IoStatus st = engine.build_tracer(geometry); !st.ok()) return st;
    run_pass(points.probes.size(), engine.threads, "validity", options, [&](std::size_t k, Counters& n) {
      out[k] = check_probe(*engine.tracer, points, k, stream_ids[k], n.rays);
      ++n.samples;
    }, cost);
    return IoStatus::success();
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Core, points.file, std::string("bake failed: ") + e.what());
  }
}

IoStatus bake_surface_points(const scene::Scene& points, const SurfacePoints& surface, const BakeOptions& options,
                             BakeResult& out) {
  try {
    BakeResult result;
    Engine engine(points, options, thread_count(options));
    engine.normals = &surface.normals;
    engine.groups = &surface.group;
    engine.untargeted = &surface.untargeted;
    engine.stream_ids = &surface.stream_ids;
    const auto& label = surface.label;
    engine.receiver_label = label;
    if (IoStatus st = run_effects(engine, result); !st.ok()) return st;
    result.validity.assign(points.probes.size(), ProbeValidity{});
    measure_errors(result);
    out = std::move(result);
    return IoStatus::success();
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Core, points.file, std::string("bake failed: ") + e.what());
  }
}

}  // namespace shpack::bake
