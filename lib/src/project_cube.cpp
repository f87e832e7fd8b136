#include "shpack/project_cube.h"

#include <algorithm>
#include <atomic>
#include <new>
#include <span>
#include <thread>
#include <utility>
#include <vector>

#include "accumulate.h"
#include "cube_moments.h"
#include "row_kernel.h"

namespace shpack {
namespace {

using detail::CubeMoments;
using detail::kCubeMoments;
using detail::NeumaierSum;

constexpr std::array<detail::FaceMap, kCubeFaceCount> kFaceMaps = {
    detail::face_map(kCubeFaceAxes[0]), detail::face_map(kCubeFaceAxes[1]),
    detail::face_map(kCubeFaceAxes[2]), detail::face_map(kCubeFaceAxes[3]),
    detail::face_map(kCubeFaceAxes[4]), detail::face_map(kCubeFaceAxes[5])};

// One tile: rows [t kTileRows, (t + 1) kTileRows) of every face. Compensated sums of the
// nine local moments per face and channel, added row by row in row order, and what the
// rows held; the tile's value depends only on its rows.
struct Tile {
  NeumaierSum moments[kCubeFaceCount][kChannelCount][kCubeMoments];
  detail::TexelCounts counts[kCubeFaceCount];
};

// Edge terms of corner row b (coordinate of row k of corners): out[k * n + x] holds term k
// of edge [a_x, a_x+1]. Exact: the nine D_k; Center: D_0 only.
void edge_row(Method method, double b, std::uint32_t n, double* out) noexcept {
  for (std::uint32_t x = 0; x < n; ++x) {
    const double a0 = detail::cube_corner_coordinate(x, n), a1 = detail::cube_corner_coordinate(x + 1, n);
    if (method == Method::Exact) {
      const CubeMoments d = detail::edge_differences(a0, a1, b);
      for (int k = 0; k < kCubeMoments; ++k) out[k * std::size_t{n} + x] = d[k];
    } else {
      out[x] = detail::solid_angle_edge_difference(a0, a1, b);
    }
  }
}

// The nine local moments of each texel of texel row y (structure of arrays, n per moment),
// from the edge terms of its top (b_y) and bottom (b_y+1) corner rows.
void moment_row(Method method, const double* top, const double* bottom, std::uint32_t y,
                std::uint32_t n, double* out) noexcept {
  if (method == Method::Exact) {
    for (std::size_t i = 0; i < kCubeMoments * std::size_t{n}; ++i) out[i] = bottom[i] - top[i];
    return;
  }
  const double b = (2.0 * y + 1.0 - n) / n;  // texel centre, correctly rounded
  for (std::uint32_t x = 0; x < n; ++x) {
    const double a = (2.0 * x + 1.0 - n) / n;
    const CubeMoments m = detail::center_moments(bottom[x] - top[x], a, b);
    for (int k = 0; k < kCubeMoments; ++k) out[k * std::size_t{n} + x] = m[k];
  }
}

// The nine dot products of one channel plane with the moment rows. Four partial sums per
// moment (texels x = 0, 1, 2, 3 mod 4), combined pairwise: a fixed order on any machine.
void plane_moment_sums(const float* v, const double* m, std::uint32_t n,
                       double (&out)[kCubeMoments]) noexcept {
  constexpr std::uint32_t kLanes = 4;
  for (int k = 0; k < kCubeMoments; ++k) {
    const double* row = m + k * std::size_t{n};
    double lane[kLanes] = {};
    std::uint32_t x = 0;
    for (; x + kLanes <= n; x += kLanes)
      for (std::uint32_t l = 0; l < kLanes; ++l) lane[l] += static_cast<double>(v[x + l]) * row[x + l];
    for (std::uint32_t l = 0; x < n; ++x, ++l) lane[l] += static_cast<double>(v[x]) * row[x];
    out[k] = (lane[0] + lane[1]) + (lane[2] + lane[3]);
  }
}

struct Job {
  std::array<ImageView, kCubeFaceCount> faces;  // resolved
  std::uint32_t n = 0;
  ProjectOptions options;
  std::vector<Tile> tiles;
  std::vector<double> edge_scratch;   // per worker: 2 rows of edge terms + 1 moment row
  std::vector<float> plane_scratch;   // per worker: 3 n floats

  std::size_t edge_terms() const noexcept {
    return (options.method == Method::Exact ? kCubeMoments : 1) * std::size_t{n};
  }
  std::size_t worker_doubles() const noexcept { return 2 * edge_terms() + kCubeMoments * std::size_t{n}; }

  void run_tile(std::uint32_t t, unsigned worker) noexcept {
    const Method method = options.method;
    double* top = edge_scratch.data() + worker * worker_doubles();
    double* bottom = top + edge_terms();
    double* moments = bottom + edge_terms();
    const std::span<float> planes(plane_scratch.data() + std::size_t{3} * n * worker, std::size_t{3} * n);
    Tile& tile = tiles[t];
    const std::uint32_t y0 = t * kTileRows, y1 = std::min(n, y0 + kTileRows);
    edge_row(method, detail::cube_corner_coordinate(y0, n), n, top);
    for (std::uint32_t y = y0; y < y1; ++y) {
      edge_row(method, detail::cube_corner_coordinate(y + 1, n), n, bottom);
      moment_row(method, top, bottom, y, n, moments);
      for (int f = 0; f < kCubeFaceCount; ++f) {
        detail::load_row_planes(faces[f].rows(y, 1), y, options, planes, tile.counts[f]);
        for (int c = 0; c < kChannelCount; ++c) {
          double sums[kCubeMoments];
          plane_moment_sums(planes.data() + c * std::size_t{n}, moments, n, sums);
          for (int k = 0; k < kCubeMoments; ++k) tile.moments[f][c][k].add(sums[k]);
        }
      }
      std::swap(top, bottom);
    }
  }

