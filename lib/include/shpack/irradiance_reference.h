// preview_reference.h (private) - the brute-force E/pi of an equirect map, summed in cells
// with a rigorous error bound (the derivation is in preview.h).
//
// The cells form a quadtree: `levels` levels, the top one cells_w x cells_h cells, each
// level splitting every cell in 2 x 2. A cell that the terminator of n crosses is looked at
// through its four children, down to the finest level, so the bound shrinks about 4x per
// level (it is proportional to the cut cells' radius times their share of the sphere) for
// about twice the work.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shpack/conventions.h"
#include "shpack/image_view.h"

namespace shpack {

struct ReferenceValue {
  std::array<double, 3> e_over_pi{};  // per channel
  std::array<double, 3> bound{};      // |e_over_pi - true E/pi| <= bound, up to rounding
};

class ReferenceIrradiance {
 public:
  // `image`: a resolved equirect view of finite F32 texels (1 channel = grey, else R, G, B),
  // every value multiplied by `scale`. levels >= 1; the finest level has
  // (cells_w << (levels - 1)) x (cells_h << (levels - 1)) cells.
  ReferenceIrradiance(const ImageView& image, double scale, std::uint32_t cells_w, std::uint32_t cells_h,
                      int levels);

  // E/pi for the unit normal n, in the map's frame (conventions.h).
  ReferenceValue eval(const Dir3& n) const;

  // The finest level's size.
  std::uint32_t cells_w() const { return cells_w_ << (levels_.size() - 1); }
  std::uint32_t cells_h() const { return cells_h_ << (levels_.size() - 1); }

 private:
  struct Cell {
    Dir3 centre;
    double radius = 0;
    std::array<Dir3, 3> flux{};           // m_T per channel: sum_t L_t int_t w dw
    std::array<double, 3> positive{}, negative{};  // P_T, N_T per channel
  };
  // Adds cell (x, y) of `level` to `out`, through its children where it is cut.
  void add(std::size_t level, std::uint32_t x, std::uint32_t y, const Dir3& n, ReferenceValue& out) const;

  std::uint32_t cells_w_, cells_h_;     // of the top level
  std::vector<std::vector<Cell>> levels_;  // [0] the top level, row-major
};

}  // namespace shpack
