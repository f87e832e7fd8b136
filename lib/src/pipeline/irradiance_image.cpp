// irradiance_image.cpp - E/pi as an image from one of four sources (irradiance_image.h).
#include "shpack/irradiance_image.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <random>
#include <thread>

#include "common/angles.h"
#include "pipeline/layout_dispatch.h"
#include "sampling/sampling_points.h"
#include "sampling/sampling_texel.h"
#include "shpack/cube_layout.h"
#include "shpack/rotate.h"
#include "shpack/work_queue.h"

namespace shpack {
namespace {

constexpr std::uint64_t kMaxOutputTexels = std::uint64_t{1} << 26;

Dir3 face_direction(CubeFace face, std::uint32_t n, std::uint32_t x, std::uint32_t y) noexcept {
  const CubeFaceAxes& f = kCubeFaceAxes[static_cast<int>(face)];
  const double a = 2 * (x + 0.5) / n - 1, b = 2 * (y + 0.5) / n - 1;
  const Dir3 d = {f.normal.x + a * f.u_axis.x + b * f.v_axis.x, f.normal.y + a * f.u_axis.y + b * f.v_axis.y,
                  f.normal.z + a * f.u_axis.z + b * f.v_axis.z};
  const double len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  return {d.x / len, d.y / len, d.z / len};
}

// A sample of the sums of Riemann and MonteCarlo: its direction, and L(w_k) times its weight.
struct Sample {
  Dir3 w;
  std::array<double, 3> weighted{};
};

Status samples_of(const MapImage& map, const ConvertOptions& options, const IrradianceRequest& r,
                  std::vector<Sample>& out) {
  ImageView view = map.image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  detail::TexelReader reader(view, {SamplingMethod::Exact, NonFinite::Zero, options.negative, 1});
  const auto add = [&](const Dir3& w, double weight) {
    Sample s{w, {}};
    reader.read(w, s.weighted);
    for (double& v : s.weighted) v *= weight;
    out.push_back(s);
  };
  if (r.source == IrradianceSource::Riemann) {
    const auto n = static_cast<std::uint32_t>(std::max(1.0, std::round(std::sqrt(r.samples / 2.0))));
    for (std::uint32_t j = 0; j < n; ++j) {
      // The row's exact solid angle per cell: (cos th0 - cos th1) dphi = 2 sin(dth/2) sin(thm) dphi.
      const double omega = 2 * std::sin(0.5 * kPi / n) * std::sin(kPi * (j + 0.5) / n) * (kPi / n);
      for (std::uint32_t i = 0; i < 2 * n; ++i)
        add(equirect_direction((i + 0.5) / (2 * n), (j + 0.5) / n), omega / kPi);
    }
  } else {
    std::mt19937_64 rng(r.seed);
    for (std::uint32_t k = 0; k < r.samples; ++k) {
      const double u1 = detail::uniform01(rng), u2 = detail::uniform01(rng);
      add(detail::sphere_point(u1, u2), 4.0 / r.samples);
    }
  }
  return Status::success();
}

Status check_request(const MapImage& map, const IrradianceRequest& r) noexcept {
  const bool sampled = r.source == IrradianceSource::Riemann || r.source == IrradianceSource::MonteCarlo;
  if (sampled && r.samples == 0) return Status::error(Errc::InvalidArgument, "riemann and mc need a sample count >= 1");
  if (sampled && map.layout != Layout::Equirect)
    return Status::error(Errc::InvalidArgument, "riemann and mc read equirect maps only");
  return Status::success();
}

// Runs value(d, rgb, row) for every used texel, rows spread over the threads.
template <class Value>
void fill(const std::vector<Dir3>& dirs, const std::vector<std::uint8_t>& used, std::uint32_t width,
          std::uint32_t height, unsigned threads, IrradianceImage& out, Value&& value) {
  const unsigned workers = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  detail::run_queue(height, workers, [&](std::uint32_t y, unsigned) noexcept {
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      if (used[i]) value(dirs[i], out.rgb.data() + 3 * i, y);
    }
  });
}

// What the finish stage does to the map (pipeline.h), for the sources that read the map
// itself: the value at d is the map's at R^T d (the environment turned by R), mixed by M and
// scaled by the intensity, as Sh gets it from finish_projection.
struct OutputTransform {
  Matrix3 rotation;
  Matrix3 colour;
  double intensity;

  explicit OutputTransform(const FinishOptions& f)
      : rotation(rotation_about_y(f.rotate_deg)),
        colour(f.colour_matrix.value_or(Matrix3{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}})),
        intensity(f.intensity) {}

  Dir3 source_direction(const Dir3& d) const noexcept {  // R^T d
    const Matrix3& r = rotation;
    return {r[0][0] * d.x + r[1][0] * d.y + r[2][0] * d.z, r[0][1] * d.x + r[1][1] * d.y + r[2][1] * d.z,
            r[0][2] * d.x + r[1][2] * d.y + r[2][2] * d.z};
  }
  void store(const double (&v)[3], float* rgb) const noexcept {
    for (int c = 0; c < 3; ++c)
      rgb[c] = static_cast<float>(intensity * (colour[c][0] * v[0] + colour[c][1] * v[1] + colour[c][2] * v[2]));
  }
};

}  // namespace

