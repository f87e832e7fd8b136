#include "hdr_decoder.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rgbe_scanline.h"
#include "shpack/io/quoted.h"

namespace shpack::io::detail {
namespace {

constexpr std::size_t kMaxHeaderBytes = std::size_t{64} << 10;
constexpr std::uint64_t kMinScanlineBytes = 4;  // one record, or the new-style mark
constexpr long long kMaxSize = 2147483647;      // 2^31 - 1: Radiance keeps sizes in an int

// The resolution string's ordering [resolu.h]: which axis the scanlines run along and which
// way each axis goes, in Radiance's y-up picture.
struct Resolution {
  bool y_major = true;        // scanlines are rows ("-Y H +X W"), else columns ("+X W -Y H")
  bool x_decreasing = false;  // "-X": pixels (or columns) from the right
  bool y_decreasing = true;   // "-Y": rows (or pixels) from the top
  long long width = 0, height = 0;

  long long scanlines() const { return y_major ? height : width; }
  long long scanline_length() const { return y_major ? width : height; }
};

struct Header {
  Resolution resolution;
  std::uint64_t data_offset = 0;  // the first scanline's
};

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// Splits `line` at blanks.
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t at = 0; at < line.size();) {
    at = line.find_first_not_of(" \t", at);
    if (at == std::string_view::npos) break;
    const std::size_t end = std::min(line.size(), line.find_first_of(" \t", at));
    out.push_back(line.substr(at, end - at));
    at = end;
  }
  return out;
}

// A size: decimal digits, 1 ... kMaxSize; else -1.
long long parse_size(std::string_view digits) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  return ec == std::errc() && end == digits.data() + digits.size() && v >= 1 && v <= kMaxSize ? v : -1;
}

// "-Y H +X W" and its seven other orderings [str2resolu]; false if `line` is none of them.
bool parse_resolution(std::string_view line, Resolution& out) {
  const std::vector<std::string_view> w = words(trim(line));
  if (w.size() != 4) return false;
  const auto axis = [](std::string_view a) {
    return a.size() == 2 && (a[0] == '-' || a[0] == '+') && (a[1] == 'X' || a[1] == 'Y');
  };
  if (!axis(w[0]) || !axis(w[2]) || w[0][1] == w[2][1]) return false;
  const long long first = parse_size(w[1]), second = parse_size(w[3]);
  if (first < 0 || second < 0) return false;
  const std::string_view x = w[0][1] == 'X' ? w[0] : w[2], y = w[0][1] == 'Y' ? w[0] : w[2];
  out.y_major = w[0][1] == 'Y';
  out.x_decreasing = x[0] == '-';
  out.y_decreasing = y[0] == '-';
  out.width = out.y_major ? second : first;
  out.height = out.y_major ? first : second;
  return true;
}

// The problem with a FORMAT line's value, or "".
std::string format_problem(std::string_view value) {
  if (value == "32-bit_rle_rgbe") return {};
  if (value == "32-bit_rle_xyze")
    return "the Radiance header says FORMAT=32-bit_rle_xyze (CIE XYZ pixels), which shpack does not read: only "
           "32-bit_rle_rgbe";
  std::string problem = "the Radiance header's FORMAT ";
  problem += quoted(value);
  problem += " is not 32-bit_rle_rgbe";
  return problem;
}

