// layout.h - how an environment map is laid out in its image.
//
// This version reads latitude-longitude (equirect) images only; cube layouts (crosses,
// strips, six faces) will join this enum. Detection follows design.md: a 2:1 image is
// equirect, and a 1x1 image is a uniform environment, which the equirect projection
// handles exactly (project.h); every other shape must be named by the user.
#pragma once

#include <cstdint>

namespace shpack::io {

enum class Layout : std::uint8_t {
  Auto,      // detect from the image size
  Equirect,  // Unity Skybox/Panoramic latitude-longitude (conventions.h)
};

// The layout's name in the CLI and in the JSON output ("auto", "equirect").
const char* layout_name(Layout layout) noexcept;

// The layout of a width x height image: `requested` unless it is Auto, else the detected
// one, or Auto when the shape does not say.
Layout resolve_layout(Layout requested, std::uint32_t width, std::uint32_t height) noexcept;

}  // namespace shpack::io
