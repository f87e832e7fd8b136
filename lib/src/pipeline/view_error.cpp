// view_error.cpp - what Unity shows against the reference (view_error.h states the measure).
#include "shpack/view_error.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <numbers>
#include <thread>

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

}  // namespace

Dir3 spherical_fibonacci(std::size_t i, std::size_t n) noexcept {
  const double golden = 0.5 * (1 + std::sqrt(5.0));
  const double z = 1 - (2.0 * static_cast<double>(i) + 1) / static_cast<double>(n);
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  const double phi = 2 * std::numbers::pi * std::fmod(static_cast<double>(i) / golden, 1.0);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Status sample_view_reference(const ViewReference& reference, ViewSamples& out, unsigned threads) noexcept {
  if (!reference.finished()) return Status::error(Errc::BadSequence, "the reference E/pi is not finished");
  try {
    ViewSamples s;
    s.directions.resize(kViewErrorDirections);
    s.values.resize(kViewErrorDirections);
    for (std::size_t i = 0; i < kViewErrorDirections; ++i) s.directions[i] = spherical_fibonacci(i, kViewErrorDirections);
    constexpr std::uint32_t kChunk = 32;  // directions per item: 16 items to share
    static_assert(kViewErrorDirections % kChunk == 0);
    const unsigned workers = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
    detail::run_queue(kViewErrorDirections / kChunk, workers, [&](std::uint32_t item, unsigned) noexcept {
      for (std::size_t i = item * kChunk; i < (item + 1) * kChunk; ++i) s.values[i] = reference.eval(s.directions[i]);
    });
    s.mean = reference.mean_e_over_pi();
    out = std::move(s);
    return {};
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory sampling the reference E/pi");
  }
}

ViewError unity_view_error(const ViewSamples& samples, const ViewTransform& finish, const UnityShaderVectors& shown,
                           std::span<const UnitySunLight> lights) noexcept {
  ViewError e;
  const std::size_t n = samples.directions.size();
  if (n == 0) return e;
  std::array<double, 3> mean = to_output(finish, samples.mean, false);
  const double largest = std::max({mean[0], mean[1], mean[2]});
  if (!(largest > 0)) return e;  // a black map: nothing to be wrong about
  for (double& m : mean)
    if (!(m > 0)) m = largest;
  const Matrix3 rotation = rotation_about_y(finish.rotate_deg);
  std::array<double, 3> squares{};
  for (std::size_t i = 0; i < n; ++i) {
    const Dir3 d = times(rotation, samples.directions[i]);
    const std::array<double, 3> truth = to_output(finish, samples.values[i].e_over_pi, false);
    const std::array<double, 3> bound = to_output(finish, samples.values[i].bound, true);
    for (int c = 0; c < 3; ++c) {
      double value = shade_sh9(shown, c, static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z));
      for (const UnitySunLight& l : lights) {
        const Dir3& f = l.forward;
        value += l.colour[c] * l.intensity * std::max(0.0, -(d.x * f.x + d.y * f.y + d.z * f.z));
      }
      const double err = 100 * (value - truth[c]) / mean[c];
      squares[c] += err * err;
      if (std::abs(err) > e.max_pct) {
        e.max_pct = std::abs(err);
        e.max_channel = c;
        e.max_direction = d;
      }
      e.bound_pct = std::max(e.bound_pct, 100 * bound[c] / mean[c]);
    }
  }
  for (int c = 0; c < 3; ++c) e.rms_pct = std::max(e.rms_pct, std::sqrt(squares[c] / static_cast<double>(n)));
  return e;
}

}  // namespace shpack
