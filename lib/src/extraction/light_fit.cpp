#include "shpack/light_fit.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>

#include "common/simplex.h"
#include "shpack/convolution.h"
#include "shpack/lights.h"
#include "shpack/vec3.h"

namespace shpack {
namespace {

// g(t) of light_fit.h: the E/pi of the L2 SH of a delta of unit E/pi, band l scaled by f_l.
double delta_sh_value(double t, const std::array<double, 3>& f) noexcept {
  return f[0] * 0.25 + f[1] * 0.5 * t + f[2] * (5.0 / 16.0) * 0.5 * (3.0 * t * t - 1.0);
}

// The columns shared by the three channels: h_k(n_i) and g(n_i . l_k), direction-major.
struct LightColumns {
  std::size_t lights = 0;
  std::vector<double> h, g;  // [i * lights + k]
};

LightColumns light_columns(const ViewSamples& samples, std::span<const Dir3> directions,
                           const std::array<double, 3>& f) {
  LightColumns out{directions.size(), {}, {}};
  out.h.resize(samples.directions.size() * out.lights);
  out.g.resize(out.h.size());
  for (std::size_t i = 0; i < samples.directions.size(); ++i) {
    const Dir3& n = samples.directions[i];
    for (std::size_t k = 0; k < out.lights; ++k) {
      const Dir3& l = directions[k];
      const double t = n.x * l.x + n.y * l.y + n.z * l.z;
      const double g = delta_sh_value(t, f);
      out.h[i * out.lights + k] = std::max(0.0, t) - g;
      out.g[i * out.lights + k] = g;
    }
  }
  return out;
}

// One channel's linear program (light_fit.h), in units of the channel's mean: columns x_0..x_{K-1}, u.
// truth[i] and sh[i] are T(n_i) and S(n_i) over the mean. Returns the fitted max error and sets x.
double fit_channel(const LightColumns& columns, const std::vector<double>& truth, const std::vector<double>& sh,
                   std::vector<double>& x) {
  const std::size_t count = truth.size(), lights = columns.lights, cols = lights + 1;
  double t0 = 0;
  for (std::size_t i = 0; i < count; ++i) t0 = std::max(t0, std::abs(truth[i] - sh[i]));
  x.assign(lights, 0.0);
  if (t0 == 0 || lights == 0) return t0;
  LinearProgram lp;
  lp.rows = 3 * count;
  lp.cols = cols;
  lp.a.assign(lp.rows * cols, 0.0);
  lp.b.resize(lp.rows);
  lp.c.assign(cols, 0.0);
  lp.c[lights] = 1.0;  // maximise u
  for (std::size_t i = 0; i < count; ++i) {
    const double b = truth[i] - sh[i];
    double* above = &lp.a[(3 * i) * cols];
    double* below = above + cols;
    double* nonnegative = below + cols;
    for (std::size_t k = 0; k < lights; ++k) {
      above[k] = columns.h[i * lights + k];
      below[k] = -columns.h[i * lights + k];
      nonnegative[k] = columns.g[i * lights + k];
    }
    above[lights] = below[lights] = 1.0;
    lp.b[3 * i] = b + t0;
    lp.b[3 * i + 1] = t0 - b;
    lp.b[3 * i + 2] = std::max(sh[i], 0.0);
  }
  // Every vertex the simplex method visits is feasible, so even a solution it stopped early
  // (PivotLimit) is a valid fit, no worse than x = 0; unbounded cannot happen (u <= t0).
  const LpSolution solution = maximize(lp);
  std::copy_n(solution.x.begin(), lights, x.begin());
  return t0 - solution.x[lights];
}

// The fit at unit directions `unit`.
LightFit fit_unit(const LightFitProblem& problem, std::span<const Dir3> unit) {
  const LightColumns columns = light_columns(*problem.samples, unit, problem.band_factors);
  LightFit out;
  out.irradiance.assign(unit.size(), {});
  std::vector<double> x;
  for (int c = 0; c < kChannelCount; ++c) {
    if (problem.truth[c].empty()) continue;  // a channel whose mean is not positive: no light
    out.max_pct[c] = 100.0 * fit_channel(columns, problem.truth[c], problem.sh[c], x);
    for (std::size_t k = 0; k < unit.size(); ++k)
      out.irradiance[k][c] = std::numbers::pi * problem.samples->mean[c] * x[k];
  }
  return out;
}

double worst_channel(const LightFit& fit) noexcept { return std::max({fit.max_pct[0], fit.max_pct[1], fit.max_pct[2]}); }

Vec3 vec(const Dir3& d) noexcept { return {d.x, d.y, d.z}; }

// v / |v| (callers check that |v| is finite and non-zero).
Dir3 unit_along(Vec3 v) noexcept {
  const double length = std::sqrt(dot(v, v));
  return {v.x / length, v.y / length, v.z / length};
}

// The unit directions along `directions`; false for one that is zero or not finite.
bool unit_directions(std::span<const Dir3> directions, std::vector<Dir3>& unit) {
  unit.clear();
  for (const Dir3& d : directions) {
    const double length = std::sqrt(dot(vec(d), vec(d)));
    if (!std::isfinite(length) || length == 0) return false;
    unit.push_back(unit_along(vec(d)));
  }
  return true;
}

// d turned by `step` radians towards the tangent e (unit, perpendicular to d).
Dir3 turned(Vec3 d, Vec3 e, double step) noexcept { return unit_along(std::cos(step) * d + std::sin(step) * e); }

// The four compass moves of d: +-e1, +-e2 for an orthonormal tangent frame (e1, e2) of d.
std::array<Dir3, 4> compass(const Dir3& direction, double step) noexcept {
  const Vec3 d = vec(direction);
  const Vec3 axis = std::abs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};  // never along d
  const Vec3 e1 = vec(unit_along(cross(d, axis)));
  const Vec3 e2 = cross(d, e1);
  return {turned(d, e1, step), turned(d, -1.0 * e1, step), turned(d, e2, step), turned(d, -1.0 * e2, step)};
}

// One sweep at one step over every light: the first move that lowers the fitted error is
// taken. True when any was.
bool sweep(const LightFitProblem& problem, std::span<const Dir3> sources, std::span<const double> reach_deg,
           double step, std::vector<Dir3>& directions, double& best) {
  bool moved = false;
  std::vector<Dir3> trial = directions;
  for (std::size_t k = 0; k < directions.size(); ++k) {
    for (const Dir3& move : compass(directions[k], step)) {
      if (angle_deg(move, sources[k]) > reach_deg[k]) continue;
      trial[k] = move;
      const double error = worst_channel(fit_unit(problem, trial));
      if (error < best) {
        best = error, directions[k] = move, moved = true;
        break;
      }
      trial[k] = directions[k];
    }
  }
  return moved;
}

}  // namespace

