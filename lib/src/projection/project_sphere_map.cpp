#include "shpack/project_sphere_map.h"

#include <algorithm>
#include <new>
#include <span>
#include <thread>
#include <vector>

#include "common/accumulate.h"
#include "projection/row_kernel.h"
#include "shpack/work_queue.h"
#include "projection/sphere_map_texels.h"

namespace shpack {
namespace {

using detail::NeumaierSum;
using detail::SphereMoments;

bool known(SphereMap map) noexcept {
  return map == SphereMap::Octahedral || map == SphereMap::Angular || map == SphereMap::MirrorBall;
}

SphereMoments texel_moments(SphereMap map, std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept {
  const detail::TexelSquare t = detail::sphere_map_texel_square(n, x, y);
  switch (map) {
    case SphereMap::Octahedral: return detail::octahedral_texel_moments(t);
    case SphereMap::Angular: return detail::angular_texel_moments(t);
    case SphereMap::MirrorBall: return detail::mirror_ball_texel_moments(t);
  }
  return {};
}

// Rows [t kTileRows, (t + 1) kTileRows): compensated sums of the moments per channel, added
// row by row in row order, and what the rows held.
struct SphereMapTile {
  NeumaierSum moments[kChannelCount][kShCount];
  detail::TexelCounts counts;
};

struct SphereMapJob {
  ImageView image;  // resolved
  SphereMap map = SphereMap::Octahedral;
  ProjectOptions options;
  std::vector<SphereMapTile> tiles;
  std::vector<float> planes;  // per worker: 3 n floats

  void run_tile(std::uint32_t t, unsigned worker) noexcept {
    const std::uint32_t n = image.width;
    const std::span<float> row_planes(planes.data() + std::size_t{3} * n * worker, std::size_t{3} * n);
    SphereMapTile& tile = tiles[t];
    const std::uint32_t y1 = std::min(n, (t + 1) * kTileRows);
    for (std::uint32_t y = t * kTileRows; y < y1; ++y) {
      const detail::RowSpan span = detail::sphere_map_row_span(map, n, y);
      if (span.first == span.last) continue;
      // Only the texels inside the map are read: a view of that run of the row.
      ImageView run = image.rows(y, 1);
      run.data = image.pixel(span.first, y);
      run.width = span.last - span.first;
      detail::TexelCounts row_counts;
      detail::load_row_planes(run, y, options, row_planes, row_counts);
      row_counts.first_nonfinite_x += span.first;
      tile.counts.merge_after(row_counts);
      const float* plane[kChannelCount] = {row_planes.data(), row_planes.data() + run.width,
                                           row_planes.data() + 2 * std::size_t{run.width}};
      double sums[kChannelCount][kShCount] = {};
      for (std::uint32_t x = span.first; x < span.last; ++x) {
        const SphereMoments m = texel_moments(map, n, x, y);
        for (int c = 0; c < kChannelCount; ++c) {
          const double value = plane[c][x - span.first];
          for (int i = 0; i < kShCount; ++i) sums[c][i] += value * m[i];
        }
      }
      for (int c = 0; c < kChannelCount; ++c)
        for (int i = 0; i < kShCount; ++i) tile.moments[c][i].add(sums[c][i]);
    }
  }

  // Tiles on up to `workers` threads (work_queue.h), each tile written by one worker.
  void run(unsigned workers) noexcept {
    detail::run_queue(static_cast<std::uint32_t>(tiles.size()), workers,
                      [&](std::uint32_t t, unsigned worker) noexcept { run_tile(t, worker); });
  }
};

}  // namespace

namespace detail {

TexelSquare sphere_map_texel_square(std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept {
  const double size = n;
  return {(2.0 * x - size) / size, (2.0 * x + 2.0 - size) / size, (size - 2.0 * y - 2.0) / size,
          (size - 2.0 * y) / size, 2.0 / size};
}

RowSpan sphere_map_row_span(SphereMap map, std::uint32_t n, std::uint32_t y) noexcept {
  if (map == SphereMap::Octahedral) return {0, n};
  RowSpan span{n, n};
  for (std::uint32_t x = 0; x < n; ++x) {
    const TexelSquare t = sphere_map_texel_square(n, x, y);
    const double nu = std::clamp(0.0, t.u0, t.u1), nv = std::clamp(0.0, t.v0, t.v1);
    if (nu * nu + nv * nv < 1.0) {
      if (span.first == n) span.first = x;
      span.last = x + 1;
    }
  }
  if (span.first == n) span.last = n;
  return span;
}

}  // namespace detail

Status project_sphere_map(const ImageView& image, SphereMap map, const ProjectOptions& options,
                          ShL2& radiance, ProjectStats* stats) noexcept {
  if (!known(map)) return Status::error(Errc::InvalidArgument, "unknown sphere map");
  if (options.method != SamplingMethod::Exact)
    return Status::error(Errc::InvalidArgument, "sphere maps are projected with SamplingMethod::Exact only");
  SphereMapJob job;
  job.image = image;
  if (Status st = resolve_view(job.image); !st.ok()) return st;
  if (job.image.width != job.image.height) return Status::error(Errc::BadView, "a sphere map must be square");
  const std::uint32_t n = job.image.width;
  const auto tile_count = (n + kTileRows - 1) / kTileRows;
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const unsigned workers = std::min<unsigned>(options.threads == 0 ? hw : options.threads, tile_count);
  job.map = map;
  job.options = options;
  try {
    job.tiles.resize(tile_count);
    job.planes.resize(std::size_t{3} * n * workers);
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the sphere map projection buffers");
  }
  job.run(workers);

  detail::TexelCounts counts;
  for (const SphereMapTile& tile : job.tiles) counts.merge_after(tile.counts);
  if (options.nonfinite == NonFinite::Error && counts.nonfinite != 0)
    return Status::error(Errc::NonFiniteTexel, "NaN or Inf texel", counts.first_nonfinite_x, counts.first_nonfinite_y);
  for (int c = 0; c < kChannelCount; ++c) {
    for (int i = 0; i < kShCount; ++i) {
      NeumaierSum s;
      for (const SphereMapTile& tile : job.tiles) s.add(tile.moments[c][i]);
      radiance.c[c][i] = kBasisScale[i] * s.value();
    }
  }
  if (stats != nullptr) {
    *stats = {counts.nonfinite, counts.negative, counts.first_nonfinite_x, counts.first_nonfinite_y,
              counts.max_value};
  }
  return Status::success();
}

Status sphere_map_texel_basis_integrals(std::uint32_t size, SphereMap map, std::uint32_t x,
                                        std::uint32_t y, std::array<double, kShCount>& out) noexcept {
  if (!known(map)) return Status::error(Errc::InvalidArgument, "unknown sphere map");
  if (size == 0 || x >= size || y >= size) return Status::error(Errc::InvalidArgument, "texel outside the map");
  const SphereMoments m = texel_moments(map, size, x, y);
  for (int i = 0; i < kShCount; ++i) out[i] = kBasisScale[i] * m[i];
  return Status::success();
}

}  // namespace shpack
