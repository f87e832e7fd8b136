#include "shpack/light_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <numbers>
#include <utility>

#include "common/angles.h"
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

// The rows of one direction i of a channel's linear program (light_fit.h), columns
// x_0..x_{K-1}, u: H_i x + u <= b_i + T0, -H_i x + u <= T0 - b_i, G_i x <= max(S_i, 0).
void add_direction_rows(const LightColumns& columns, std::size_t i, double b, double sh, double t0,
                        LinearProgram& lp) {
  const std::size_t lights = columns.lights, cols = lights + 1;
  const std::size_t first = lp.rows;
  lp.rows += 3;
  lp.a.resize(lp.rows * cols, 0.0);
  double* above = &lp.a[first * cols];
  double* below = above + cols;
  double* nonnegative = below + cols;
  for (std::size_t k = 0; k < lights; ++k) {
    above[k] = columns.h[i * lights + k];
    below[k] = -columns.h[i * lights + k];
    nonnegative[k] = columns.g[i * lights + k];
  }
  above[lights] = below[lights] = 1.0;
  lp.b.insert(lp.b.end(), {b + t0, t0 - b, std::max(sh, 0.0)});
}

// One channel's side of the fit: b_i = T(n_i) - S(n_i) and S(n_i), over the channel's mean.
struct ChannelRows {
  const LightColumns& columns;
  const std::vector<double>& truth;
  const std::vector<double>& sh;
  std::size_t count() const noexcept { return truth.size(); }
  double b(std::size_t i) const noexcept { return truth[i] - sh[i]; }
  // |H_i x - b_i|, and how far x breaks direction i's rows at the error bound t: its
  // residual's excess over t, or its SH's dip below 0 where the map's own is not.
  std::array<double, 2> residual_and_break(std::size_t i, const std::vector<double>& x, double t) const noexcept {
    double hx = 0, gx = 0;
    for (std::size_t k = 0; k < columns.lights; ++k) {
      hx += columns.h[i * columns.lights + k] * x[k];
      gx += columns.g[i * columns.lights + k] * x[k];
    }
    const double residual = std::abs(hx - b(i));
    return {residual, std::max(residual - t, gx - std::max(sh[i], 0.0))};
  }
};

// The working set's first directions: the kLightFitFirstRows of largest |b_i| (those that bind
// at x = 0, ties by index), and those that bound the channel's last fit.
std::vector<std::size_t> first_directions(const ChannelRows& rows, const std::vector<std::size_t>& binding) {
  std::vector<std::size_t> order(rows.count());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  const std::size_t first = std::min(order.size(), kLightFitFirstRows);
  std::partial_sort(order.begin(), order.begin() + first, order.end(), [&](std::size_t a, std::size_t b) {
    const double ea = std::abs(rows.b(a)), eb = std::abs(rows.b(b));
    return ea != eb ? ea > eb : a < b;
  });
  order.resize(first);
  for (std::size_t i : binding)
    if (i < rows.count() && std::find(order.begin(), order.end(), i) == order.end()) order.push_back(i);
  return order;
}

