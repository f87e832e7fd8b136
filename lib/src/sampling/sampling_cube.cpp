// cube:N and cube-exact:N - resample the equirect map to six N x N cube faces (each cube
// texel takes the equirect texel its centre direction falls in) and sum the basis at the
// cube texel centres with a per-texel weight:
//
//   cube-exact  the texel's exact solid angle (Filament's cmgen, Babylon.js): Omega(x, y)
//   cube        three.js LightProbeGenerator.fromCubeTexture: the centre-point weight
//               (2/N)^2 / (1 + a^2 + b^2)^1.5, then every weight times 4 pi / sum.
//
// Face texel (x, y) of N x N, row 0 at the top (conventions.h):
//
//      a = -1        a = +1
//   b = -1 +----+----+     a = 2 (x + 0.5)/N - 1,  b = 2 (y + 0.5)/N - 1
//          |    |    |     direction = normalize(normal + a u_axis + b v_axis)
//          +----+----+     corners a0 = 2x/N - 1, a1 = 2(x+1)/N - 1 (b likewise)
//   b = +1 |    |    |
//          +----+----+
//
// The solid angle of the part of the face plane (at distance 1) with corner (0, 0) and
// (a, b) is f(a, b) = atan2(a b, sqrt(a^2 + b^2 + 1)) for a, b >= 0, extended as an odd
// function of each coordinate; a texel is the inclusion-exclusion of its four corners.
// The weights depend on (x, y) only, the same on all six faces; they are computed once per
// face position, never stored.
#include <cmath>
#include <numbers>

#include "common/accumulate.h"
#include "sampling/sampling_estimator.h"
#include "sampling/sampling_projectors.h"

namespace shpack {
namespace {

// a = 2 i / N - 1: a corner (i integer) or a centre (i + 0.5) coordinate in [-1, 1].
double face_coordinate(double i, std::uint32_t n) noexcept { return 2.0 * i / n - 1.0; }

double corner_solid_angle(double a, double b) noexcept {
  return std::atan2(a * b, std::sqrt(a * a + b * b + 1.0));
}

}  // namespace

double cube_texel_solid_angle(std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept {
  const double a0 = face_coordinate(x, n), a1 = face_coordinate(x + 1.0, n);
  const double b0 = face_coordinate(y, n), b1 = face_coordinate(y + 1.0, n);
  return corner_solid_angle(a0, b0) - corner_solid_angle(a0, b1) - corner_solid_angle(a1, b0) +
         corner_solid_angle(a1, b1);
}

double cube_texel_weight_threejs(std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept {
  const double a = face_coordinate(x + 0.5, n), b = face_coordinate(y + 0.5, n);
  const double r2 = 1.0 + a * a + b * b;
  const double side = 2.0 / n;
  return side * side / (r2 * std::sqrt(r2));
}

namespace detail {

Status project_cube(const ImageView& image, std::uint32_t n, bool exact_solid_angle,
                    const ProjectOptions& options, ShL2& radiance, ProjectStats* stats) noexcept {
  const auto weight = [&](std::uint32_t x, std::uint32_t y) noexcept {
    return exact_solid_angle ? cube_texel_solid_angle(n, x, y) : cube_texel_weight_threejs(n, x, y);
  };
  // three.js renormalises by 4 pi / (sum of its weights over the six faces).
  double scale = 1.0;
  if (!exact_solid_angle) {
    NeumaierSum face;
    for (std::uint32_t y = 0; y < n; ++y)
      for (std::uint32_t x = 0; x < n; ++x) face.add(weight(x, y));
    scale = 4.0 * std::numbers::pi / (6.0 * face.value());
  }
  std::uint32_t f = 0, x = 0, y = 0;  // face, column, row of the next sample
  auto next = [&]() noexcept {
    const CubeFaceAxes& axes = kCubeFaceAxes[f];
    const double a = face_coordinate(x + 0.5, n), b = face_coordinate(y + 0.5, n);
    const double inv_len = 1.0 / std::sqrt(1.0 + a * a + b * b);
    const Dir3 d = {(axes.normal.x + a * axes.u_axis.x + b * axes.v_axis.x) * inv_len,
                    (axes.normal.y + a * axes.u_axis.y + b * axes.v_axis.y) * inv_len,
                    (axes.normal.z + a * axes.u_axis.z + b * axes.v_axis.z) * inv_len};
    const Sample s{d, weight(x, y)};
    if (++x == n) {
      x = 0;
      if (++y == n) {
        y = 0;
        ++f;
      }
    }
    return s;
  };
  return project_samples(image, options, 6 * std::uint64_t{n} * n, next, scale, radiance, stats);
}

}  // namespace detail
}  // namespace shpack
