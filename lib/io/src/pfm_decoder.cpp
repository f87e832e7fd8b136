#include "pfm_decoder.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "shpack/io/quoted.h"

namespace shpack::io::detail {
namespace {

constexpr std::size_t kMaxHeaderBytes = std::size_t{64} << 10;
constexpr long long kMaxSize = 2147483647;                // 2^31 - 1, as OpenImageIO's int sizes
constexpr std::size_t kReadBytes = std::size_t{1} << 20;  // rows are read in pieces of about this

struct Header {
  int channels = 3;
  long long width = 0, height = 0;
  bool big_endian = false;
  float scale = 1.0f;  // the scale's absolute value, which every value is multiplied by
  std::uint64_t data_offset = 0;
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// The next word of `head` from `at`, after blanks and "#" comments; "" at the end of `head`.
std::string_view next_word(std::string_view head, std::size_t& at) {
  for (;;) {
    while (at < head.size() && is_blank(head[at])) ++at;
    if (at >= head.size() || head[at] != '#') break;
    at = std::min(head.size(), head.find('\n', at));
  }
  const std::size_t begin = at;
  while (at < head.size() && !is_blank(head[at])) ++at;
  return head.substr(begin, at - begin);
}

bool parse_size(std::string_view word, long long& out) {
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), out);
  return ec == std::errc() && end == word.data() + word.size() && out >= 1 && out <= kMaxSize;
}

bool parse_scale(std::string_view word, float& out) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), out);
  return ec == std::errc() && end == word.data() + word.size() && std::isfinite(out) && out != 0.0f;
}

// Reads the header from the file's first bytes `head`.
IoStatus parse_header(const std::filesystem::path& path, std::string_view head, std::uint64_t file_size, Header& out) {
  const auto unreadable = [&](const std::string& problem) {
    return IoStatus::error(IoErrc::Unreadable, path, problem);
  };
  if (!is_pfm_magic(head)) return unreadable("not a PFM: it does not start with PF or Pf");
  out.channels = head[1] == 'F' ? 3 : 1;
  std::size_t at = 2;
  const char* names[] = {"width", "height", "scale"};
  for (int k = 0; k < 3; ++k) {
    const std::string_view word = next_word(head, at);
    // A word that reaches the end of `head` may go on past it: the header is not whole.
    if (word.empty() || at == head.size()) {
      if (head.size() == file_size) return unreadable("the file ends inside the PFM header");
      return unreadable("the PFM header does not end in the file's first 65536 bytes");
    }
    const bool ok = k == 0   ? parse_size(word, out.width)
                    : k == 1 ? parse_size(word, out.height)
                             : parse_scale(word, out.scale);
    if (!ok) {
      std::string problem = "the PFM header's ";
      problem += names[k];
      problem += " ";
      problem += quoted(word, 32);
      problem += k < 2 ? " is not a whole number from 1 to 2147483647"
                       : " is not a finite number other than 0 (its sign gives the byte order)";
      return unreadable(problem);
    }
  }
  out.big_endian = out.scale > 0.0f;
  out.scale = std::fabs(out.scale);
  out.data_offset = at + 1;  // past the one blank after the scale
  return IoStatus::success();
}

