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

#include "environment.h"
#include "sampling.h"
#include "scene_lights.h"
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
  std::unique_ptr<Tracer> tracer;
  std::vector<Bounds> bounds;
  // Ray offset off a surface point x: epsilon (1 + max|x_k|). Embree works in float (relative
  // rounding 6e-8) and its sphere roots lose more near tangency; 1e-4 clears both.
  static constexpr double epsilon = 1e-4;

  Engine(const scene::Scene& s, const BakeOptions& o, unsigned t) : scene(s), options(o), threads(t) {}

  // Adds one probe's part of one effect to its total (passes run in a fixed order, so every
  // total is summed in the same order) and keeps it if asked.
  void commit(std::size_t probe, Effect e, const ShL2& part) {
    add_scaled(total[probe], part, 1.0);
    if (options.keep_effects) parts[probe][static_cast<std::size_t>(e)] = part;
  }
  Vec3d probe_at(std::size_t k) const { return vec(scene.probes[k]); }
  std::uint64_t seed() const { return scene.settings.seed; }

  IoStatus error_at(std::size_t probe, std::size_t light, const Status& st) const {
    const std::string where = scene::probe_label(scene, probe);
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
        const Status st = add_light(scene.lights[l], scene.probes[k], out);
        ++n.analytic;
        if (!st.ok() && failure[k].first.ok()) failure[k] = {st, l};
      }
      commit(k, Effect::Direct, out);
    }, cost);
    for (std::size_t k = 0; k < failure.size(); ++k)
      if (!failure[k].first.ok()) return error_at(k, failure[k].second, failure[k].first);
    return IoStatus::success();
  }

  void add_environment(EffectCost& cost) {
    run_pass(scene.probes.size(), threads, "environment", options, [&](std::size_t k, Counters& n) {
      commit(k, Effect::Environment, environment.sh());
      ++n.analytic;
    }, cost);
  }

  // shadows: the closed form minus what the geometry hides (bake.h).
  void shadows(EffectCost& cost) {
    run_pass(scene.probes.size(), threads, "shadows", options, [&](std::size_t k, Counters& n) {
      const Vec3d p = probe_at(k);
      ShL2 out;
      LightSamples ls;
      for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const scene::SceneLight& light = scene.lights[l];
        const bool any = std::any_of(bounds.begin(), bounds.end(),
                                     [&](const Bounds& b) { return can_shadow(light, p, b); });
        if (!any) {
          ++n.analytic;  // no shape can touch the rays: the closed form stands
          continue;
        }
        ShL2 closed;
        if (!add_light(light, scene.probes[k], closed).ok() || closed == ShL2{}) continue;
        Rng rng = stream(seed(), static_cast<std::uint64_t>(Effect::Shadows), k, l);
        sample_light(light, p, scene.settings.shadow_samples, rng, ls);
        if (ls.samples.size() == 1 && ls.samples.front().weight == 0) {  // a delta light
          const LightSample& s = ls.samples.front();
          ++n.rays;
          ++n.samples;
          if (tracer->occluded(p, s.dir, 0.0, s.distance * (1.0 - 1e-7))) add_scaled(out, closed, -1.0);
          continue;
        }
        // Extended light: visible part by the light's rule, with the rule's own error on the
        // whole light (closed - full) spread in proportion to the visible weight, so that all
        // visible gives the closed form and all hidden gives 0, exactly.
        ShL2 visible, full;
        double w_visible = 0, w_total = 0;
        for (const LightSample& s : ls.samples) {
          if (s.weight == 0) continue;
          ++n.rays;
          ++n.samples;
          const bool hidden = tracer->occluded(p, s.dir, 0.0, s.distance * (1.0 - 1e-7));
          const Rgb w = {s.weight * ls.radiance[0], s.weight * ls.radiance[1], s.weight * ls.radiance[2]};
          add_basis(full, s.dir, w);
          w_total += s.weight;
          if (!hidden) {
            add_basis(visible, s.dir, w);
            w_visible += s.weight;
          }
        }
        if (w_visible == w_total) continue;
        if (w_visible == 0) {
          add_scaled(out, closed, -1.0);
          continue;
        }
        add_scaled(out, visible, 1.0);
        add_scaled(out, closed, w_visible / w_total - 1.0);
        add_scaled(out, full, -w_visible / w_total);
      }
      commit(k, Effect::Shadows, out);
    }, cost);
  }

  // sky_occlusion: the environment's radiance in the directions that hit geometry, removed
  // (with the same exact ends as shadows: nothing hidden gives 0, everything hidden -env).
  void sky_occlusion(EffectCost& cost) {
    const SphereStrata strata(scene.settings.sky_samples);
    run_pass(scene.probes.size(), threads, "sky_occlusion", options, [&](std::size_t k, Counters& n) {
      const Vec3d p = probe_at(k);
      Rng rng = stream(seed(), static_cast<std::uint64_t>(Effect::SkyOcclusion), k, 0);
      ShL2 hidden, full;
      int hidden_count = 0;
      for (int j = 0; j < strata.count(); ++j) {
        const Vec3d w = strata.direction(j, rng);
        const Rgb l = environment.radiance(w);
        const Rgb wl = {strata.weight() * l[0], strata.weight() * l[1], strata.weight() * l[2]};
        ++n.rays;
        ++n.samples;
        add_basis(full, w, wl);
        if (tracer->occluded(p, w, 0.0)) {
          add_basis(hidden, w, wl);
          ++hidden_count;
        }
      }
      ShL2 out;
      if (hidden_count == strata.count()) {
        add_scaled(out, environment.sh(), -1.0);
      } else if (hidden_count > 0) {
        const double fraction = static_cast<double>(hidden_count) / strata.count();
        add_scaled(out, hidden, -1.0);
        add_scaled(out, environment.sh(), -fraction);
        add_scaled(out, full, fraction);
      }
      commit(k, Effect::SkyOcclusion, out);
    }, cost);
  }

  // emission: emissive geometry seen from the probe; it hides the environment behind it
  // unless sky_occlusion has already removed that.
  void emission(EffectCost& cost) {
    const SphereStrata strata(scene.settings.sky_samples);
    const bool hides_sky = scene.effects.environment && !scene.effects.sky_occlusion;
    run_pass(scene.probes.size(), threads, "emission", options, [&](std::size_t k, Counters& n) {
      const Vec3d p = probe_at(k);
      Rng rng = stream(seed(), static_cast<std::uint64_t>(Effect::Emission), k, 0);
      ShL2 out;
      for (int j = 0; j < strata.count(); ++j) {
        const Vec3d w = strata.direction(j, rng);
        ++n.rays;
        ++n.samples;
        const Hit hit = tracer->intersect(p, w, 0.0);
        if (!hit.hit) continue;
        const Rgb& le = scene.geometry[hit.shape].emission;
        if (is_black(le)) continue;
        Rgb value = le;
        if (hides_sky) {
          const Rgb sky = environment.radiance(w);
          for (int c = 0; c < 3; ++c) value[c] -= sky[c];
        }
        add_basis(out, w, {strata.weight() * value[0], strata.weight() * value[1], strata.weight() * value[2]});
      }
      commit(k, Effect::Emission, out);
    }, cost);
  }

  // bounce:N: light reflected 1..N times by the geometry's diffuse albedo (bake.h).
  void bounce(EffectCost& cost) {
    const SphereStrata strata(scene.settings.bounce_samples);
    const int depth = scene.effects.bounces;
    run_pass(scene.probes.size(), threads, "bounce", options, [&](std::size_t k, Counters& n) {
      const Vec3d p = probe_at(k);
      Rng rng = stream(seed(), static_cast<std::uint64_t>(Effect::Bounce), k, 0);
      ShL2 out;
      for (int j = 0; j < strata.count(); ++j) {
        const Vec3d w0 = strata.direction(j, rng);
        ++n.samples;
        ++n.rays;
        Hit hit = tracer->intersect(p, w0, 0.0);
        if (!hit.hit) continue;
        Vec3d x = p + hit.t * w0;
        Rgb beta{1, 1, 1}, radiance{0, 0, 0};
        for (int b = 1; b <= depth; ++b) {
          const Rgb& albedo = scene.geometry[hit.shape].albedo;
          for (int c = 0; c < 3; ++c) beta[c] *= albedo[c];
          if (is_black(beta)) break;
          const Vec3d normal = hit.normal;
          const double eps = epsilon * (1.0 + std::max({std::fabs(x.x), std::fabs(x.y), std::fabs(x.z)}));
          // Next-event estimation: (albedo / pi) E_light(x), albedo already in beta.
          if (scene.effects.direct)
            for (const scene::SceneLight& light : scene.lights) {
              const Rgb e = light_irradiance(light, x, normal, eps, *tracer, rng, n.rays);
              for (int c = 0; c < 3; ++c) radiance[c] += beta[c] * e[c] / std::numbers::pi;
            }
          // Continue: cosine-weighted, so the estimator of (albedo / pi) int L cos is albedo L.
          const Vec3d w = cosine_direction(normal, rng);
          ++n.rays;
          hit = tracer->intersect(x, w, eps);
          if (!hit.hit) {
            Rgb far{0, 0, 0};
            if (scene.effects.environment) far = environment.radiance(w);
            if (scene.effects.direct)
              for (const scene::SceneLight& light : scene.lights)
                if (is_distant(light)) {
                  const Rgb d = distant_radiance(light, w);
                  for (int c = 0; c < 3; ++c) far[c] += d[c];
                }
            for (int c = 0; c < 3; ++c) radiance[c] += beta[c] * far[c];
            break;
          }
          if (scene.effects.emission) {
            const Rgb& le = scene.geometry[hit.shape].emission;
            for (int c = 0; c < 3; ++c) radiance[c] += beta[c] * le[c];
          }
          x = x + hit.t * w;
        }
        const double wt = strata.weight();
        add_basis(out, w0, {wt * radiance[0], wt * radiance[1], wt * radiance[2]});
      }
      commit(k, Effect::Bounce, out);
    }, cost);
  }

  IoStatus build_tracer(GeometryCost& cost) {
    const auto start = Clock::now();
    tracer = std::make_unique<Tracer>(scene.geometry);
    if (!tracer->ok()) return IoStatus::error(IoErrc::Core, scene.file, tracer->error());
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

}  // namespace

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

