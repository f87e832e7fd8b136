// writable_map.cpp - the copy of a caller's map that stage 2 writes into (pipeline.h
// make_writable): the transforms set the texels of extracted lights to their fill levels,
// and a caller's pixels, views of memory it owns, must stay as they were.
#include <cstring>
#include <new>
#include <utility>
#include <vector>

#include "shpack/pipeline.h"

namespace shpack {

Status make_writable(MapImage& map, std::vector<float>& storage) noexcept {
  if (map.layout != Layout::Equirect) return Status::success();
  ImageView view = map.image;
  if (Status st = resolve_view(view); !st.ok()) return st;
  const std::size_t row = std::size_t{view.width} * view.channels;
  std::vector<float> pixels;
  try {
    pixels.resize(row * view.height);
  } catch (const std::bad_alloc&) {
    return Status::error(Errc::OutOfMemory, "cannot allocate a copy of the image for extract_sun or extract_lights");
  }
  for (std::uint32_t y = 0; y < view.height; ++y) {
    for (std::uint32_t x = 0; x < view.width; ++x) {
      const std::byte* texel = view.pixel(x, y);
      float* out = pixels.data() + y * row + std::size_t{x} * view.channels;
      for (std::uint32_t c = 0; c < view.channels; ++c) {
        if (view.type == PixelType::F32) {
          std::memcpy(out + c, texel + 4 * c, sizeof(float));
        } else {
          std::uint16_t half;
          std::memcpy(&half, texel + 2 * c, sizeof half);
          out[c] = half_to_float(half);
        }
      }
    }
  }
  storage = std::move(pixels);  // a move of a vector does not throw
  map.image = make_view(storage.data(), view.width, view.height, view.channels);
  map.writable = storage.data();
  return Status::success();
}

}  // namespace shpack