Status irradiance_directions(Layout layout, std::uint32_t size, std::uint32_t& width, std::uint32_t& height,
                             std::vector<Dir3>& directions, std::vector<std::uint8_t>& used) noexcept {
  const bool cube = is_cube_layout(layout) && layout != Layout::Faces;
  if (layout != Layout::Equirect && !cube)
    return Status::error(Errc::InvalidArgument, "the output layout is equirect, hcross, vcross, hstrip or vstrip");
  const CubeGrid grid = cube ? cube_layout_grid(detail::cube_layout_of(layout)) : CubeGrid{2, 1};
  const std::uint64_t w = std::uint64_t{grid.columns} * size, h = std::uint64_t{grid.rows} * size;
  if (size == 0 || w * h > kMaxOutputTexels)
    return Status::error(Errc::InvalidArgument, "the output size must be at least 1 and the image at most 2^26 texels");
  try {
    std::vector<Dir3> dirs(w * h);
    std::vector<std::uint8_t> in(w * h, cube ? 0 : 1);
    if (!cube) {
      for (std::uint64_t y = 0; y < h; ++y)
        for (std::uint64_t x = 0; x < w; ++x) dirs[y * w + x] = equirect_direction((x + 0.5) / w, (y + 0.5) / h);
    } else {
      for (int f = 0; f < kCubeFaceCount; ++f) {
        const CubeCell cell = cube_layout_cell(detail::cube_layout_of(layout), static_cast<CubeFace>(f));
        for (std::uint32_t y = 0; y < size; ++y)
          for (std::uint32_t x = 0; x < size; ++x) {
            // A rotated cell stores face texel (x, y) at (N-1-x, N-1-y) of the cell (cube_layout.h).
            const std::uint32_t sx = cell.rotated_180 ? size - 1 - x : x, sy = cell.rotated_180 ? size - 1 - y : y;
            const std::uint64_t i = (std::uint64_t{cell.row} * size + sy) * w + std::uint64_t{cell.column} * size + sx;
            dirs[i] = face_direction(static_cast<CubeFace>(f), size, x, y);
            in[i] = 1;
          }
      }
    }
    width = static_cast<std::uint32_t>(w);
    height = static_cast<std::uint32_t>(h);
    directions = std::move(dirs);
    used = std::move(in);
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory for the irradiance image's directions");
  }
}

Status render_irradiance(const MapImage& map, const ConvertOptions& options, const IrradianceRequest& request,
                         IrradianceImage& out) noexcept {
  if (Status st = check_request(map, request); !st.ok()) return st;
  IrradianceImage image;
  std::vector<Dir3> dirs;
  std::vector<std::uint8_t> used;
  if (Status st = irradiance_directions(request.layout, request.size, image.width, image.height, dirs, used); !st.ok())
    return st;
  try {
    image.rgb.assign(std::size_t{3} * image.width * image.height, 0.0f);
    const unsigned threads = request.threads;
    const OutputTransform output(options.finish);
    if (request.source == IrradianceSource::Sh) {
      Conversion conversion;
      if (Status st = convert_map(map, options, conversion); !st.ok()) return st;
      const UnityShaderVectors& shader = conversion.sh.shader;
      fill(dirs, used, image.width, image.height, threads, image, [&](const Dir3& d, float* rgb, std::uint32_t) {
        for (int c = 0; c < 3; ++c)
          rgb[c] = shade_sh9(shader, c, static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z));
      });
    } else if (request.source == IrradianceSource::Exact) {
      ViewReference reference;
      const ProjectOptions project{SamplingMethod::Exact, NonFinite::Zero, options.negative, threads};
      if (Status st = build_view_reference(map, project, reference); !st.ok()) return st;
      std::vector<double> bounds(image.height, 0.0);
      fill(dirs, used, image.width, image.height, threads, image, [&](const Dir3& d, float* rgb, std::uint32_t y) {
        const ReferenceValue v = reference.eval(output.source_direction(d));
        const double e[3] = {v.e_over_pi[0], v.e_over_pi[1], v.e_over_pi[2]};
        output.store(e, rgb);
        // The bound in the output's colours: k |M| bound, per channel (view_error.h).
        for (int c = 0; c < 3; ++c) {
          double b = 0;
          for (int j = 0; j < 3; ++j) b += std::abs(output.colour[c][j]) * v.bound[j];
          bounds[y] = std::max(bounds[y], output.intensity * b);  // one row is one worker's
        }
      });
      image.bound = *std::max_element(bounds.begin(), bounds.end());
    } else {
      std::vector<Sample> samples;
      samples.reserve(request.samples);
      if (Status st = samples_of(map, options, request, samples); !st.ok()) return st;
      fill(dirs, used, image.width, image.height, threads, image, [&](const Dir3& out_d, float* rgb, std::uint32_t) {
        const Dir3 d = output.source_direction(out_d);
        double sum[3] = {};
        for (const Sample& s : samples) {
          const double cosine = std::max(0.0, d.x * s.w.x + d.y * s.w.y + d.z * s.w.z);
          for (int c = 0; c < 3; ++c) sum[c] += s.weighted[c] * cosine;
        }
        output.store(sum, rgb);
      });
    }
    out = std::move(image);
    return Status::success();
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "out of memory for the irradiance image");
  }
}

}  // namespace shpack
