// view_reference.h - the exact E/pi of a map (the cosine convolution of its piecewise-
// constant radiance), with a rigorous bound, fast enough to be computed for every map: the
// "truth" against which what Unity shows is measured (view_error.h).
//
// Representation. The sphere is cut into cells on a latitude-longitude grid (at most
// 128 x 64 at the finest level, coarser levels by 2 x 2 merges, up to 16 x 8 at the top).
// Each cell holds, per channel, from the exact texel integrals
//   m   = sum_t L_t int_t w dw          (the flux vector)
//   P+  = sum_{L_t > 0} L_t Omega_t,    P- = sum_{L_t < 0} |L_t| Omega_t,
// and a cap (centre c, angular radius R) holding every point of its texels. Of the four texels
// of largest sum_c |L_c| Omega in each finest cell, those carrying at least 1/8 of the cell's
// sum are kept as leaves of their own, with their own cap (a sun, a lamp), and the rest of the
// cell as one leaf.
//
// Evaluation. E(n) = sum_t L_t int_t max(0, n.w) dw. A node entirely above the horizon of n
// (angle(n, c) <= 90 - R degrees) adds n.m exactly; one entirely below adds 0; one the
// horizon cuts is opened, and a cut leaf adds the interval that its cap allows: with g =
// max(0, n.w) in [a, b] = [max(0, cos(alpha + R)), max(0, cos(alpha - R))] on the cap,
// alpha = angle(n, c),
//   A:  sum L_t int g  in [P+ a - P- b, P+ b - P- a]
//   B:  sum L_t int g  = n.m + sum L_t int h,  h = max(0, -n.w) in [max(0, -cos(alpha - R)),
//       max(0, -cos(alpha + R))],
// and the leaf adds the midpoint of the intersection of A and B, half its width to the bound.
// So |eval - E/pi| <= bound, up to rounding (a few ulps of sum |L| Omega). The bound of a cut
// cell is about P R / pi: about 2 R^2 of the mean over all normals for a smooth map (R ~ 0.05
// at the finest level), and a sun's texel, its own leaf, costs its texel's radius instead.
//
// Texels. Equirect maps are read row by row (begin_equirect / add_rows, any band heights:
// the same streamed bands as EquirectProjector), with closed-form texel integrals:
//   Omega = dphi (cos th0 - cos th1),   int w dw = (S (sin p1 - sin p0), C dphi,
//   S (cos p0 - cos p1)),  S = int sin^2 = dth/2 - sin(dth) cos(th0 + th1)/2,
//   C = int sin cos = (sin^2 th1 - sin^2 th0)/2  (conventions.h's texel patch, p = longitude).
// Every other layout goes through add_texel with its texel's exact integrals (the
// projectors' own: cube_texel_basis_integrals, sphere_map_texel_basis_integrals) and a bound
// on its texel's angular diameter. The value policies are the projector's (NaN/Inf as 0,
// --negative clamp), so reference and projection see the same texels.
//
// Costs: per texel a few multiply-adds into its cell (equirect) or its integrals (other
// layouts); per direction a few hundred node visits. Memory: a few MiB (8192 finest cells),
// whatever the map's size.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/image_view.h"
#include "shpack/project.h"
#include "shpack/status.h"

namespace shpack {

struct ReferenceValue {
  std::array<double, 3> e_over_pi{};  // per channel
  std::array<double, 3> bound{};      // |e_over_pi - true E/pi| <= bound, up to rounding
};

class ViewReference {
 public:
  ViewReference() noexcept;
  ~ViewReference();
  ViewReference(ViewReference&&) noexcept;
  ViewReference& operator=(ViewReference&&) noexcept;

  // Equirect rows: begin_equirect, then add_rows with consecutive bands from the top (rows
  // is a view of image rows [first_row, first_row + rows.height), width = the image width).
  Status begin_equirect(std::uint32_t width, std::uint32_t height, const ProjectOptions& options) noexcept;
  Status add_rows(const ImageView& rows, std::uint32_t first_row) noexcept;

  // Any other layout: begin_texels, then every texel once: its radiance (after the value
  // policies), its solid angle, int_t w dw, and an upper bound on its angular diameter
  // (radians).
  Status begin_texels() noexcept;
  void add_texel(const std::array<float, 3>& rgb, double solid_angle, const Dir3& flux_vector,
                 double diameter) noexcept;

  // After the last texel: builds the tree. Then eval may be called (thread-safe).
  Status finish() noexcept;
  ReferenceValue eval(const Dir3& n) const noexcept;

  // sum_t L_t Omega_t / (4 pi) per channel: the mean of E/pi over all normals.
  std::array<double, 3> mean_e_over_pi() const noexcept;

  bool finished() const noexcept;

  struct State;

 private:
  std::unique_ptr<State> state_;
};

}  // namespace shpack
