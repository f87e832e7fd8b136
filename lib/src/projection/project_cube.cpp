#include "shpack/project_cube.h"

#include <algorithm>
#include <new>
#include <span>
#include <thread>
#include <utility>
#include <vector>

#include "common/accumulate.h"
#include "projection/cube_moments.h"
#include "projection/row_kernel.h"
#include "shpack/work_queue.h"

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
struct CubeTile {
  NeumaierSum moments[kCubeFaceCount][kChannelCount][kCubeMoments];
  detail::TexelCounts counts[kCubeFaceCount];
};

// Edge terms of the corner row at height b: out[k * n + x] holds term k of edge x
// (corners x, x + 1). Exact: the nine D_k; Center: D_0 only. Corner values are shared by
// the two edges that meet there, and edges x >= (n+1)/2 are mirrored (cube_moments.h), with
// the same arithmetic as detail::edge_terms.
void edge_row(SamplingMethod method, double b, std::uint32_t n, double* out) noexcept {
  const detail::CornerRow row = detail::corner_row(b);
  const std::uint32_t half = detail::first_mirrored_edge(n);
  const std::size_t stride = n;
  if (method == SamplingMethod::Exact) {
    detail::CubeCorner c0 = detail::exact_corner(detail::cube_corner_coordinate(0, n), row);
    for (std::uint32_t x = 0; x < half; ++x) {
      const detail::CubeCorner c1 = detail::exact_corner(detail::cube_corner_coordinate(x + 1, n), row);
      const CubeMoments d = detail::edge_differences(c0, c1, row);
      for (int k = 0; k < kCubeMoments; ++k) out[k * stride + x] = d[k];
      c0 = c1;
    }
    for (std::uint32_t x = half; x < n; ++x)
      for (int k = 0; k < kCubeMoments; ++k) out[k * stride + x] = out[k * stride + (n - 1 - x)] * detail::kMirrorEdgeSign[k];
  } else {
    detail::CubeCorner c0 = detail::solid_angle_corner(detail::cube_corner_coordinate(0, n), row);
    for (std::uint32_t x = 0; x < half; ++x) {
      const detail::CubeCorner c1 = detail::solid_angle_corner(detail::cube_corner_coordinate(x + 1, n), row);
      out[x] = detail::solid_angle_edge_difference(c0, c1, row);
      c0 = c1;
    }
    for (std::uint32_t x = half; x < n; ++x) out[x] = out[n - 1 - x] * detail::kMirrorEdgeSign[0];
  }
}

