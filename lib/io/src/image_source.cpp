#include "image_source.h"

#include <algorithm>
#include <span>

#include "image_open.h"
#include "pixel_encoding.h"

namespace shpack::io::detail {
namespace {

int find_channel(const ImagePart& part, const std::string& name) {
  const auto it = std::find(part.channels.begin(), part.channels.end(), name);
  return it == part.channels.end() ? -1 : static_cast<int>(it - part.channels.begin());
}

// Channels prefix+"R", "G", "B" (used = 3) or prefix+"Y" (used = 1) of `part`, or false.
bool named_channels(const ImagePart& part, const std::string& prefix, std::array<int, 3>& channel,
                    std::uint32_t& used) {
  const int r = find_channel(part, prefix + "R"), g = find_channel(part, prefix + "G"),
            b = find_channel(part, prefix + "B");
  if (r >= 0 && g >= 0 && b >= 0) {
    channel = {r, g, b};
    used = 3;
    return true;
  }
  if (const int y = find_channel(part, prefix + "Y"); y >= 0) {
    channel = {y, y, y};
    used = 1;
    return true;
  }
  return false;
}

// The channel names of `part` in file order, for messages (at most 16, then how many).
std::string channel_list(const ImagePart& part) {
  constexpr std::size_t kShown = 16;
  std::string list;
  const std::size_t count = part.channels.size();
  for (std::size_t k = 0; k < std::min(count, kShown); ++k) {
    const std::string& n = part.channels[k];
    list += (k == 0 ? "" : ", ") + (n.empty() ? std::string("an unnamed channel") : n.substr(0, 64));
  }
  if (count > kShown) list += ", ... (" + std::to_string(count) + " channels)";
  return list.empty() ? "no channels" : list;
}

// The colour channels of a part without a layer prefix: R, G, B, else Y, else its only
// channel if that is unnamed. Else the problem, naming the channels the part has; "" when
// the part has layered names instead (the caller lists the layers).
std::string unprefixed_channels(const ImagePart& part, bool layered, std::array<int, 3>& channel,
                                std::uint32_t& used, bool& found) {
  found = named_channels(part, "", channel, used);
  if (found) return {};
  std::string missing;
  bool some = false;
  for (const char* name : {"R", "G", "B"}) {
    if (find_channel(part, name) >= 0)
      some = true;
    else
      missing += (missing.empty() ? "" : ", ") + std::string(name);
  }
  if (some)
    return "incomplete colour channels: no " + missing + " (R, G and B, or Y, are read); it has " + channel_list(part);
  if (layered) return {};
  if (part.channels.size() == 1 && part.channels[0].empty()) {
    channel = {0, 0, 0};
    used = 1;
    found = true;
    return {};
  }
  return "no colour channels (R, G, B or Y); it has " + channel_list(part);
}

bool has_layered_names(const ImagePart& part) {
  return std::any_of(part.channels.begin(), part.channels.end(),
                     [](const std::string& n) { return n.find('.') != std::string::npos; });
}

// The layers a file offers, for messages: part names, then channel prefixes ("diffuse" of
// "diffuse.R"), each once, in file order.
std::string layer_list(const std::vector<ImagePart>& parts) {
  std::vector<std::string> names;
  const auto add = [&](const std::string& n) {
    if (!n.empty() && std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  };
  for (const ImagePart& part : parts) {
    add(part.name);
    for (const std::string& c : part.channels)
      if (const auto dot = c.rfind('.'); dot != std::string::npos) add(c.substr(0, dot));
  }
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list.empty() ? "none" : list;
}

}  // namespace

IoStatus ImageSource::open(const std::filesystem::path& path, const std::string& layer, const TexelBudget& budget) {
  path_ = path;
  if (IoStatus st = open_image(path, budget, decoder_); !st.ok()) return st;
  format_ = decoder_->format();
  const std::vector<ImagePart>& parts = decoder_->parts();
  if (parts.empty()) return IoStatus::error(IoErrc::Unreadable, path, "the file holds no image");

  // Choose the part and channels.
  bool found = false;
  if (layer.empty()) {
    part_ = 0;
    const bool layered = has_layered_names(parts[0]);
    if (const std::string problem = unprefixed_channels(parts[0], layered, channel_, used_, found); !problem.empty())
      return IoStatus::error(IoErrc::Unsupported, path, problem);
    if (!found && !parts[0].channels.empty()) {
      return IoStatus::error(IoErrc::Unsupported, path,
                             "the image has no R, G, B or Y channels; its layers are " + layer_list(parts) +
                                 " (--layer chooses one)");
    }
  } else {
    for (std::size_t p = 0; p < parts.size() && !found; ++p) {  // a part of that name
      if (parts[p].name != layer) continue;
      part_ = p;
      const bool layered = has_layered_names(parts[p]);
      if (const std::string problem = unprefixed_channels(parts[p], layered, channel_, used_, found); !problem.empty())
        return IoStatus::error(IoErrc::Unsupported, path, "part '" + layer + "': " + problem);
    }
    for (std::size_t p = 0; p < parts.size() && !found; ++p) {  // channels layer.R, layer.G, layer.B
      if (named_channels(parts[p], layer + ".", channel_, used_)) {
        part_ = p;
        found = true;
      }
    }
    if (!found) {
      return IoStatus::error(IoErrc::Unsupported, path,
                             "no layer '" + layer + "' (its layers are " + layer_list(parts) + ")");
    }
  }
  const ImagePart& part = parts[part_];
  if (const std::string problem = part_problem(part); !problem.empty())
    return IoStatus::error(IoErrc::Unsupported, path, problem);
  // The budget, from the header: the display window (what is held) and the data window
  // (what is decoded), before anything is allocated for either.
  {
    std::string problem = budget_problem("the image", part.display.width, part.display.height, budget);
    if (problem.empty()) problem = budget_problem("the data window", part.data.width, part.data.height, budget);
    if (!problem.empty()) return IoStatus::error(IoErrc::Unsupported, path, problem);
  }
  data_ = part.data;
  display_ = part.display;
  width_ = static_cast<std::uint32_t>(display_.width);
  height_ = static_cast<std::uint32_t>(display_.height);
  file_channels_ = static_cast<std::uint32_t>(part.channels.size());
  srgb_ = part.srgb;
  chromaticities_ = part.chromaticities;
  return IoStatus::success();
}

IoStatus ImageSource::read_rows(std::uint32_t first, std::uint32_t count, float* out) {
  const std::size_t out_values = std::size_t{count} * width_ * used_;
  // Display rows first.. and the data rows they overlap.
  const long long y_begin = std::max(display_.y + first, data_.y);
  const long long y_end = std::min(display_.y + first + count, data_.y + data_.height);
  const long long x_begin = std::max(display_.x, data_.x);
  const long long x_end = std::min(display_.x + display_.width, data_.x + data_.width);
  const std::span<const int> channels(channel_.data(), used_);
  std::string reason;
  const auto read_error = [&] {
    return IoStatus::error(IoErrc::Unreadable, path_,
                           with_reason("cannot read rows " + std::to_string(first) + ".." +
                                           std::to_string(first + count - 1),
                                       reason));
  };
  if (data_ == display_) {
    if (!decoder_->read_rows(part_, y_begin, y_end, channels, out, reason)) return read_error();
  } else {
    std::fill(out, out + out_values, 0.0f);  // outside the data window: black
    if (y_begin < y_end && x_begin < x_end) {
      const std::size_t data_row = static_cast<std::size_t>(data_.width) * used_;
      scratch_.resize(data_row * static_cast<std::size_t>(y_end - y_begin));
      if (!decoder_->read_rows(part_, y_begin, y_end, channels, scratch_.data(), reason)) return read_error();
      for (long long y = y_begin; y < y_end; ++y) {
        const float* src = scratch_.data() + data_row * static_cast<std::size_t>(y - y_begin) +
                           static_cast<std::size_t>(x_begin - data_.x) * used_;
        float* dst = out + static_cast<std::size_t>(y - display_.y - first) * width_ * used_ +
                     static_cast<std::size_t>(x_begin - display_.x) * used_;
        std::copy(src, src + static_cast<std::size_t>(x_end - x_begin) * used_, dst);
      }
    }
  }
  if (srgb_) decode_srgb(std::span<float>(out, out_values));
  return IoStatus::success();
}

}  // namespace shpack::io::detail
