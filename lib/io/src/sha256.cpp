// SHA-256 (FIPS 180-4) through OpenSSL's EVP interface.
#include "shpack/io/sha256.h"

#include <openssl/evp.h>

#include <cerrno>
#include <cstdio>
#include <memory>
#include <new>
#include <system_error>
#include <vector>

#include "shpack/io/file_checks.h"

namespace shpack::io {
namespace {

struct FileCloser {
  void operator()(std::FILE* file) const noexcept { std::fclose(file); }
};

}  // namespace

struct Sha256::Context {
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> evp{EVP_MD_CTX_new(), &EVP_MD_CTX_free};
};

Sha256::Sha256() : context_(std::make_unique<Context>()) {
  if (!context_->evp || EVP_DigestInit_ex(context_->evp.get(), EVP_sha256(), nullptr) != 1)
    throw std::bad_alloc();  // libcrypto fails here only when it cannot allocate
}

Sha256::~Sha256() = default;

void Sha256::update(std::span<const std::byte> bytes) noexcept {
  EVP_DigestUpdate(context_->evp.get(), bytes.data(), bytes.size());  // cannot fail for SHA-256
}

Sha256Digest Sha256::finish() noexcept {
  Sha256Digest digest{};
  unsigned int size = 0;
  EVP_DigestFinal_ex(context_->evp.get(), digest.data(), &size);
  return digest;
}

std::string to_hex(const Sha256Digest& digest) {
  constexpr char kDigits[] = "0123456789abcdef";
  std::string hex;
  hex.reserve(2 * digest.size());
  for (const std::uint8_t byte : digest) {
    hex += kDigits[byte >> 4];
    hex += kDigits[byte & 0xf];
  }
  return hex;
}

IoStatus sha256_file(const std::filesystem::path& path, std::string& hex) {
  if (IoStatus st = detail::check_regular_file(path); !st.ok()) return st;
  const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) {
    return IoStatus::error(IoErrc::Unreadable, path,
                           "cannot open for hashing: " + std::generic_category().message(errno));
  }
  Sha256 sha;
  std::vector<std::byte> chunk(std::size_t{1} << 20);
  std::size_t got;
  while ((got = std::fread(chunk.data(), 1, chunk.size(), file.get())) != 0)
    sha.update(std::span(chunk.data(), got));
  if (std::ferror(file.get())) return IoStatus::error(IoErrc::Unreadable, path, "read error while hashing");
  hex = to_hex(sha.finish());
  return IoStatus::success();
}

}  // namespace shpack::io
