#include "rgbe_scanline.h"

#include <array>
#include <cmath>
#include <cstring>

namespace shpack::io::detail {
namespace {

constexpr std::size_t kMinRleWidth = 8;       // Radiance's MINELEN
constexpr std::size_t kMaxRleWidth = 0x7fff;  // MAXELEN: the width must fit in 15 bits
// Four old-style run records in a row repeat up to 255 << 24 > 2^31 pixels, more than any
// scanline holds (hdr_decoder.h caps sizes at 2^31 - 1); a fifth is refused, as its count
// would no longer fit in 32 bits (Radiance shifts an int by it).
constexpr int kMaxRunShift = 24;

bool ended(const ByteStream& in, std::string& problem) {
  problem = in.at_end() ? "the file ends inside it" : "the file cannot be read";
  return false;
}

bool past_end(const char* what, std::size_t count, std::size_t at, std::size_t width, std::string& problem) {
  problem = what;
  problem += " of ";
  problem += std::to_string(count);
  problem += " from pixel ";
  problem += std::to_string(at);
  problem += " goes past its ";
  problem += std::to_string(width);
  problem += " pixels";
  return false;
}

bool is_run_record(const std::uint8_t* record) { return record[0] == 1 && record[1] == 1 && record[2] == 1; }

// Flat and old-style records from pixel `p` on (oldreadcolrs [2]).
bool read_records(ByteStream& in, std::span<std::uint8_t> rgbe, std::size_t p, std::string& problem) {
  const std::size_t width = rgbe.size() / 4;
  int shift = 0;
  while (p < width) {
    std::uint8_t* record = rgbe.data() + 4 * p;
    if (!in.read(record, 4)) return ended(in, problem);
    if (!is_run_record(record)) {
      ++p;
      shift = 0;
      continue;
    }
    if (p == 0) {
      problem = "an old-style run at its start has no pixel to repeat";
      return false;
    }
    if (shift > kMaxRunShift) {
      problem = "more than four old-style run records in a row";
      return false;
    }
    const std::uint64_t count = std::uint64_t{record[3]} << shift;
    if (count > width - p) return past_end("an old-style run", static_cast<std::size_t>(count), p, width, problem);
    const std::uint8_t* previous = record - 4;
    for (std::uint64_t k = 0; k < count; ++k) std::memcpy(record + 4 * k, previous, 4);
    p += static_cast<std::size_t>(count);
    shift += 8;
  }
  return true;
}

// Component `c` of a new-style scanline: runs and literals until the scanline is full.
bool read_component(ByteStream& in, std::span<std::uint8_t> rgbe, std::size_t c, std::string& problem) {
  const std::size_t width = rgbe.size() / 4;
  std::uint8_t* out = rgbe.data() + c;
  for (std::size_t p = 0; p < width;) {
    std::uint8_t code = 0, value = 0;
    if (!in.get(code)) return ended(in, problem);
    if (code > 128) {
      const std::size_t count = code - 128u;
      if (count > width - p) return past_end("a run", count, p, width, problem);
      if (!in.get(value)) return ended(in, problem);
      for (std::size_t k = 0; k < count; ++k) out[4 * (p + k)] = value;
      p += count;
    } else {
      if (code == 0) {
        problem = "a literal of 0 bytes at pixel ";
        problem += std::to_string(p);
        return false;
      }
      if (code > width - p) return past_end("a literal", code, p, width, problem);
      for (std::size_t k = 0; k < code; ++k)
        if (!in.get(out[4 * (p + k)])) return ended(in, problem);
      p += code;
    }
  }
  return true;
}

}  // namespace

bool read_rgbe_scanline(ByteStream& in, std::span<std::uint8_t> rgbe, std::string& problem) {
  const std::size_t width = rgbe.size() / 4;
  if (width < kMinRleWidth || width > kMaxRleWidth) return read_records(in, rgbe, 0, problem);
  std::uint8_t* first = rgbe.data();
  if (!in.read(first, 4)) return ended(in, problem);
  if (first[0] != 2 || first[1] != 2 || (first[2] & 0x80) != 0) {
    // Not new-style: these 4 bytes are the first record (freadcolrs [2]).
    if (is_run_record(first)) {
      problem = "an old-style run at its start has no pixel to repeat";
      return false;
    }
    return read_records(in, rgbe, 1, problem);
  }
  const std::size_t declared = std::size_t{first[2]} << 8 | first[3];
  if (declared != width) {
    problem = "its run-length header gives a width of ";
    problem += std::to_string(declared);
    problem += ", not ";
    problem += std::to_string(width);
    return false;
  }
  for (std::size_t c = 0; c < 4; ++c)
    if (!read_component(in, rgbe, c, problem)) return false;
  return true;
}

void rgbe_to_float(std::span<const std::uint8_t> rgbe, float* rgb) {
  // 2^(E - 136) for E = 1..255, each exact in float; E = 0 is black.
  static const std::array<float, 256> kScale = [] {
    std::array<float, 256> scale{};
    for (int e = 1; e < 256; ++e) scale[static_cast<std::size_t>(e)] = std::ldexp(1.0f, e - 136);
    return scale;
  }();
  const std::size_t pixels = rgbe.size() / 4;
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::uint8_t* in = rgbe.data() + 4 * p;
    const float scale = kScale[in[3]];
    rgb[3 * p] = static_cast<float>(in[0]) * scale;
    rgb[3 * p + 1] = static_cast<float>(in[1]) * scale;
    rgb[3 * p + 2] = static_cast<float>(in[2]) * scale;
  }
}

}  // namespace shpack::io::detail
