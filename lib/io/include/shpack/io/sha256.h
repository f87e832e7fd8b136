// sha256.h - SHA-256 of a file, for the JSON output's source.sha256.
//
// SHA-256 (FIPS 180-4) through OpenSSL's libcrypto, which uses the processor's SHA
// extensions where it has them: hashing a 100 MB EXR with a portable implementation took a
// third of `shpack convert`'s time (docs/dependencies.md). It identifies inputs; it is not
// used for security.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "shpack/io/io_status.h"

namespace shpack::io {

using Sha256Digest = std::array<std::uint8_t, 32>;

// Incremental hashing: update() with the message in any pieces, then finish() once.
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  void update(std::span<const std::byte> bytes) noexcept;
  Sha256Digest finish() noexcept;

 private:
  struct Context;
  std::unique_ptr<Context> context_;
};

// Lower-case hexadecimal, 64 characters.
std::string to_hex(const Sha256Digest& digest);

// The digest of a whole file, as hexadecimal.
IoStatus sha256_file(const std::filesystem::path& path, std::string& hex);

}  // namespace shpack::io
