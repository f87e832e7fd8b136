// reference_tree.h (private) - the cells of view_reference.h, how texels are added to them,
// and the tree they are evaluated through.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "projection/row_kernel.h"
#include "shpack/conventions.h"
#include "shpack/project.h"
#include "shpack/view_reference.h"

namespace shpack::detail {

inline constexpr std::uint32_t kReferenceCellsW = 128, kReferenceCellsH = 64;  // the finest grid, at most
inline constexpr std::uint32_t kReferenceTopW = 16, kReferenceTopH = 8;        // the top level, at most
inline constexpr int kHeavyTexels = 4;  // texels kept as leaves of their own, per finest cell
inline constexpr double kHeavyShare = 0.125;  // of the cell's sum |L| Omega, at least

// A texel kept apart: its radiance, solid angle, int w dw and angular diameter.
struct HeavyTexel {
  double weight = 0;  // sum_c |L_c| Omega: the largest are kept
  std::array<float, 3> rgb{};
  double solid_angle = 0;
  Dir3 flux;
  double diameter = 0;
};

// What a cell sums, per channel.
struct CellSums {
  std::array<Dir3, 3> m{};
  std::array<double, 3> positive{}, negative{};
};

struct FinestCell {
  CellSums sums;
  double extra_radius = 0;  // the largest diameter of a texel assigned to it by its centroid
  int heavy_count = 0;
  std::array<HeavyTexel, kHeavyTexels> heavy{};  // by decreasing weight

  // Keeps `t` if it is among the kHeavyTexels heaviest so far (the first of equal ones).
  void offer(const HeavyTexel& t) noexcept;
  double heavy_threshold() const noexcept { return heavy_count < kHeavyTexels ? 0.0 : heavy[kHeavyTexels - 1].weight; }
};

// A cap: every point of the node is within angle R of c.
struct Cap {
  Dir3 c{0, 1, 0};
  double cos_r = -1, sin_r = 0;  // R in [0, pi]
};
Cap make_cap(const Dir3& centre, double radius) noexcept;

// A node of the tree; leaves are the finest cells (their rest and their heavy texels).
struct Node {
  Cap cap;
  CellSums sums;
};

// The interval that a cap allows for sum_t L_t int_t max(0, n.w) dw (view_reference.h, A and
// B), added to `value` (midpoint) and `bound` (half-width), both divided by pi.
void add_cut_interval(const Cap& cap, const CellSums& sums, const Dir3& n, ReferenceValue& out) noexcept;

}  // namespace shpack::detail

namespace shpack {

struct ViewReference::State {
  enum class Kind { Equirect, Texels } kind = Kind::Equirect;
  ProjectOptions options;
  // The finest grid: cells_w x cells_h cells, each block_w x block_h texels (equirect), or
  // kReferenceCellsW x kReferenceCellsH assigned by texel centroid (texels).
  std::uint32_t width = 0, height = 0;      // equirect image
  std::uint32_t block_w = 1, block_h = 1;   // equirect texels per cell
  std::uint32_t cells_w = 0, cells_h = 0;
  std::uint32_t next_row = 0;
  std::vector<detail::FinestCell> cells;
  // Equirect column tables: sin p1 - sin p0 and cos p0 - cos p1 of each column's longitudes.
  std::vector<double> column_cos, column_sin;
  std::vector<float> planes;  // one row, three channel planes

  // The tree, levels[0] the finest (cells_w x cells_h), each level 2 x 2 merges of the one
  // below; level_w/level_h their sizes.
  std::vector<std::vector<detail::Node>> levels;
  std::vector<std::uint32_t> level_w, level_h;
  std::vector<detail::Node> heavy_leaves;      // kHeavyTexels slots per finest cell
  std::vector<std::uint8_t> heavy_counts;      // per finest cell
  std::array<double, 3> mean{};
  bool finished = false;

  // The latitude-longitude rectangle of finest cells [x0, x1) x [y0, y1): polar angles and
  // longitudes of its edges.
  void cell_range(std::uint32_t x0, std::uint32_t x1, std::uint32_t y0, std::uint32_t y1, double& th0, double& th1,
                  double& lon_lo, double& lon_hi) const noexcept;
  Status build_tree() noexcept;
  void add_node(std::size_t level, std::uint32_t x, std::uint32_t y, const Dir3& n, ReferenceValue& out) const noexcept;
};

}  // namespace shpack
