// light_fit.h - the colours of directional lights at given directions that bring what Unity
// shows nearest to the exact E/pi of a map: the colours of `--extract-lights` (light_choice.h
// chooses the directions among light_candidates.h's sources).
//
// The model. A light of colour x (colour * intensity = E / pi, unity_light.h) towards l is a
// delta of radiance integral pi x at l; taking it out of the map leaves the SH of the map
// less the delta's, L - pi x Y(l) (lights.h, add_directional_light). For one channel, at a
// normal n, Unity then shows
//   shown(n) = S(n) - sum_k x_k g(n . l_k) + sum_k x_k max(0, n . l_k),
// S the E/pi of the map's L2 SH (with the finish stage's fixed band factors f_l: a band-scaling
// window, or band 2 removed by --l1), and g(t) = f_0/4 + f_1 t/2 + f_2 (5/16) P_2(t) the same
// of a delta of unit E/pi: the clamped cosine's zonal series
//   max(0, t) = 1/4 + t/2 + (5/16) P_2(t) + (bands >= 4),  P_2(t) = (3 t^2 - 1)/2,
// ((2l + 1)/2 int_0^1 t P_l(t) dt for l = 0, 1, 2). So with the truth T(n),
//   shown(n) - T(n) = sum_k x_k h_k(n) - b(n),  h_k(n) = max(0, n . l_k) - g(n . l_k),
//   b(n) = T(n) - S(n):
// linear in x. A light of x = its source's flux (the texels' own light) is one choice; the
// fit takes the best.
//
// The fit, per channel, over the view directions n_i of view_error.h and their reference
// values T(n_i) (ViewSamples), in units of the channel's mean E/pi:
//   minimise  max_i |sum_k x_k h_k(n_i) - b(n_i)|
//   over      x >= 0 (a light adds light)
//   such that S(n_i) - sum_k x_k g(n_i . l_k) >= min(S(n_i), 0)
// (the SH left is non-negative wherever the map's own SH is, so that what the lights take out
// never makes Unity's SH shade with negative light; --window sloan and optimal correct what the
// map's own SH has). It is a linear program in K + 1 unknowns: with T0 = max_i |b(n_i)| and
// t = T0 - u it is max u over x, u >= 0 with
//    H x + u <= b + T0,  -H x + u <= T0 - b,  G x <= max(S, 0),
// every right-hand side >= 0, so x = 0, u = 0 is a vertex to start from (lib/src/common/
// simplex.h solves it: 3 x 512 rows, K + 1 <= 9 columns). x = 0 is feasible, so the fitted
// error is never above the map's own (b's max) at the view directions. Few of the rows bind at
// the optimum (K + 1 of them at a vertex), so it is solved on a working set of directions
// that grows by those the last solution breaks (light_fit.cpp, fit_channel), each program a
// few tens of rows instead of 1536.
//
// The directions. A source's centre (light_candidates.h: the direction of its flux vector) is
// where a delta shows its own light best, but the lights are also what is left to show the
// map's light above L2 (the SH cannot), and a light moved off the centre can show more of it.
// refine_light_directions moves them, each within its reach (light_reach_deg: kLightReachRadii
// times the source's radius plus kLightReachDeg, so that a sun's light stays within a few
// degrees of the sun and a window's on or beside the window), to lower the fitted max error
// (the largest of the channels' max_pct): a compass search [T. G. Kolda, R. M. Lewis,
// V. Torczon, "Optimization by direct search", SIAM Review 45 (2003), sec. 3] over each
// light's two tangent directions, steps of kLightRefineStepsDeg, taking the first move that
// lowers it, until no move at the
// finest step does (or kLightRefineSweeps sweeps over the lights at one step). A trial's fit
// ends as soon as a working set's error, a lower bound of the whole's, shows it cannot lower
// the best (most trials do not), so the same moves are taken for far less. Deterministic:
// the same inputs give the same directions.
//
// The fit sees the view directions only, and the rounding of the packed floats and the
// nonlinear windows (sloan, optimal) not at all: the pipeline measures what it gives with
// view_error.h, as every other choice.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/sh_basis.h"
#include "shpack/status.h"
#include "shpack/view_error.h"

