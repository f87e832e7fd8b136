// fuzz_reader.h - libFuzzer's bytes turned into integers, big-endian, as the seed corpora
// were written: each take reads its bytes or what is left (then zeros).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace shpack_fuzz {

struct Reader {
  const std::uint8_t* data;
  std::size_t size;

  // Two bytes, reduced modulo `modulo` unless it is 0.
  std::uint32_t take(std::uint32_t modulo) {
    std::uint32_t v = 0;
    for (int k = 0; k < 2 && size > 0; ++k, ++data, --size) v = (v << 8) | *data;
    return modulo == 0 ? v : v % modulo;
  }
  std::uint32_t take32() { return take(0) << 16 | take(0); }
  std::int64_t take64() {
    std::uint64_t v = 0;
    for (int k = 0; k < 8 && size > 0; ++k, ++data, --size) v = (v << 8) | *data;
    std::int64_t s;
    std::memcpy(&s, &v, sizeof s);
    return s;
  }
};

}  // namespace shpack_fuzz
