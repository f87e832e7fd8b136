// sha256.h - SHA-256 of a file, for the JSON output's source.sha256.
//
// A small implementation of FIPS 180-4 section 6.2, so that shpack_io needs no crypto
// library for one digest (OpenImageIO 2.4 exposes only SHA-1). It identifies inputs; it
// is not used for security.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "shpack/io/io_status.h"

namespace shpack::io {

using Sha256Digest = std::array<std::uint8_t, 32>;

// Incremental hashing: update() with the message in any pieces, then finish() once.
class Sha256 {
 public:
  void update(std::span<const std::byte> bytes) noexcept;
  Sha256Digest finish() noexcept;

 private:
  void compress(const std::uint8_t* block) noexcept;

  // FIPS 180-4 5.3.3: the initial hash value H(0).
  std::array<std::uint32_t, 8> state_ = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                         0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  std::array<std::uint8_t, 64> block_{};
  std::size_t block_size_ = 0;   // bytes waiting in block_
  std::uint64_t total_bytes_ = 0;
};

// Lower-case hexadecimal, 64 characters.
std::string to_hex(const Sha256Digest& digest);

// The digest of a whole file, as hexadecimal.
IoStatus sha256_file(const std::filesystem::path& path, std::string& hex);

}  // namespace shpack::io
