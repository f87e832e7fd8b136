// rgb_image.h - an owned float RGB image for tests (row-major from the top, 3 floats a texel).
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "shpack/image_view.h"

namespace shpack_test {

struct RgbImage {
  std::uint32_t width = 0, height = 0;
  std::vector<float> rgb;

  RgbImage() = default;
  RgbImage(std::uint32_t w, std::uint32_t h) : width(w), height(h), rgb(std::size_t{3} * w * h, 0.0f) {}

  float& at(std::uint32_t x, std::uint32_t y, int c) {
    return rgb[(std::size_t{y} * width + x) * 3 + static_cast<std::size_t>(c)];
  }
  float at(std::uint32_t x, std::uint32_t y, int c) const {
    return rgb[(std::size_t{y} * width + x) * 3 + static_cast<std::size_t>(c)];
  }
  void set(std::uint32_t x, std::uint32_t y, float r, float g, float b) {
    at(x, y, 0) = r;
    at(x, y, 1) = g;
    at(x, y, 2) = b;
  }
  // A tightly packed float RGB view of the pixels.
  shpack::ImageView view() const { return shpack::make_view(rgb.data(), width, height, 3); }
};

// A w x h image of values uniform in [lo, hi), the same for the same seed.
inline RgbImage uniform_random_image(std::uint32_t w, std::uint32_t h, std::uint64_t seed, float lo, float hi) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(lo, hi);
  RgbImage img(w, h);
  for (float& v : img.rgb) v = u(rng);
  return img;
}

}  // namespace shpack_test