double angle_deg(const Dir3& a, const Dir3& b) noexcept {
  const Vec3 u = vec(a), v = vec(b), c = cross(u, v);
  return std::atan2(std::sqrt(dot(c, c)), dot(u, v)) * (180.0 / std::numbers::pi);
}

Status prepare_light_fit(const ViewSamples& samples, const ShL2& projected, const std::array<double, 3>& band_factors,
                         LightFitProblem& out) noexcept {
  try {
    LightFitProblem problem{&samples, band_factors, {}, {}};
    ShL2 banded = projected;
    for (auto& channel : banded.c)
      for (int i = 0; i < kShCount; ++i) channel[i] *= band_factors[kBand[i]];
    const ShL2 unity_form = radiance_to_unity_form(banded);
    for (int c = 0; c < kChannelCount; ++c) {
      const double mean = samples.mean[c];
      if (!(mean > 0) || !std::isfinite(mean)) continue;
      for (std::size_t i = 0; i < samples.directions.size(); ++i) {
        const Dir3& n = samples.directions[i];
        problem.truth[c].push_back(samples.values[i].e_over_pi[c] / mean);
        problem.sh[c].push_back(eval_unity_form(unity_form, c, n.x, n.y, n.z) / mean);
      }
    }
    out = std::move(problem);
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory preparing the light fit");
  }
}

Status fit_light_colours(const LightFitProblem& problem, std::span<const Dir3> directions, LightFit& out) noexcept {
  try {
    std::vector<Dir3> unit;
    if (!unit_directions(directions, unit))
      return Status::error(Errc::InvalidArgument, "a light direction is not finite and non-zero");
    out = fit_unit(problem, unit);
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory fitting the light colours");
  }
}

Status refine_light_directions(const LightFitProblem& problem, std::span<const Dir3> sources,
                               std::span<const double> reach_deg, std::vector<Dir3>& directions) noexcept {
  if (sources.size() != directions.size() || reach_deg.size() != directions.size())
    return Status::error(Errc::InvalidArgument, "a light's source or reach is missing");
  try {
    std::vector<Dir3> unit;
    if (!unit_directions(directions, unit))
      return Status::error(Errc::InvalidArgument, "a light direction is not finite and non-zero");
    double best = worst_channel(fit_unit(problem, unit));
    for (double step_deg : kLightRefineStepsDeg) {
      const double step = step_deg * (std::numbers::pi / 180.0);
      for (int k = 0; k < kLightRefineSweeps && sweep(problem, sources, reach_deg, step, unit, best); ++k) {
      }
    }
    directions = std::move(unit);
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory refining the light directions");
  }
}

ShL2 fitted_lights_sh(std::span<const Dir3> directions, const LightFit& fit) noexcept {
  ShL2 out;
  for (std::size_t k = 0; k < directions.size() && k < fit.irradiance.size(); ++k)
    (void)add_directional_light(directions[k], 0.0, fit.irradiance[k], out);
  return out;
}

}  // namespace shpack
