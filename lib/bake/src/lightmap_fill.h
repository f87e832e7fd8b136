// lightmap_fill.h (private) - texels that take their value from their neighbours: invalid
// texels dilated within their chart, then each chart padded into the unused texels around it
// (lightmap_bake.h). A ring's new values are all computed from the previous ring before any
// is written, so the result does not depend on the scan order.
#pragma once

#include <cstdint>
#include <vector>

#include "shpack/bake/lightmap_bake.h"

namespace shpack::bake {

// Texels with `invalid` set take the mean of their 8-neighbours of the same chart that are
// valid or already filled, ring by ring; those a chart never reaches keep their baked value
// (counted in invalid_kept). Marks them Dilated.
void dilate_invalid_texels(LightmapTexels& map, const std::vector<std::int32_t>& chart,
                           const std::vector<bool>& invalid);

// `rings` rings of Unused texels around the charts, each the mean of its filled 8-neighbours
// of one chart (the lowest-numbered chart among them). Marks them Padded.
void pad_charts(LightmapTexels& map, std::vector<std::int32_t> chart, std::uint32_t rings);

}  // namespace shpack::bake