std::uint32_t byte_swapped(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

class PfmDecoder final : public ImageDecoder {
 public:
  PfmDecoder(FileBytes file, const Header& header)
      : file_(std::move(file)), header_(header), swap_(header.big_endian != (std::endian::native == std::endian::big)) {
    ImagePart part;
    part.channels = header.channels == 3 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"Y"};
    part.data = part.display = {0, 0, header.width, header.height};
    parts_.push_back(std::move(part));
  }

  const std::string& format() const noexcept override { return format_; }
  const std::vector<ImagePart>& parts() const noexcept override { return parts_; }
  void set_threads(unsigned) override {}  // a read is a copy and a byte swap: one thread keeps up

  // Rows [y_begin, y_end) are file rows [height - y_end, height - y_begin): read in pieces
  // of whole rows, each piece's rows turned top-down into `out`.
  bool read_rows(std::size_t, long long y_begin, long long y_end, std::span<const int> channels, float* out,
                 std::string& error) override {
    const std::size_t row_values = static_cast<std::size_t>(header_.width) * static_cast<std::size_t>(header_.channels);
    const std::size_t row_bytes = 4 * row_values;
    const long long rows_per_read = static_cast<long long>(std::max<std::size_t>(1, kReadBytes / row_bytes));
    const std::size_t k = channels.size();
    for (long long top = y_begin; top < y_end; top += rows_per_read) {
      const long long bottom = std::min(y_end, top + rows_per_read);  // image rows [top, bottom)
      const long long file_row = header_.height - bottom;
      raw_.resize(row_values * static_cast<std::size_t>(bottom - top));
      if (!file_.read(header_.data_offset + static_cast<std::uint64_t>(file_row) * row_bytes, raw_.data(),
                      4 * raw_.size())) {
        error = "the file cannot be read at image row ";
        error += std::to_string(bottom - 1);
        return false;
      }
      for (long long y = top; y < bottom; ++y) {
        const std::uint32_t* src = raw_.data() + row_values * static_cast<std::size_t>(bottom - 1 - y);
        float* dst = out + static_cast<std::size_t>(y - y_begin) * static_cast<std::size_t>(header_.width) * k;
        for (long long x = 0; x < header_.width; ++x)
          for (std::size_t c = 0; c < k; ++c)
            dst[static_cast<std::size_t>(x) * k + c] =
                value(src[static_cast<std::size_t>(x) * static_cast<std::size_t>(header_.channels) + channels[c]]);
      }
    }
    return true;
  }

 private:
  float value(std::uint32_t bits) const {
    return std::bit_cast<float>(swap_ ? byte_swapped(bits) : bits) * header_.scale;
  }

  FileBytes file_;
  Header header_;
  bool swap_;                       // the file's byte order is not this machine's
  std::vector<std::uint32_t> raw_;  // rows as stored
  std::string format_ = "pnm";
  std::vector<ImagePart> parts_;
};

}  // namespace

bool is_pfm_magic(std::string_view head) {
  return head.size() >= 3 && head[0] == 'P' && (head[1] == 'F' || head[1] == 'f') && is_blank(head[2]);
}

IoStatus open_pfm(const std::filesystem::path& path, FileBytes file, const TexelBudget& budget,
                  std::unique_ptr<ImageDecoder>& decoder) {
  decoder.reset();
  Header header;
  if (IoStatus st = parse_header(path, file.read_some(0, kMaxHeaderBytes), file.size(), header); !st.ok()) return st;
  if (const std::string problem = budget_problem("the image", header.width, header.height, budget); !problem.empty())
    return IoStatus::error(IoErrc::Unsupported, path, problem);
  // width * height < 2^62 (both below 2^31), so the comparison cannot overflow.
  const std::uint64_t texels = static_cast<std::uint64_t>(header.width) * static_cast<std::uint64_t>(header.height);
  const std::uint64_t texel_bytes = 4 * static_cast<std::uint64_t>(header.channels);
  const std::uint64_t data_bytes = file.size() - std::min(file.size(), header.data_offset);
  if (texels > data_bytes / texel_bytes) {
    std::string problem = "the PFM header declares ";
    problem += std::to_string(header.width);
    problem += "x";
    problem += std::to_string(header.height);
    problem += " texels of ";
    problem += std::to_string(texel_bytes);
    problem += " bytes, but the file holds ";
    problem += std::to_string(data_bytes);
    problem += " bytes after its header (it is truncated)";
    return IoStatus::error(IoErrc::Unreadable, path, problem);
  }
  decoder = std::make_unique<PfmDecoder>(std::move(file), header);
  return IoStatus::success();
}

}  // namespace shpack::io::detail