// Reads the header and the resolution string from the file's first bytes `head`.
IoStatus parse_header(const std::filesystem::path& path, std::string_view head, std::uint64_t file_size, Header& out) {
  const auto unreadable = [&](const std::string& problem) {
    return IoStatus::error(IoErrc::Unreadable, path, problem);
  };
  const bool whole = head.size() == file_size;
  const auto cut_short = [&](const char* what) {
    std::string problem =
        whole ? "the file ends inside the Radiance header, before its " : "the Radiance header has no ";
    problem += what;
    if (!whole) problem += " in the file's first 65536 bytes";
    return unreadable(problem);
  };
  if (!is_radiance_magic(head))
    return unreadable("not a Radiance picture: it does not start with #?RADIANCE or #?RGBE");
  std::size_t at = head.find('\n');  // the end of the magic line
  if (at == std::string_view::npos) return cut_short("blank line");
  for (;;) {
    const std::size_t end = head.find('\n', at + 1);
    if (end == std::string_view::npos) return cut_short("blank line");
    const std::string_view line = trim(head.substr(at + 1, end - at - 1));
    at = end;
    if (line.empty()) break;
    if (Resolution ignored; parse_resolution(line, ignored)) {
      std::string problem = "the Radiance header has no blank line before its resolution string ";
      problem += quoted(line);
      return unreadable(problem);
    }
    if (line.rfind("FORMAT=", 0) == 0) {
      if (std::string problem = format_problem(trim(line.substr(7))); !problem.empty())
        return IoStatus::error(IoErrc::Unsupported, path, problem);
    }
  }
  const std::size_t end = head.find('\n', at + 1);
  if (end == std::string_view::npos) return cut_short("resolution string");
  const std::string_view line = head.substr(at + 1, end - at - 1);
  if (!parse_resolution(line, out.resolution)) {
    std::string problem = "the Radiance resolution string ";
    problem += quoted(trim(line));
    problem += " is not of the form '-Y height +X width' (or another ordering of the axes)";
    return unreadable(problem);
  }
  out.data_offset = end + 1;
  return IoStatus::success();
}

class HdrDecoder final : public ImageDecoder {
 public:
  HdrDecoder(FileBytes file, const Header& header)
      : file_(std::move(file)), stream_(file_), res_(header.resolution), offsets_{header.data_offset} {
    ImagePart part;
    part.channels = {"R", "G", "B"};
    part.data = part.display = {0, 0, res_.width, res_.height};
    parts_.push_back(std::move(part));
  }
  HdrDecoder(const HdrDecoder&) = delete;
  HdrDecoder& operator=(const HdrDecoder&) = delete;

  const std::string& format() const noexcept override { return format_; }
  const std::vector<ImagePart>& parts() const noexcept override { return parts_; }
  void set_threads(unsigned) override {}  // RLE scanlines decode in sequence, on the caller's thread

  bool read_rows(std::size_t, long long y_begin, long long y_end, std::span<const int> channels, float* out,
                 std::string& error) override {
    return res_.y_major ? read_row_scanlines(y_begin, y_end, channels, out, error)
                        : read_column_scanlines(y_begin, y_end, channels, out, error);
  }

 private:
  // Decodes scanline `s` into rgb_ (3 floats a pixel), from its known offset; the scanlines
  // before it are decoded first if their offsets are not known yet.
  bool scanline(long long s, std::string& error) {
    const std::size_t index = static_cast<std::size_t>(s);
    while (offsets_.size() <= index)
      if (!decode(offsets_.size() - 1, error)) return false;
    if (!decode(index, error)) return false;
    rgb_.resize(3 * static_cast<std::size_t>(res_.scanline_length()));
    rgbe_to_float(rgbe_, rgb_.data());
    return true;
  }

  // Decodes scanline `s`, whose offset is known, into rgbe_, and keeps the next one's offset.
  bool decode(std::size_t s, std::string& error) {
    rgbe_.resize(4 * static_cast<std::size_t>(res_.scanline_length()));
    stream_.seek(offsets_[s]);
    std::string problem;
    if (!read_rgbe_scanline(stream_, rgbe_, problem)) {
      error = "scanline ";
      error += std::to_string(s);
      error += " of ";
      error += std::to_string(res_.scanlines());
      error += ": ";
      error += problem;
      return false;
    }
    if (s + 1 == offsets_.size() && offsets_.size() < static_cast<std::size_t>(res_.scanlines()))
      offsets_.push_back(stream_.tell());
    return true;
  }

