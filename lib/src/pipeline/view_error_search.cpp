// view_error_search.cpp - the max of the view error searched for between the directions
// (view_error.h, "Between the directions").
#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>
#include <vector>

#include "common/angles.h"
#include "pipeline/view_comparison.h"
#include "shpack/vec3.h"
#include "shpack/view_error.h"
#include "shpack/work_queue.h"

namespace shpack {
namespace {

using detail::PointError;
using detail::ViewComparison;

// Moves at one radius, at most: each is a step of r towards a worse point, so a few cross a
// basin at that radius, and the search's cost stays bounded on a slope that goes on.
constexpr int kMovesPerRadius = 4;

struct Evaluated {
  Dir3 direction;  // map frame
  PointError error;
};

// The point of the circle of angular radius r about the unit d at angle a in its tangent frame.
Dir3 on_circle(const Dir3& d, double r, double a) noexcept {
  const Vec3 c = to_vec3(d);
  const Vec3 axis = std::abs(d.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};  // never along d
  Vec3 e1 = cross(c, axis);
  e1 = (1 / std::sqrt(dot(e1, e1))) * e1;
  const Vec3 e2 = cross(c, e1);
  const Vec3 p = std::cos(r) * c + std::sin(r) * (std::cos(a) * e1 + std::sin(a) * e2);
  const double length = std::sqrt(dot(p, p));
  return {p.x / length, p.y / length, p.z / length};
}

Evaluated evaluate(const ViewReference& reference, const ViewComparison& compare, const Dir3& d) noexcept {
  return {d, compare.at(d, reference.eval(d))};
}

// The pattern search of view_error.h from `start`; every point it evaluates is folded into `e`.
void search_from(const ViewReference& reference, const ViewComparison& compare, Evaluated best, ViewError& e) noexcept {
  ViewComparison::fold(best.error, e);
  for (double r = kViewSearchStartDeg; r >= kViewSearchEndDeg; r /= 2) {
    for (int move = 0; move < kMovesPerRadius; ++move) {
      Evaluated worst = best;
      for (int k = 0; k < kViewSearchPoints; ++k) {
        const Evaluated p = evaluate(reference, compare, on_circle(best.direction, r * kDegree,
                                                                   2 * std::numbers::pi * k / kViewSearchPoints));
        ViewComparison::fold(p.error, e);
        if (p.error.worst() > worst.error.worst()) worst = p;
      }
      if (!(worst.error.worst() > best.error.worst())) break;
      best = worst;
    }
  }
}

// The seeds: the worst of `points`, each at least kViewSeedSeparationDeg from those before.
std::vector<Evaluated> seeds_of(std::vector<Evaluated>& points) {
  std::stable_sort(points.begin(), points.end(),
                   [](const Evaluated& a, const Evaluated& b) { return a.error.worst() > b.error.worst(); });
  const double apart = std::cos(kViewSeedSeparationDeg * kDegree);
  std::vector<Evaluated> seeds;
  for (const Evaluated& p : points) {
    if (seeds.size() == kViewSearchSeeds) break;
    const bool near = std::any_of(seeds.begin(), seeds.end(), [&](const Evaluated& s) {
      return dot(to_vec3(s.direction), to_vec3(p.direction)) > apart;
    });
    if (!near) seeds.push_back(p);
  }
  return seeds;
}

// The samples' directions, and the check directions when lights are shown, evaluated.
std::vector<Evaluated> starting_points(const ViewSamples& samples, const ViewComparison& compare, bool check) {
  std::vector<Evaluated> points;
  points.reserve(samples.directions.size() + (check ? kViewCheckDirections : 0));
  for (std::size_t i = 0; i < samples.directions.size(); ++i)
    points.push_back({samples.directions[i], compare.at(samples.directions[i], samples.values[i])});
  if (!check) return points;
  const std::size_t first = points.size();
  points.resize(first + kViewCheckDirections);
  constexpr std::uint32_t kChunk = 64;  // directions per item: 16 items to share
  static_assert(kViewCheckDirections % kChunk == 0);
  detail::run_queue(kViewCheckDirections / kChunk, samples.threads, [&](std::uint32_t item, unsigned) noexcept {
    for (std::size_t j = item * kChunk; j < (item + 1) * kChunk; ++j)
      points[first + j] = evaluate(*samples.reference, compare, spherical_fibonacci(j, kViewCheckDirections));
  });
  return points;
}

}  // namespace

Status searched_view_error(const ViewSamples& samples, const ViewTransform& transform, const UnityShaderVectors& shown,
                           std::span<const UnitySunLight> lights, ViewError& out) noexcept {
  ViewError e = unity_view_error(samples, transform, shown, lights);
  const ViewComparison compare(samples, transform, shown, lights);
  if (!samples.reference || samples.directions.empty() || !compare.active()) return out = e, Status::success();
  try {
    std::vector<Evaluated> points = starting_points(samples, compare, !lights.empty());
    for (const Evaluated& p : points) ViewComparison::fold(p.error, e);
    const std::vector<Evaluated> seeds = seeds_of(points);
    std::vector<ViewError> found(seeds.size(), e);  // each seed its own slot, folded in order
    const auto count = static_cast<std::uint32_t>(seeds.size());
    detail::run_queue(count, samples.threads, [&](std::uint32_t k, unsigned) noexcept {
      search_from(*samples.reference, compare, seeds[k], found[k]);
    });
    for (const ViewError& f : found) {
      const double bound = std::max(e.bound_pct, f.bound_pct);
      if (f.max_pct > e.max_pct) e = f;
      e.bound_pct = bound;
    }
    out = e;
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory searching the view error");
  }
}

}  // namespace shpack