  // Tiles on up to `workers` threads; each tile is written by one worker only. If a thread
  // cannot be started, the others (and the caller) drain the queue: the result is the same.
  void run(unsigned workers) noexcept {
    const auto count = static_cast<std::uint32_t>(tiles.size());
    std::atomic<std::uint32_t> next{0};
    auto drain = [&](unsigned worker) noexcept {
      for (std::uint32_t t; (t = next.fetch_add(1)) < count;) run_tile(t, worker);
    };
    std::vector<std::thread> threads;
    try {
      threads.reserve(workers - 1);
      for (unsigned w = 1; w < workers; ++w) threads.emplace_back(drain, w);
    } catch (...) {
      // Fewer workers than asked for; the queue is still drained below.
    }
    drain(0);
    for (std::thread& th : threads) th.join();
  }
};

}  // namespace

Status project_cube(const std::array<ImageView, kCubeFaceCount>& faces, const ProjectOptions& options,
                    ShL2& radiance, ProjectStats* stats) noexcept {
  if (options.method != Method::Exact && options.method != Method::Center)
    return Status::error(Errc::InvalidArgument, "unknown projection method");
  std::array<ImageView, kCubeFaceCount> views = faces;
  for (std::uint32_t f = 0; f < kCubeFaceCount; ++f) {
    if (Status st = resolve_view(views[f]); !st.ok()) {
      st.face = f;
      return st;
    }
    if (views[f].width != views[f].height)
      return Status::error(Errc::BadView, "cube face is not square", 0, 0, f);
    if (views[f].width != views[0].width)
      return Status::error(Errc::BadView, "cube faces differ in size", 0, 0, f);
  }
  const std::uint32_t n = views[0].width;
  const auto tile_count = (n + kTileRows - 1) / kTileRows;
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const unsigned workers = std::min<unsigned>(options.threads == 0 ? hw : options.threads, tile_count);

  Job job;
  try {
    job.faces = views;
    job.n = n;
    job.options = options;
    job.tiles.resize(tile_count);
    job.edge_scratch.resize(job.worker_doubles() * workers);
    job.plane_scratch.resize(std::size_t{3} * n * workers);
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate the cube projection buffers");
  }
  job.run(workers);

  // Reduce: per face in tile order, then the faces in face order.
  detail::TexelCounts counts;
  NeumaierSum total[kChannelCount][kShCount];
  for (int f = 0; f < kCubeFaceCount; ++f) {
    detail::TexelCounts face_counts;
    for (const Tile& tile : job.tiles) face_counts.merge_after(tile.counts[f]);
    if (options.nonfinite == NonFinite::Error && face_counts.nonfinite != 0)
      return Status::error(Errc::NonFiniteTexel, "NaN or Inf texel", face_counts.first_nonfinite_x,
                           face_counts.first_nonfinite_y, static_cast<std::uint32_t>(f));
    counts.merge_after(face_counts);
    for (int c = 0; c < kChannelCount; ++c) {
      CubeMoments m{};
      for (int k = 0; k < kCubeMoments; ++k) {
        NeumaierSum s;
        for (const Tile& tile : job.tiles) s.add(tile.moments[f][c][k]);
        m[k] = s.value();
      }
      const std::array<double, kShCount> p = detail::face_basis_integrals(kFaceMaps[f], m);
      for (int i = 0; i < kShCount; ++i) total[c][i].add(p[i]);
    }
  }
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) radiance.c[c][i] = kBasisScale[i] * total[c][i].value();
  if (stats != nullptr) {
    *stats = {counts.nonfinite, counts.negative, counts.first_nonfinite_x, counts.first_nonfinite_y,
              counts.max_value};
  }
  return Status::success();
}

Status cube_texel_basis_integrals(std::uint32_t size, CubeFace face, std::uint32_t x, std::uint32_t y,
                                  Method method, std::array<double, kShCount>& out) noexcept {
  const auto f = static_cast<std::uint32_t>(face);
  if (size == 0 || x >= size || y >= size || f >= kCubeFaceCount)
    return Status::error(Errc::InvalidArgument, "texel or face outside the cube");
  if (method != Method::Exact && method != Method::Center)
    return Status::error(Errc::InvalidArgument, "unknown projection method");
  const double a0 = detail::cube_corner_coordinate(x, size), a1 = detail::cube_corner_coordinate(x + 1, size);
  const double b0 = detail::cube_corner_coordinate(y, size), b1 = detail::cube_corner_coordinate(y + 1, size);
  CubeMoments m{};
  if (method == Method::Exact) {
    const CubeMoments top = detail::edge_differences(a0, a1, b0), bottom = detail::edge_differences(a0, a1, b1);
    for (int k = 0; k < kCubeMoments; ++k) m[k] = bottom[k] - top[k];
  } else {
    const double omega = detail::solid_angle_edge_difference(a0, a1, b1) -
                         detail::solid_angle_edge_difference(a0, a1, b0);
    m = detail::center_moments(omega, (2.0 * x + 1.0 - size) / size, (2.0 * y + 1.0 - size) / size);
  }
  const std::array<double, kShCount> p = detail::face_basis_integrals(kFaceMaps[f], m);
  for (int i = 0; i < kShCount; ++i) out[i] = kBasisScale[i] * p[i];
  return Status::success();
}

}  // namespace shpack
