#include "image_source.h"

#include <algorithm>
#include <cstring>
#include <span>

#include "image_open.h"
#include "pixel_encoding.h"

namespace shpack::io::detail {
namespace {

int find_channel(const OIIO::ImageSpec& spec, const std::string& name) {
  const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
  return it == spec.channelnames.end() ? -1 : static_cast<int>(it - spec.channelnames.begin());
}

// Channels prefix+"R", "G", "B" (used = 3) or prefix+"Y" (used = 1) of `spec`, or false.
bool named_channels(const OIIO::ImageSpec& spec, const std::string& prefix, std::array<int, 3>& channel,
                    std::uint32_t& used) {
  const int r = find_channel(spec, prefix + "R"), g = find_channel(spec, prefix + "G"),
            b = find_channel(spec, prefix + "B");
  if (r >= 0 && g >= 0 && b >= 0) {
    channel = {r, g, b};
    used = 3;
    return true;
  }
  if (const int y = find_channel(spec, prefix + "Y"); y >= 0) {
    channel = {y, y, y};
    used = 1;
    return true;
  }
  return false;
}

// The channel names of `spec` in file order, for messages (at most 16, then how many).
std::string channel_list(const OIIO::ImageSpec& spec) {
  constexpr std::size_t kShown = 16;
  std::string list;
  const std::size_t count = spec.channelnames.size();
  for (std::size_t k = 0; k < std::min(count, kShown); ++k) {
    const std::string& n = spec.channelnames[k];
    list += (k == 0 ? "" : ", ") + (n.empty() ? std::string("an unnamed channel") : n.substr(0, 64));
  }
  if (count > kShown) list += ", ... (" + std::to_string(count) + " channels)";
  return list.empty() ? "no channels" : list;
}

// The colour channels of a part without a layer prefix: R, G, B, else Y, else its only
// channel if that is unnamed. Else the problem, naming the channels the part has; "" when
// the part has layered names instead (the caller lists the layers).
std::string unprefixed_channels(const OIIO::ImageSpec& spec, bool layered, std::array<int, 3>& channel,
                                std::uint32_t& used, bool& found) {
  found = named_channels(spec, "", channel, used);
  if (found) return {};
  std::string missing;
  bool some = false;
  for (const char* name : {"R", "G", "B"}) {
    if (find_channel(spec, name) >= 0)
      some = true;
    else
      missing += (missing.empty() ? "" : ", ") + std::string(name);
  }
  if (some)
    return "incomplete colour channels: no " + missing + " (R, G and B, or Y, are read); it has " + channel_list(spec);
  if (layered) return {};
  if (spec.nchannels == 1 && spec.channelnames.size() <= 1 &&
      (spec.channelnames.empty() || spec.channelnames[0].empty())) {
    channel = {0, 0, 0};
    used = 1;
    found = true;
    return {};
  }
  return "no colour channels (R, G, B or Y); it has " + channel_list(spec);
}

bool has_layered_names(const OIIO::ImageSpec& spec) {
  return std::any_of(spec.channelnames.begin(), spec.channelnames.end(),
                     [](const std::string& n) { return n.find('.') != std::string::npos; });
}

// The layers a file offers, for messages: part names, then channel prefixes ("diffuse" of
// "diffuse.R"), each once, in file order.
std::string layer_list(OIIO::ImageInput& in) {
  std::vector<std::string> names;
  const auto add = [&](const std::string& n) {
    if (!n.empty() && std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  };
  for (int s = 0;; ++s) {
    const OIIO::ImageSpec spec = in.spec(s);
    if (spec.format == OIIO::TypeUnknown) break;
    add(spec.get_string_attribute("oiio:subimagename"));
    for (const std::string& c : spec.channelnames)
      if (const auto dot = c.rfind('.'); dot != std::string::npos) add(c.substr(0, dot));
  }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list.empty() ? "none" : list;
}

}  // namespace

IoStatus ImageSource::open(const std::filesystem::path& path, const std::string& layer, const TexelBudget& budget) {
  path_ = path;
  if (IoStatus st = open_image(path, budget, in_, png_); !st.ok()) return st;
  format_ = in_->format_name();

  // Choose the subimage and channels.
  bool found = false;
  if (layer.empty()) {
    spec_ = in_->spec(0);
    subimage_ = 0;
    const bool layered = has_layered_names(spec_);
    if (const std::string problem = unprefixed_channels(spec_, layered, channel_, used_, found); !problem.empty())
      return IoStatus::error(IoErrc::Unsupported, path, problem);
    if (!found && spec_.nchannels > 0) {
      return IoStatus::error(IoErrc::Unsupported, path,
                             "the image has no R, G, B or Y channels; its layers are " + layer_list(*in_) +
                                 " (--layer chooses one)");
    }
  } else {
    for (int s = 0; !found; ++s) {  // a part of that name
      const OIIO::ImageSpec spec = in_->spec(s);
      if (spec.format == OIIO::TypeUnknown) break;
      if (spec.get_string_attribute("oiio:subimagename") != layer) continue;
      spec_ = spec;
      subimage_ = s;
      const bool layered = has_layered_names(spec_);
      if (const std::string problem = unprefixed_channels(spec_, layered, channel_, used_, found); !problem.empty())
        return IoStatus::error(IoErrc::Unsupported, path, "part '" + layer + "': " + problem);
    }
    for (int s = 0; !found; ++s) {  // channels layer.R, layer.G, layer.B
      const OIIO::ImageSpec spec = in_->spec(s);
      if (spec.format == OIIO::TypeUnknown) break;
      if (named_channels(spec, layer + ".", channel_, used_)) {
        spec_ = spec;
        subimage_ = s;
        found = true;
      }
    }
    if (!found) {
      return IoStatus::error(IoErrc::Unsupported, path,
                             "no layer '" + layer + "' (its layers are " + layer_list(*in_) + ")");
    }
  }
  if (const std::string problem = spec_problem(spec_); !problem.empty())
    return IoStatus::error(IoErrc::Unsupported, path, problem);
  // The budget, from the header: the display window (what is held) and the data window
  // (what is decoded), before anything is allocated for either.
  {
    const bool has_display = spec_.full_width > 0 && spec_.full_height > 0;
    std::string problem = budget_problem("the image", has_display ? spec_.full_width : spec_.width,
                                         has_display ? spec_.full_height : spec_.height, budget);
    if (problem.empty()) problem = budget_problem("the data window", spec_.width, spec_.height, budget);
    if (!problem.empty()) return IoStatus::error(IoErrc::Unsupported, path, problem);
  }

  // The display window; OpenImageIO fills it with the data window for formats without one.
  width_ = static_cast<std::uint32_t>(spec_.full_width > 0 ? spec_.full_width : spec_.width);
  height_ = static_cast<std::uint32_t>(spec_.full_height > 0 ? spec_.full_height : spec_.height);
  if (spec_.full_width <= 0 || spec_.full_height <= 0) {
    spec_.full_x = spec_.x;
    spec_.full_y = spec_.y;
  }
  file_channels_ = static_cast<std::uint32_t>(spec_.nchannels);
  first_channel_ = *std::min_element(channel_.begin(), channel_.begin() + used_);
  last_channel_ = *std::max_element(channel_.begin(), channel_.begin() + used_) + 1;
  srgb_ = !spec_.channelformat(channel_[0]).is_floating_point() &&
          pixel_transfer(spec_, format_) == Transfer::Srgb;
  if (const OIIO::ParamValue* p = spec_.find_attribute("chromaticities");
      p != nullptr && p->type().basetype == OIIO::TypeDesc::FLOAT && p->type().numelements() * p->type().aggregate == 8) {
    std::array<double, 8> c{};
    for (int k = 0; k < 8; ++k) c[k] = static_cast<const float*>(p->data())[k];
    chromaticities_ = c;
  }
  return IoStatus::success();
}

IoStatus ImageSource::read_rows(std::uint32_t first, std::uint32_t count, float* out) {
  const std::size_t out_values = std::size_t{count} * width_ * used_;
  // Display rows first.. and the data rows they overlap.
  const long long y_begin = std::max<long long>(spec_.full_y + static_cast<long long>(first), spec_.y);
  const long long y_end = std::min<long long>(spec_.full_y + static_cast<long long>(first) + count,
                                              static_cast<long long>(spec_.y) + spec_.height);
  const long long x_begin = std::max(spec_.full_x, spec_.x);
  const long long x_end = std::min<long long>(static_cast<long long>(spec_.full_x) + width_,
                                              static_cast<long long>(spec_.x) + spec_.width);
  const int range = last_channel_ - first_channel_;
  const bool in_place = spec_.tile_width == 0 && spec_.x == spec_.full_x && spec_.y == spec_.full_y &&
                        static_cast<std::uint32_t>(spec_.width) == width_ &&
                        static_cast<std::uint32_t>(spec_.height) == height_ && range == static_cast<int>(used_) &&
                        (used_ == 1 || (channel_[1] == channel_[0] + 1 && channel_[2] == channel_[0] + 2));
  const auto read_error = [&] {
    return IoStatus::error(IoErrc::Unreadable, path_,
                           with_reason("cannot read rows " + std::to_string(first) + ".." +
                                           std::to_string(first + count - 1),
                                       in_->geterror()));
  };
  const QuietLibpng quiet(png_);
  if (in_place) {
    if (!in_->read_scanlines(subimage_, 0, static_cast<int>(y_begin), static_cast<int>(y_end), spec_.z,
                             first_channel_, last_channel_, OIIO::TypeDesc::FLOAT, out))
      return read_error();
  } else {
    std::fill(out, out + out_values, 0.0f);  // outside the data window: black
    if (y_begin < y_end && x_begin < x_end) {
      const std::size_t data_row = std::size_t(spec_.width) * range;
      // Tiled files are read by whole tile rows (OpenImageIO 2.4's read_scanlines fails on
      // tiled files whose data window is offset); the rows wanted start `skip` rows in.
      long long band_begin = y_begin, band_end = y_end;
      if (spec_.tile_width != 0) {
        const long long th = spec_.tile_height;
        band_begin = spec_.y + (y_begin - spec_.y) / th * th;
        band_end = std::min<long long>(spec_.y + (y_end - spec_.y + th - 1) / th * th,
                                       static_cast<long long>(spec_.y) + spec_.height);
      }
      scratch_.resize(data_row * static_cast<std::size_t>(band_end - band_begin));
      const bool read =
          spec_.tile_width != 0
              ? in_->read_tiles(subimage_, 0, spec_.x, spec_.x + spec_.width, static_cast<int>(band_begin),
                                static_cast<int>(band_end), spec_.z, spec_.z + std::max(1, spec_.depth),
                                first_channel_, last_channel_, OIIO::TypeDesc::FLOAT, scratch_.data())
              : in_->read_scanlines(subimage_, 0, static_cast<int>(y_begin), static_cast<int>(y_end), spec_.z,
                                    first_channel_, last_channel_, OIIO::TypeDesc::FLOAT, scratch_.data());
      if (!read) return read_error();
      for (long long y = y_begin; y < y_end; ++y) {
        const float* src = scratch_.data() + data_row * static_cast<std::size_t>(y - band_begin);
        float* dst = out + std::size_t(y - spec_.full_y - first) * width_ * used_;
        for (long long x = x_begin; x < x_end; ++x)
          for (std::uint32_t k = 0; k < used_; ++k)
            dst[std::size_t(x - spec_.full_x) * used_ + k] =
                src[std::size_t(x - spec_.x) * range + static_cast<std::size_t>(channel_[k] - first_channel_)];
      }
    }
  }
  if (srgb_) decode_srgb(std::span<float>(out, out_values));
  return IoStatus::success();
}

}  // namespace shpack::io::detail