namespace shpack {

struct LightFit {
  // Per light, per channel: E at normal incidence (pi x), in the map's colours, unscaled.
  std::vector<std::array<double, 3>> irradiance;
  // Per channel: the fitted max |shown - truth| at the view directions, % of the channel's
  // mean E/pi (0 for a channel whose mean is not positive: no light is fitted there).
  std::array<double, 3> max_pct{};
};

// The map's side of every fit, made once per map: per channel, T(n_i) and S(n_i) over the
// channel's mean (both empty for a channel whose mean is not positive: no light is fitted
// there). It refers to `samples`, which must outlive it.
// A problem is used by one thread at a time: each fit leaves in `binding` the directions whose
// error rows bind at its optimum, and the next fit of the channel starts its working set from
// them (the lights move little between fits, so the rows that bind do too), and in `last_pct`
// its channels' errors, the order a fit that may stop early tries them in; the optimum does
// not depend on either.
struct LightFitProblem {
  const ViewSamples* samples = nullptr;
  std::array<double, 3> band_factors{};
  std::array<std::vector<double>, kChannelCount> truth, sh;
  mutable std::array<std::vector<std::size_t>, kChannelCount> binding;
  mutable std::array<double, kChannelCount> last_pct{};
};

// The problem of the map whose exact E/pi `samples` holds and whose radiance SH is `projected`
// (the map's frame and colours), the finish stage scaling band l by band_factors[l].
// Errors: OutOfMemory.
Status prepare_light_fit(const ViewSamples& samples, const ShL2& projected, const std::array<double, 3>& band_factors,
                         LightFitProblem& out) noexcept;

// Fits the colours of lights towards `directions` (finite, non-zero, the map's frame).
// Errors: InvalidArgument for a direction that is not finite and non-zero, OutOfMemory.
Status fit_light_colours(const LightFitProblem& problem, std::span<const Dir3> directions, LightFit& out) noexcept;

// The working set's first directions, and how far a row may be broken (in units of the
// channel's mean: 1e-12 of it, far below what the packed floats show) and still count as kept.
inline constexpr std::size_t kLightFitFirstRows = 16;
inline constexpr std::size_t kLightFitRowsPerRound = 8;  // the most broken directions added per round
inline constexpr double kLightFitRowTolerance = 1e-12;
inline constexpr double kLightFitBindingTolerance = 1e-9;  // a row this near the optimum's bound binds

inline constexpr double kLightReachDeg = 2.0;
// Measured on the bundled maps (docs/accuracy.md): with 2 radii the worst map (courtyard)
// keeps 4.9 % of its mean, with 3 radii 3.8 %; the lights of a sun or a lamp hardly move.
inline constexpr double kLightReachRadii = 3.0;
inline constexpr std::array<double, 6> kLightRefineStepsDeg = {8.0, 4.0, 2.0, 1.0, 0.5, 0.25};
inline constexpr int kLightRefineSweeps = 32;

// How far from its source's centre a light may be moved, degrees.
constexpr double light_reach_deg(double source_radius_deg) noexcept {
  return kLightReachRadii * source_radius_deg + kLightReachDeg;
}

// The angle between two unit directions, degrees (atan2 of |a x b| and a . b: accurate at 0).
double angle_deg(const Dir3& a, const Dir3& b) noexcept;

// Moves `directions` (in; unit out), each within reach_deg[k] of sources[k], as above.
// Errors: those of fit_light_colours, InvalidArgument for spans of unequal sizes.
Status refine_light_directions(const LightFitProblem& problem, std::span<const Dir3> sources,
                               std::span<const double> reach_deg, std::vector<Dir3>& directions) noexcept;

// The radiance SH a fit's lights take out of the map: sum_k E_k Y(l_k) (lights.h).
ShL2 fitted_lights_sh(std::span<const Dir3> directions, const LightFit& fit) noexcept;

}  // namespace shpack
