#include "pixel_encoding.h"

#include "shpack/srgb.h"

namespace shpack::io::detail {

void decode_srgb(std::span<float> values) noexcept {
  for (float& v : values) v = static_cast<float>(srgb_to_linear(v));
}

}  // namespace shpack::io::detail
