// SHA-256 against the test vectors of NIST's "Cryptographic Algorithm Validation Program"
// examples for FIPS 180-4 (SHA256.pdf: "abc", the 448-bit two-block message) and the
// well-known digests of the empty message and of one million 'a'.
#include "shpack/io/sha256.h"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "io_test_files.h"

namespace shpack::io {
namespace {

std::string sha256_hex(std::string_view text) {
  Sha256 sha;
  sha.update(std::as_bytes(std::span(text.data(), text.size())));
  return to_hex(sha.finish());
}

TEST(Sha256, FipsExampleOneBlock) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(Sha256, FipsExampleTwoBlocks) {
  // 56 bytes: the padding (1 + 8 bytes) no longer fits in the first block.
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, EmptyMessage) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Sha256, OneMillionA) {
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, PiecesDoNotMatter) {
  // Every split of a 130-byte message (two blocks and a partial one) gives the same digest.
  std::string message;
  for (int i = 0; i < 130; ++i) message += static_cast<char>('!' + i % 90);
  const std::string whole = sha256_hex(message);
  for (std::size_t split = 0; split <= message.size(); ++split) {
    Sha256 sha;
    sha.update(std::as_bytes(std::span(message.data(), split)));
    sha.update(std::as_bytes(std::span(message.data() + split, message.size() - split)));
    EXPECT_EQ(to_hex(sha.finish()), whole) << "split=" << split;
  }
}

TEST(Sha256, FileDigestIsTheDigestOfItsBytes) {
  const shpack_io_test::ScratchDir dir;
  const std::vector<char> bytes(3 << 20, 'a');  // spans several 1 MiB read chunks
  shpack_io_test::write_bytes(dir / "a.bin", bytes);
  std::string hex;
  const IoStatus st = sha256_file(dir / "a.bin", hex);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(hex, sha256_hex(std::string_view(bytes.data(), bytes.size())));
}

TEST(Sha256, MissingFileIsNamed) {
  std::string hex;
  const IoStatus st = sha256_file("no/such/file.exr", hex);
  EXPECT_EQ(st.code, IoErrc::NotFound);
  EXPECT_EQ(st.message, "no/such/file.exr: no such file");
}

}  // namespace
}  // namespace shpack::io
