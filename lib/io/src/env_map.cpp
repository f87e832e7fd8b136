#include "shpack/io/env_map.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <new>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "image_open.h"
#include "pixel_encoding.h"

namespace shpack::io {
namespace {

namespace fs = std::filesystem;

// Rows per band: whole tiles, one per worker, within kBandBudgetBytes (at least one tile).
std::uint32_t band_rows(std::uint32_t width, std::uint32_t channels, unsigned threads) {
  const unsigned workers = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t row_bytes = std::size_t{width} * channels * sizeof(float);
  const std::size_t tiles_in_budget = kBandBudgetBytes / (row_bytes * kTileRows);
  const std::size_t tiles = std::clamp<std::size_t>(tiles_in_budget, 1, workers);
  return static_cast<std::uint32_t>(tiles * kTileRows);
}

IoStatus core_error(const fs::path& path, const Status& st) {
  return IoStatus::error(IoErrc::Core, path, st.what);
}

// Fills `out` completely or returns an error (project_env_map keeps `out` untouched then).
IoStatus project_opened(const fs::path& path, OIIO::ImageInput& in, const EnvMapOptions& options,
                        EnvMapProjection& out) {
  const OIIO::ImageSpec& spec = in.spec();
  if (const std::string problem = detail::spec_problem(spec); !problem.empty())
    return IoStatus::error(IoErrc::Unsupported, path, problem);

  EnvMapInfo& info = out.info;
  info.width = static_cast<std::uint32_t>(spec.width);
  info.height = static_cast<std::uint32_t>(spec.height);
  info.channels = static_cast<std::uint32_t>(spec.nchannels);
  info.format = in.format_name();
  info.layout = resolve_layout(options.layout, info.width, info.height);
  if (info.layout == Layout::Auto) {
    return IoStatus::error(IoErrc::UnknownLayout, path,
                           "the layout of a " + std::to_string(info.width) + "x" +
                               std::to_string(info.height) +
                               " image cannot be detected (2:1 is equirect, 1x1 is uniform)");
  }
  // Grey (+ alpha) is read as its one grey channel; anything else as R, G, B.
  const std::uint32_t used = info.channels >= 3 ? 3 : 1;
  info.ignored_channels = info.channels - used;
  info.srgb_decoded = detail::pixel_transfer(spec, info.format) == detail::Transfer::Srgb;

  // NaN/Inf texels are always counted and zeroed here, and the Error policy applied once
  // the whole image is seen, so the message can say how many there are.
  ProjectOptions project = options.project;
  project.nonfinite = NonFinite::Zero;
  in.threads(static_cast<int>(project.threads));

  EquirectProjector projector;
  if (Status st = projector.begin(info.width, info.height, project); !st.ok())
    return core_error(path, st);
  const std::uint32_t rows_per_band = band_rows(info.width, used, project.threads);
  std::vector<float> band(std::size_t{info.width} * used * std::min(rows_per_band, info.height));
  for (std::uint32_t first = 0; first < info.height; first += rows_per_band) {
    const std::uint32_t count = std::min(rows_per_band, info.height - first);
    const int y_begin = spec.y + static_cast<int>(first);
    if (!in.read_scanlines(0, 0, y_begin, y_begin + static_cast<int>(count), spec.z, 0,
                           static_cast<int>(used), OIIO::TypeDesc::FLOAT, band.data())) {
      return IoStatus::error(IoErrc::Unreadable, path,
                             "cannot read rows " + std::to_string(first) + ".." +
                                 std::to_string(first + count - 1) + " (" + in.geterror() + ")");
    }
    const std::span<float> values(band.data(), std::size_t{info.width} * used * count);
    if (info.srgb_decoded) detail::decode_srgb(values);
    const ImageView view = make_view(values.data(), info.width, count, used);
    if (Status st = projector.add_rows(view, first); !st.ok()) return core_error(path, st);
  }
  if (Status st = projector.finish(out.radiance, &out.stats); !st.ok()) return core_error(path, st);

  if (options.project.nonfinite == NonFinite::Error && out.stats.nonfinite_texels != 0) {
    return IoStatus::error(IoErrc::NonFiniteTexel, path,
                           std::to_string(out.stats.nonfinite_texels) +
                               " NaN/Inf texels (first at x=" +
                               std::to_string(out.stats.first_nonfinite_x) +
                               ", y=" + std::to_string(out.stats.first_nonfinite_y) + ")");
  }
  return IoStatus::success();
}

}  // namespace

IoStatus project_env_map(const fs::path& path, const EnvMapOptions& options, EnvMapProjection& out) {
  try {
    std::unique_ptr<OIIO::ImageInput> in;
    if (IoStatus st = detail::open_image(path, in); !st.ok()) return st;
    EnvMapProjection result;
    if (IoStatus st = project_opened(path, *in, options, result); !st.ok()) return st;
    out = std::move(result);
    return IoStatus::success();
  } catch (const std::bad_alloc&) {
    return IoStatus::error(IoErrc::Unreadable, path, "out of memory while reading");
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Unreadable, path, e.what());
  }
}

}  // namespace shpack::io
