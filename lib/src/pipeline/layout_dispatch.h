// layout_dispatch.h (private) - which projector family a resolved layout belongs to.
#pragma once

#include "shpack/cube_layout.h"
#include "shpack/layout.h"
#include "shpack/project_sphere_map.h"

namespace shpack::detail {

inline CubeLayout cube_layout_of(Layout layout) noexcept {
  switch (layout) {
    case Layout::VerticalCross: return CubeLayout::VerticalCross;
    case Layout::HorizontalStrip: return CubeLayout::HorizontalStrip;
    case Layout::VerticalStrip: return CubeLayout::VerticalStrip;
    default: return CubeLayout::HorizontalCross;
  }
}

inline SphereMap sphere_map_of(Layout layout) noexcept {
  return layout == Layout::Angular ? SphereMap::Angular
         : layout == Layout::MirrorBall ? SphereMap::MirrorBall
                                        : SphereMap::Octahedral;
}

inline bool is_sphere_map(Layout layout) noexcept {
  return layout == Layout::Octahedral || layout == Layout::Angular || layout == Layout::MirrorBall;
}

}  // namespace shpack::detail
