// libFuzzer target: the part file reader of sharded bakes (bake_part.h decode_part, the
// input of `shpack merge`) given arbitrary bytes. A part ends with the SHA-256 of the rest,
// which random bytes never match, so an input whose first byte is odd is read with its own
// hash appended: the reader past the hash (the header, the counts against the bytes, the
// records) gets arbitrary bytes too.
// Properties: no crash, no sanitizer report, memory bounded by the input (counts are checked
// against the bytes before anything is allocated for them); on failure one non-empty line; on
// success the records are what the header counts, no NaN nor infinite coefficient, and what was read,
// encoded and read back, encodes to the same bytes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>

#include "shpack/bake/bake_part.h"
#include "shpack/io/sha256.h"

namespace {

using shpack::bake::BakePart;

void check_counts(const BakePart& part) {
  if (part.probe_result.radiance.size() != part.probes.count || part.probe_result.sampling.size() != part.probes.count ||
      part.probe_result.validity.size() != part.probes.count)
    std::abort();
  if (part.texel_result.texels.size() != part.texels.count || part.texel_result.radiance.size() != part.texels.count ||
      part.texel_result.invalid.size() != part.texels.count)
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] % 2 == 1) {
    shpack::io::Sha256 hash;
    hash.update(std::as_bytes(std::span(bytes.data(), bytes.size())));
    const shpack::io::Sha256Digest digest = hash.finish();
    bytes.append(reinterpret_cast<const char*>(digest.data()), digest.size());
  }
  BakePart part;
  std::string error;
  if (!shpack::bake::decode_part(bytes, part, error)) {
    if (error.empty() || error.find('\n') != std::string::npos) std::abort();
    return 0;
  }
  check_counts(part);
  BakePart back;
  if (!shpack::bake::decode_part(shpack::bake::encode_part(part), back, error)) std::abort();
  check_counts(back);
  if (back.probes != part.probes || back.texels != part.texels ||
      shpack::bake::encode_part(back) != shpack::bake::encode_part(part))
    std::abort();
  return 0;
}
