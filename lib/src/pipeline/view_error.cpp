// view_error.cpp - what Unity shows against the reference at the samples (view_error.h states
// the measure), and the one comparison at a direction it and the search share.
#include "shpack/view_error.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>
#include <thread>

#include "pipeline/view_comparison.h"
#include "shpack/work_queue.h"

namespace shpack {
namespace {

Dir3 times(const Matrix3& r, const Dir3& d) noexcept {
  return {r[0][0] * d.x + r[0][1] * d.y + r[0][2] * d.z, r[1][0] * d.x + r[1][1] * d.y + r[1][2] * d.z,
          r[2][0] * d.x + r[2][1] * d.y + r[2][2] * d.z};
}

// k M v, and k |M| v for bounds (no matrix: the identity).
std::array<double, 3> to_output(const ViewTransform& f, const std::array<double, 3>& v, bool absolute) noexcept {
  std::array<double, 3> out = v;
  if (f.colour_matrix) {
    const Matrix3& m = *f.colour_matrix;
    for (int c = 0; c < 3; ++c) {
      out[c] = 0;
      for (int j = 0; j < 3; ++j) out[c] += (absolute ? std::abs(m[c][j]) : m[c][j]) * v[j];
    }
  }
  for (double& x : out) x *= f.intensity;
  return out;
}

Status sample_into(const ViewReference& reference, ViewSamples& s, unsigned threads) noexcept {
  if (!reference.finished()) return Status::error(Errc::BadSequence, "the reference E/pi is not finished");
  try {
    s.directions.resize(kViewErrorDirections);
    s.values.resize(kViewErrorDirections);
    for (std::size_t i = 0; i < kViewErrorDirections; ++i) s.directions[i] = spherical_fibonacci(i, kViewErrorDirections);
    constexpr std::uint32_t kChunk = 32;  // directions per item: 16 items to share
    static_assert(kViewErrorDirections % kChunk == 0);
    s.threads = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    detail::run_queue(kViewErrorDirections / kChunk, s.threads, [&](std::uint32_t item, unsigned) noexcept {
      for (std::size_t i = item * kChunk; i < (item + 1) * kChunk; ++i) s.values[i] = reference.eval(s.directions[i]);
    });
    s.mean = reference.mean_e_over_pi();
    return {};
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory sampling the reference E/pi");
  }
}

}  // namespace

namespace detail {

double PointError::worst() const noexcept {
  return std::max({std::abs(error[0]), std::abs(error[1]), std::abs(error[2])});
}

ViewComparison::ViewComparison(const ViewSamples& samples, const ViewTransform& finish,
                               const UnityShaderVectors& shown, std::span<const UnitySunLight> lights) noexcept
    : finish_(finish), shown_(shown), lights_(lights), mean_(to_output(finish, samples.mean, false)),
      rotation_(rotation_about_y(finish.rotate_deg)) {
  const double largest = std::max({mean_[0], mean_[1], mean_[2]});
  active_ = largest > 0;
  for (double& m : mean_)
    if (!(m > 0)) m = largest;
}

PointError ViewComparison::at(const Dir3& direction, const ReferenceValue& v) const noexcept {
  PointError p;
  const Dir3 d = times(rotation_, direction);
  p.shown_at = d;
  const std::array<double, 3> truth = to_output(finish_, v.e_over_pi, false);
  const std::array<double, 3> bound = to_output(finish_, v.bound, true);
  for (int c = 0; c < 3; ++c) {
    double value = shade_sh9(shown_, c, static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z));
    for (const UnitySunLight& l : lights_) {
      const Dir3& f = l.forward;
      value += l.colour[c] * l.intensity * std::max(0.0, -(d.x * f.x + d.y * f.y + d.z * f.z));
    }
    p.error[c] = 100 * (value - truth[c]) / mean_[c];
    p.bound = std::max(p.bound, 100 * bound[c] / mean_[c]);
  }
  return p;
}

void ViewComparison::fold(const PointError& p, ViewError& e) noexcept {
  for (int c = 0; c < 3; ++c)
    if (std::abs(p.error[c]) > e.max_pct) {
      e.max_pct = std::abs(p.error[c]);
      e.max_channel = c;
      e.max_direction = p.shown_at;
    }
  e.bound_pct = std::max(e.bound_pct, p.bound);
}

}  // namespace detail

Dir3 spherical_fibonacci(std::size_t i, std::size_t n) noexcept {
  const double golden = 0.5 * (1 + std::sqrt(5.0));
  const double z = 1 - (2.0 * static_cast<double>(i) + 1) / static_cast<double>(n);
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  const double phi = 2 * std::numbers::pi * std::fmod(static_cast<double>(i) / golden, 1.0);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Status sample_view_reference(const ViewReference& reference, ViewSamples& out, unsigned threads) noexcept {
  ViewSamples s;
  if (Status st = sample_into(reference, s, threads); !st.ok()) return st;
  out = std::move(s);
  return {};
}

Status sample_view_reference(ViewReference&& reference, ViewSamples& out, unsigned threads) noexcept {
  ViewSamples s;
  if (Status st = sample_into(reference, s, threads); !st.ok()) return st;
  try {
    s.reference = std::make_shared<const ViewReference>(std::move(reference));
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory keeping the reference E/pi");
  }
  out = std::move(s);
  return {};
}

ViewError unity_view_error(const ViewSamples& samples, const ViewTransform& finish, const UnityShaderVectors& shown,
                           std::span<const UnitySunLight> lights) noexcept {
  ViewError e;
  const std::size_t n = samples.directions.size();
  const detail::ViewComparison compare(samples, finish, shown, lights);
  if (n == 0 || !compare.active()) return e;
  std::array<double, 3> squares{};
  for (std::size_t i = 0; i < n; ++i) {
    const detail::PointError p = compare.at(samples.directions[i], samples.values[i]);
    for (int c = 0; c < 3; ++c) squares[c] += p.error[c] * p.error[c];
    detail::ViewComparison::fold(p, e);
  }
  for (int c = 0; c < 3; ++c) e.rms_pct = std::max(e.rms_pct, std::sqrt(squares[c] / static_cast<double>(n)));
  return e;
}

}  // namespace shpack
