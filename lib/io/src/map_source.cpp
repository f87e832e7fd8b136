#include "shpack/io/map_source.h"

#include <algorithm>
#include <new>
#include <string>
#include <thread>
#include <utility>

#include "image_source.h"

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
  return IoStatus::error(st.code == Errc::InvalidArgument ? IoErrc::InvalidArgument : IoErrc::Core, path, st.what);
}

// The colour space of the source (colorspace.h), or the error naming `path`.
IoStatus resolve_colour(const fs::path& path, ColorSpace requested, const std::optional<Chromaticities>& file,
                        ColourResolution& out) {
  std::string problem;
  if (!resolve_colorspace(requested, file, out, problem))
    return IoStatus::error(IoErrc::Unsupported, path, problem + "; --colorspace can name the primaries");
  return IoStatus::success();
}

template <class Work>
IoStatus guarded(const fs::path& path, Work work) {
  try {
    return work();
  } catch (const std::bad_alloc&) {
    return IoStatus::error(IoErrc::Unreadable, path, "out of memory while reading");
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Unreadable, path, e.what());
  }
}

}  // namespace

MapSource::MapSource() = default;
MapSource::~MapSource() = default;

const fs::path& MapSource::path(std::uint32_t face) const noexcept {
  return info_.layout == Layout::Faces && face < kCubeFaceCount ? paths_[face] : paths_[0];
}

IoStatus MapSource::open(const fs::path& path, const SourceOptions& options) {
  return guarded(path, [&] {
    auto image = std::make_unique<detail::ImageSource>();
    if (IoStatus st = image->open(path, options.layer, detail::TexelBudget{options.max_texels, 1}); !st.ok()) return st;
    SourceInfo info;
    info.width = image->width();
    info.height = image->height();
    info.channels = image->file_channels();
    info.ignored_channels = image->ignored_channels();
    info.format = image->format();
    info.srgb_decoded = image->srgb_decoded();
    if (const std::string problem = layout_shape_problem(options.layout, info.width, info.height); !problem.empty())
      return IoStatus::error(IoErrc::UnknownLayout, path, problem);
    info.layout = resolve_layout(options.layout, info.width, info.height);
    if (info.layout == Layout::Faces)
      return IoStatus::error(IoErrc::InvalidArgument, path, "the faces layout takes six files, not one image");
    if (IoStatus st = resolve_colour(path, options.colorspace, image->chromaticities(), info.colour); !st.ok())
      return st;
    paths_ = {path};
    info_ = std::move(info);
    cube_frame_ = options.cube_frame;
    image_ = std::move(image);
    return IoStatus::success();
  });
}

IoStatus MapSource::open_faces(const std::array<fs::path, kCubeFaceCount>& paths, const SourceOptions& options) {
  std::array<ImageFile, kCubeFaceCount> files;
  for (std::uint32_t f = 0; f < kCubeFaceCount; ++f) {
    const fs::path& path = paths[f];
    if (IoStatus st = detail::read_image_file(path, options.layer, detail::TexelBudget{options.max_texels, kCubeFaceCount}, files[f]); !st.ok()) return st;
    const ImageFile& face = files[f];
    const std::string size = std::to_string(face.width) + "x" + std::to_string(face.height);
    if (face.width != face.height)
      return IoStatus::error(IoErrc::Unsupported, path, "the face is " + size + ", not square");
    if (face.width != files[0].width) {
      return IoStatus::error(IoErrc::Unsupported, path,
                             "the face is " + size + " but " + paths[0].filename().string() + " is " +
                                 std::to_string(files[0].width) + "x" + std::to_string(files[0].height));
    }
    if (face.chromaticities != files[0].chromaticities) {
      return IoStatus::error(IoErrc::Unsupported, path,
                             "the face's chromaticities differ from those of " + paths[0].filename().string());
    }
  }
  SourceInfo info;
  info.width = info.height = files[0].width;
  info.layout = Layout::Faces;
  info.format = files[0].format;
  for (const ImageFile& face : files) {
    info.channels += face.file_channels;
    info.ignored_channels += face.ignored_channels();
    info.srgb_decoded = info.srgb_decoded || face.srgb_decoded;
  }
  if (IoStatus st = resolve_colour(paths[0], options.colorspace, files[0].chromaticities, info.colour); !st.ok())
    return st;
  paths_ = paths;
  info_ = std::move(info);
  cube_frame_ = options.cube_frame;
  faces_ = std::move(files);
  return IoStatus::success();
}

IoStatus MapSource::stream_into(EquirectProjector& projector, ViewReference& reference, unsigned threads) {
  const fs::path& file = paths_[0];
  return guarded(file, [&] {
    image_->set_threads(threads);
    const std::uint32_t used = image_->channels();
    const std::uint32_t rows_per_band = band_rows(info_.width, used, threads);
    std::vector<float> band(std::size_t{info_.width} * used * std::min(rows_per_band, info_.height));
    for (std::uint32_t first = 0; first < info_.height; first += rows_per_band) {
      const std::uint32_t count = std::min(rows_per_band, info_.height - first);
      if (IoStatus st = image_->read_rows(first, count, band.data()); !st.ok()) return st;
      const ImageView view = make_view(band.data(), info_.width, count, used);
      if (Status st = projector.add_rows(view, first); !st.ok()) return core_error(file, st);
      if (Status st = reference.add_rows(view, first); !st.ok()) return core_error(file, st);
    }
    return IoStatus::success();
  });
}

IoStatus MapSource::read_whole(MapImage& map, unsigned threads) {
  MapImage whole;
  whole.layout = info_.layout;
  whole.cube_frame = cube_frame_;
  if (info_.layout == Layout::Faces) {
    for (std::uint32_t f = 0; f < kCubeFaceCount; ++f) whole.faces[f] = faces_[f].view();
    map = whole;
    return IoStatus::success();
  }
  return guarded(paths_[0], [&] {
    image_->set_threads(threads);
    pixels_.resize(std::size_t{info_.width} * info_.height * image_->channels());
    if (IoStatus st = image_->read_rows(0, info_.height, pixels_.data()); !st.ok()) return st;
    whole.image = make_view(pixels_.data(), info_.width, info_.height, image_->channels());
    whole.writable = pixels_.data();
    map = whole;
    return IoStatus::success();
  });
}

}  // namespace shpack::io
