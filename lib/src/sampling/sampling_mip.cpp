// mip:K - reduce the map as a GPU mip chain would, then project the small map exactly.
//
// Level K of a W x H map is W' x H' = max(1, W >> K) x max(1, H >> K) (the level-size rule
// of Vulkan, Direct3D and OpenGL). Small texel (I, J) is the plain average, by texel count,
// of the source texels under its footprint [I W/W', (I+1) W/W') x [J H/H', (J+1) H/H').
// Measured in units of 1/W' source texels, the footprint of column I is [I W, (I+1) W) and
// source column i is [i W', (i+1) W'), so overlaps are exact integers; since W >= W', a
// source column overlaps at most two small columns (rows likewise):
//
//   source  |  0  |  1  |  2  |  3  |  4  |  5  |  6  |     W = 7, W' = 3: footprints of
//   small   |      0        |       1       |       2       |   7/3 source texels each
//
// When 2^K divides W and H every overlap is a whole texel and this is the average of a
// 2^K x 2^K block. The average ignores that texels near the poles cover less solid angle;
// that is what GPU reductions and engine importers do, and part of the error being measured.
#include <algorithm>
#include <new>
#include <vector>

#include "sampling/sampling_projectors.h"
#include "sampling/sampling_texel.h"

namespace shpack::detail {
namespace {

// The at most two small cells that source cell i overlaps, with integer overlaps in units
// of 1/small of a source cell (source cells [i small, (i+1) small), small cells [I size,
// (I+1) size)). Products stay below 2^64 for any uint32 sizes.
struct Overlap {
  std::uint32_t first;             // small cell of the first part
  std::uint64_t first_part, rest;  // overlap with `first` and with `first + 1`
};

Overlap overlap(std::uint32_t i, std::uint32_t size, std::uint32_t small) noexcept {
  const std::uint64_t begin = std::uint64_t{i} * small, end = begin + small;
  const auto first = static_cast<std::uint32_t>(begin / size);
  const std::uint64_t split = std::min<std::uint64_t>(end, (std::uint64_t{first} + 1) * size);
  return {first, split - begin, end - split};
}

}  // namespace

Status project_mip(const ImageView& image, std::uint32_t levels, const ProjectOptions& options,
                   ShL2& radiance, ProjectStats* stats) noexcept {
  const std::uint32_t width = image.width, height = image.height;
  const std::uint32_t small_w = std::max(1u, width >> levels),
                      small_h = std::max(1u, height >> levels);
  std::vector<double> acc;
  std::vector<float> small, planes;
  try {
    acc.assign(std::size_t{3} * small_w * small_h, 0.0);
    small.resize(acc.size());
    planes.resize(std::size_t{3} * width);
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the mip level");
  }

  // One pass over the source rows, each loaded with the policies by the row loader of
  // project_equirect; every texel is added to the (at most four) small texels it overlaps.
  TexelCounts counts;
  for (std::uint32_t y = 0; y < height; ++y) {
    if (Status st = load_image_row(image, y, options, planes, counts); !st.ok()) return st;
    const Overlap oy = overlap(y, height, small_h);
    const std::uint64_t row_parts[2] = {oy.first_part, oy.rest};
    for (std::uint32_t x = 0; x < width; ++x) {
      const Overlap ox = overlap(x, width, small_w);
      const std::uint64_t col_parts[2] = {ox.first_part, ox.rest};
      const double rgb[3] = {planes[x], planes[width + x], planes[2 * std::size_t{width} + x]};
      for (std::uint32_t r = 0; r < 2; ++r) {
        if (row_parts[r] == 0) continue;
        for (std::uint32_t q = 0; q < 2; ++q) {
          if (col_parts[q] == 0) continue;
          const double w = static_cast<double>(row_parts[r]) * static_cast<double>(col_parts[q]);
          double* cell = &acc[3 * (std::size_t{oy.first + r} * small_w + (ox.first + q))];
          for (int c = 0; c < 3; ++c) cell[c] += w * rgb[c];
        }
      }
    }
  }
  // Each small texel's overlaps sum to W x H units of 1/(W' H').
  const double footprint = static_cast<double>(width) * static_cast<double>(height);
  for (std::size_t k = 0; k < acc.size(); ++k) small[k] = static_cast<float>(acc[k] / footprint);

  // The small map holds only finite values with the policies applied; keep them as they are.
  ProjectOptions exact = options;
  exact.method = SamplingMethod::Exact;
  exact.nonfinite = NonFinite::Error;
  exact.negative = Negative::Keep;
  const Status st = project_equirect(make_view(small.data(), small_w, small_h, 3), exact, radiance);
  if (st.ok() && stats != nullptr) *stats = stats_from_counts(counts);
  return st;
}

}  // namespace shpack::detail