// The nine local moments of each texel of texel row y (structure of arrays, n per moment),
// from the edge terms of its top (b_y) and bottom (b_y+1) corner rows.
void moment_row(SamplingMethod method, const double* top, const double* bottom, std::uint32_t y,
                std::uint32_t n, double* out) noexcept {
  if (method == SamplingMethod::Exact) {
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

// The 3 x 9 dot products of a face row (three channel planes of n floats) with the nine
// moment rows. Each weight is loaded once for the three channels. Four partial sums per
// product (lane l takes texels x = l mod 4), combined as (l0 + l1) + (l2 + l3): a fixed order
// on any machine. 64-bit indices and named scalars keep the twelve accumulators in registers.
void row_moment_sums(const float* planes, const double* moments, std::size_t n,
                     double (&out)[kChannelCount][kCubeMoments]) noexcept {
  const float *red = planes, *green = planes + n, *blue = planes + 2 * n;
  for (int k = 0; k < kCubeMoments; ++k) {
    const double* w = moments + k * n;
    double r0 = 0, r1 = 0, r2 = 0, r3 = 0, g0 = 0, g1 = 0, g2 = 0, g3 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0;
    std::size_t x = 0;
    for (; x + 4 <= n; x += 4) {
      const double w0 = w[x], w1 = w[x + 1], w2 = w[x + 2], w3 = w[x + 3];
      r0 += red[x] * w0, r1 += red[x + 1] * w1, r2 += red[x + 2] * w2, r3 += red[x + 3] * w3;
      g0 += green[x] * w0, g1 += green[x + 1] * w1, g2 += green[x + 2] * w2, g3 += green[x + 3] * w3;
      b0 += blue[x] * w0, b1 += blue[x + 1] * w1, b2 += blue[x + 2] * w2, b3 += blue[x + 3] * w3;
    }
    if (x < n) r0 += red[x] * w[x], g0 += green[x] * w[x], b0 += blue[x] * w[x], ++x;
    if (x < n) r1 += red[x] * w[x], g1 += green[x] * w[x], b1 += blue[x] * w[x], ++x;
    if (x < n) r2 += red[x] * w[x], g2 += green[x] * w[x], b2 += blue[x] * w[x];
    out[0][k] = (r0 + r1) + (r2 + r3);
    out[1][k] = (g0 + g1) + (g2 + g3);
    out[2][k] = (b0 + b1) + (b2 + b3);
  }
}

struct CubeJob {
  std::array<ImageView, kCubeFaceCount> faces;  // resolved
  std::uint32_t n = 0;
  ProjectOptions options;
  std::vector<CubeTile> tiles;
  std::vector<double> edge_scratch;   // per worker: 2 rows of edge terms + 1 moment row
  std::vector<float> plane_scratch;   // per worker: 3 n floats

  std::size_t edge_terms() const noexcept {
    return (options.method == SamplingMethod::Exact ? kCubeMoments : 1) * std::size_t{n};
  }
  std::size_t worker_doubles() const noexcept { return 2 * edge_terms() + kCubeMoments * std::size_t{n}; }

  void run_tile(std::uint32_t t, unsigned worker) noexcept {
    const SamplingMethod method = options.method;
    double* top = edge_scratch.data() + worker * worker_doubles();
    double* bottom = top + edge_terms();
    double* moments = bottom + edge_terms();
    const std::span<float> planes(plane_scratch.data() + std::size_t{3} * n * worker, std::size_t{3} * n);
    CubeTile& tile = tiles[t];
    const std::uint32_t y0 = t * kTileRows, y1 = std::min(n, y0 + kTileRows);
    edge_row(method, detail::cube_corner_coordinate(y0, n), n, top);
    for (std::uint32_t y = y0; y < y1; ++y) {
      edge_row(method, detail::cube_corner_coordinate(y + 1, n), n, bottom);
      moment_row(method, top, bottom, y, n, moments);
      for (int f = 0; f < kCubeFaceCount; ++f) {
        detail::load_row_planes(faces[f].rows(y, 1), y, options, planes, tile.counts[f]);
        double sums[kChannelCount][kCubeMoments];
        row_moment_sums(planes.data(), moments, n, sums);
        for (int c = 0; c < kChannelCount; ++c)
          for (int k = 0; k < kCubeMoments; ++k) tile.moments[f][c][k].add(sums[c][k]);
      }
      std::swap(top, bottom);
    }
  }

  // Tiles on up to `workers` threads (work_queue.h), each tile written by one worker.
  void run(unsigned workers) noexcept {
    detail::run_queue(static_cast<std::uint32_t>(tiles.size()), workers,
                      [&](std::uint32_t t, unsigned worker) noexcept { run_tile(t, worker); });
  }
};

}  // namespace

Status project_cube(const std::array<ImageView, kCubeFaceCount>& faces, const ProjectOptions& options,
                    ShL2& radiance, ProjectStats* stats) noexcept {
  if (options.method != SamplingMethod::Exact && options.method != SamplingMethod::Center)
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

  CubeJob job;
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
  std::uint32_t first_bad_face = 0;
  NeumaierSum total[kChannelCount][kShCount];
  for (int f = 0; f < kCubeFaceCount; ++f) {
    detail::TexelCounts face_counts;
    for (const CubeTile& tile : job.tiles) face_counts.merge_after(tile.counts[f]);
    if (options.nonfinite == NonFinite::Error && face_counts.nonfinite != 0)
      return Status::error(Errc::NonFiniteTexel, "NaN or Inf texel", face_counts.first_nonfinite_x,
                           face_counts.first_nonfinite_y, static_cast<std::uint32_t>(f));
    if (counts.nonfinite == 0 && face_counts.nonfinite != 0) first_bad_face = static_cast<std::uint32_t>(f);
    counts.merge_after(face_counts);
    for (int c = 0; c < kChannelCount; ++c) {
      CubeMoments m{};
      for (int k = 0; k < kCubeMoments; ++k) {
        NeumaierSum s;
        for (const CubeTile& tile : job.tiles) s.add(tile.moments[f][c][k]);
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
              counts.max_value, first_bad_face};
  }
  return Status::success();
}

Status cube_texel_basis_integrals(std::uint32_t size, CubeFace face, std::uint32_t x, std::uint32_t y,
                                  SamplingMethod method, std::array<double, kShCount>& out) noexcept {
  const auto f = static_cast<std::uint32_t>(face);
  if (size == 0 || x >= size || y >= size || f >= kCubeFaceCount)
    return Status::error(Errc::InvalidArgument, "texel or face outside the cube");
  if (method != SamplingMethod::Exact && method != SamplingMethod::Center)
    return Status::error(Errc::InvalidArgument, "unknown projection method");
  const bool exact = method == SamplingMethod::Exact;
  const CubeMoments top = detail::edge_terms(exact, x, size, detail::corner_row(detail::cube_corner_coordinate(y, size)));
  const CubeMoments bottom =
      detail::edge_terms(exact, x, size, detail::corner_row(detail::cube_corner_coordinate(y + 1, size)));
  CubeMoments m{};
  if (exact) {
    for (int k = 0; k < kCubeMoments; ++k) m[k] = bottom[k] - top[k];
  } else {
    m = detail::center_moments(bottom[0] - top[0], (2.0 * x + 1.0 - size) / size, (2.0 * y + 1.0 - size) / size);
  }
  const std::array<double, kShCount> p = detail::face_basis_integrals(kFaceMaps[f], m);
  for (int i = 0; i < kShCount; ++i) out[i] = kBasisScale[i] * p[i];
  return Status::success();
}

}  // namespace shpack