  // Rows stored as scanlines: rows [y_begin, y_end) are one run of scanlines, decoded in
  // file order whichever way the rows go.
  bool read_row_scanlines(long long y_begin, long long y_end, std::span<const int> channels, float* out,
                          std::string& error) {
    const long long h = res_.height, w = res_.width;
    const long long first = res_.y_decreasing ? y_begin : h - y_end;
    const long long last = res_.y_decreasing ? y_end : h - y_begin;
    const std::size_t k = channels.size();
    for (long long s = first; s < last; ++s) {
      if (!scanline(s, error)) return false;
      const long long y = res_.y_decreasing ? s : h - 1 - s;
      float* row = out + static_cast<std::size_t>((y - y_begin) * w) * k;
      for (long long x = 0; x < w; ++x) {
        const float* texel = rgb_.data() + 3 * static_cast<std::size_t>(res_.x_decreasing ? w - 1 - x : x);
        for (std::size_t c = 0; c < k; ++c) row[static_cast<std::size_t>(x) * k + c] = texel[channels[c]];
      }
    }
    return true;
  }

  // Columns stored as scanlines: the image is decoded whole once, after every scanline has
  // been checked (so a truncated file allocates nothing), and rows are copied from it.
  bool read_column_scanlines(long long y_begin, long long y_end, std::span<const int> channels, float* out,
                             std::string& error) {
    const long long h = res_.height, w = res_.width;
    if (whole_.empty()) {
      if (!scanline(res_.scanlines() - 1, error)) return false;
      std::vector<float> whole(static_cast<std::size_t>(w * h) * 3);
      for (long long s = 0; s < w; ++s) {
        if (!scanline(s, error)) return false;
        const long long x = res_.x_decreasing ? w - 1 - s : s;
        for (long long p = 0; p < h; ++p) {
          const long long y = res_.y_decreasing ? p : h - 1 - p;
          std::copy_n(rgb_.data() + 3 * p, 3, whole.data() + 3 * (y * w + x));
        }
      }
      whole_ = std::move(whole);
    }
    const std::size_t k = channels.size();
    for (long long t = y_begin * w; t < y_end * w; ++t)
      for (std::size_t c = 0; c < k; ++c)
        out[static_cast<std::size_t>(t - y_begin * w) * k + c] = whole_[3 * static_cast<std::size_t>(t) + channels[c]];
    return true;
  }

  FileBytes file_;
  ByteStream stream_;  // over file_
  Resolution res_;
  std::vector<std::uint64_t> offsets_;  // of scanlines 0 .. offsets_.size() - 1
  std::vector<std::uint8_t> rgbe_;      // one scanline as stored
  std::vector<float> rgb_;              // one scanline as float
  std::vector<float> whole_;            // the image, for files that store columns
  std::string format_ = "hdr";
  std::vector<ImagePart> parts_;
};

}  // namespace

bool is_radiance_magic(std::string_view head) {
  for (const std::string_view magic : {std::string_view("#?RADIANCE"), std::string_view("#?RGBE")}) {
    if (head.size() > magic.size() && head.substr(0, magic.size()) == magic) {
      const char next = head[magic.size()];
      if (next == '\n' || next == '\r' || next == ' ' || next == '\t') return true;
    }
  }
  return false;
}

IoStatus open_hdr(const std::filesystem::path& path, FileBytes file, const TexelBudget& budget,
                  std::unique_ptr<ImageDecoder>& decoder) {
  decoder.reset();
  Header header;
  if (IoStatus st = parse_header(path, file.read_some(0, kMaxHeaderBytes), file.size(), header); !st.ok()) return st;
  const Resolution& res = header.resolution;
  if (const std::string problem = budget_problem("the image", res.width, res.height, budget); !problem.empty())
    return IoStatus::error(IoErrc::Unsupported, path, problem);
  const std::uint64_t pixel_bytes = file.size() - header.data_offset;
  if (static_cast<std::uint64_t>(res.scanlines()) > pixel_bytes / kMinScanlineBytes) {
    std::string problem = "the Radiance header declares ";
    problem += std::to_string(res.scanlines());
    problem += " scanlines, at least 4 bytes each, but the file holds ";
    problem += std::to_string(pixel_bytes);
    problem += " bytes after its header (it is truncated)";
    return IoStatus::error(IoErrc::Unreadable, path, problem);
  }
  decoder = std::make_unique<HdrDecoder>(std::move(file), header);
  return IoStatus::success();
}

}  // namespace shpack::io::detail