// The kLightFitRowsPerRound directions out of the working set that x breaks most (by more than
// kLightFitRowTolerance; ties by index); `fitted` is set to the largest residual over all.
std::vector<std::size_t> most_broken(const ChannelRows& rows, const std::vector<bool>& working,
                                     const std::vector<double>& x, double t, double& fitted) {
  std::vector<std::pair<double, std::size_t>> broken;  // by how much, which
  fitted = 0;
  for (std::size_t i = 0; i < rows.count(); ++i) {
    const std::array<double, 2> r = rows.residual_and_break(i, x, t);
    fitted = std::max(fitted, r[0]);
    if (!working[i] && r[1] > kLightFitRowTolerance) broken.push_back({r[1], i});
  }
  const std::size_t take = std::min(broken.size(), kLightFitRowsPerRound);
  std::partial_sort(broken.begin(), broken.begin() + take, broken.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  std::vector<std::size_t> out(take);
  for (std::size_t k = 0; k < take; ++k) out[k] = broken[k].second;
  return out;
}

// One channel's linear program (light_fit.h), in units of the channel's mean, solved on a
// working set of directions [the cutting-plane method for many constraints: Chvatal, "Linear
// Programming", ch. 16]: first_directions, then, round by round, the most_broken ones, until
// the working set's optimum breaks no row. Each working set's program has fewer rows than the
// whole, so its optimum u is at least the whole's; one that keeps every row is then the
// whole's optimum (up to kLightFitRowTolerance). Returns the fitted max error, the largest
// |H_i x - b_i| over every direction, sets x, and leaves in `binding` the working directions
// whose residual is within kLightFitBindingTolerance of the optimum's bound. Each working set's
// error is a lower bound of the whole's, so once one reaches `stop` the fit ends there and
// returns it, `binding` left as it was: the caller only needed to know it is not below `stop`.
double fit_channel(const ChannelRows& rows, std::vector<std::size_t>& binding, double stop, std::vector<double>& x) {
  const std::size_t lights = rows.columns.lights, cols = lights + 1;
  double t0 = 0;
  for (std::size_t i = 0; i < rows.count(); ++i) t0 = std::max(t0, std::abs(rows.b(i)));
  x.assign(lights, 0.0);
  if (t0 == 0 || lights == 0) return t0;
  std::vector<bool> working(rows.count(), false);
  LinearProgram lp;
  lp.cols = cols;
  lp.c.assign(cols, 0.0);
  lp.c[lights] = 1.0;  // maximise u
  for (std::vector<std::size_t> added = first_directions(rows, binding);;) {
    for (std::size_t i : added) working[i] = true, add_direction_rows(rows.columns, i, rows.b(i), rows.sh[i], t0, lp);
    // Every vertex the simplex method visits is feasible, so even a solution it stopped early
    // (PivotLimit) is a valid fit of the working set; unbounded cannot happen (u <= t0).
    const LpSolution solution = maximize(lp);
    std::copy_n(solution.x.begin(), lights, x.begin());
    const double t = t0 - solution.x[lights];
    if (t >= stop) return t;
    double fitted = 0;
    added = most_broken(rows, working, x, t, fitted);
    if (!added.empty()) continue;
    binding.clear();
    for (std::size_t i = 0; i < rows.count(); ++i)
      if (working[i] && std::abs(rows.residual_and_break(i, x, t)[0] - t) <= kLightFitBindingTolerance)
        binding.push_back(i);
    return fitted;
  }
}


// The fit at unit directions `unit`; once a channel's error is known to reach stop_pct
// (fit_channel) the fit ends, with that channel's max_pct a lower bound at or above stop_pct
// and the others' unset. The channels go worst first by the last complete fit (the one most
// likely to reach stop_pct; a complete fit does not depend on the order).
LightFit fit_unit(const LightFitProblem& problem, std::span<const Dir3> unit,
                  double stop_pct = std::numeric_limits<double>::infinity()) {
  const LightColumns columns = light_columns(*problem.samples, unit, problem.band_factors);
  LightFit out;
  out.irradiance.assign(unit.size(), {});
  std::array<int, kChannelCount> order = {0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return problem.last_pct[a] > problem.last_pct[b]; });
  std::vector<double> x;
  for (int c : order) {
    if (problem.truth[c].empty()) continue;  // a channel whose mean is not positive: no light
    const ChannelRows rows{columns, problem.truth[c], problem.sh[c]};
    out.max_pct[c] = 100.0 * fit_channel(rows, problem.binding[c], stop_pct / 100, x);
    if (out.max_pct[c] >= stop_pct) return out;
    for (std::size_t k = 0; k < unit.size(); ++k)
      out.irradiance[k][c] = std::numbers::pi * problem.samples->mean[c] * x[k];
  }
  problem.last_pct = out.max_pct;
  return out;
}

// Above the rounding of a working set's optimum against the whole's (a few ulps of errors of a
// few percent), so that a stopped fit is one the whole fit would not have taken either.
constexpr double kPruneMarginPct = 1e-9;

double worst_channel(const LightFit& fit) noexcept { return std::max({fit.max_pct[0], fit.max_pct[1], fit.max_pct[2]}); }

// v / |v| (callers check that |v| is finite and non-zero).
Dir3 unit_along(Vec3 v) noexcept {
  const double length = std::sqrt(dot(v, v));
  return {v.x / length, v.y / length, v.z / length};
}

// The unit directions along `directions`; false for one that is zero or not finite.
bool unit_directions(std::span<const Dir3> directions, std::vector<Dir3>& unit) {
  unit.clear();
  for (const Dir3& d : directions) {
    const double length = std::sqrt(dot(to_vec3(d), to_vec3(d)));
    if (!std::isfinite(length) || length == 0) return false;
    unit.push_back(unit_along(to_vec3(d)));
  }
  return true;
}

// d turned by `step` radians towards the tangent e (unit, perpendicular to d).
Dir3 turned(Vec3 d, Vec3 e, double step) noexcept { return unit_along(std::cos(step) * d + std::sin(step) * e); }

// The four compass moves of d: +-e1, +-e2 for an orthonormal tangent frame (e1, e2) of d.
std::array<Dir3, 4> compass(const Dir3& direction, double step) noexcept {
  const Vec3 d = to_vec3(direction);
  const Vec3 axis = std::abs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};  // never along d
  const Vec3 e1 = to_vec3(unit_along(cross(d, axis)));
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
      // A fit known not to come below `best` is stopped there (fit_unit): the same moves are
      // taken, most trials cost a working set or two.
      const double error = worst_channel(fit_unit(problem, trial, best + kPruneMarginPct));
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
  const Vec3 u = to_vec3(a), v = to_vec3(b), c = cross(u, v);
  return std::atan2(std::sqrt(dot(c, c)), dot(u, v)) * (180.0 / std::numbers::pi);
}

Status prepare_light_fit(const ViewSamples& samples, const ShL2& projected, const std::array<double, 3>& band_factors,
                         LightFitProblem& out) noexcept {
  try {
    LightFitProblem problem{&samples, band_factors, {}, {}, {}, {}};
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
      const double step = step_deg * kDegree;
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