IoStatus bake(const scene::Scene& scene, const BakeOptions& options, BakeResult& out) {
  try {
    const unsigned threads = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    Engine engine(scene, options, threads);
    engine.total.assign(scene.probes.size(), ShL2{});
    if (options.keep_effects) engine.parts.assign(scene.probes.size(), {});
    BakeResult result;
    auto& costs = result.costs;
    const auto cost = [&](Effect e) -> EffectCost& { return costs[static_cast<std::size_t>(e)]; };
    const scene::SceneEffects& fx = scene.effects;
    if (fx.direct)
      if (IoStatus st = engine.direct(cost(Effect::Direct)); !st.ok()) return st;
    if (fx.environment) {
      const auto start = Clock::now();
      const bool lookup = fx.sky_occlusion || fx.bounces > 0 || fx.emission;
      if (IoStatus st = engine.environment.load(scene, lookup, threads); !st.ok()) return st;
      cost(Effect::Environment).time_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      engine.add_environment(cost(Effect::Environment));
    }
    const bool traces = fx.shadows || fx.sky_occlusion || fx.emission || fx.bounces > 0;
    if (traces && !scene.geometry.empty()) {
      if (IoStatus st = engine.build_tracer(result.geometry); !st.ok()) return st;
      if (fx.shadows) engine.shadows(cost(Effect::Shadows));
      if (fx.sky_occlusion) engine.sky_occlusion(cost(Effect::SkyOcclusion));
      if (fx.emission) engine.emission(cost(Effect::Emission));
      if (fx.bounces > 0) engine.bounce(cost(Effect::Bounce));
    } else {
      // No geometry: nothing to hide, emit or reflect; the effects cost nothing.
      cost(Effect::Shadows).enabled = fx.shadows;
      cost(Effect::SkyOcclusion).enabled = fx.sky_occlusion;
      cost(Effect::Emission).enabled = fx.emission;
      cost(Effect::Bounce).enabled = fx.bounces > 0;
    }
    result.radiance = std::move(engine.total);
    result.effects = std::move(engine.parts);
    out = std::move(result);
    return IoStatus::success();
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Core, scene.file, std::string("bake failed: ") + e.what());
  }
}

}  // namespace shpack::bake
