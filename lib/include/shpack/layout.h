// layout.h - how an environment map is laid out in its image.
//
// Layouts (docs/layouts.md draws each; conventions.md and project_sphere_map.h are normative):
//   equirect    latitude-longitude, Unity's Skybox/Panoramic mapping (conventions.h), any W x H
//   hcross      horizontal cross of six cube faces, 4N x 3N    (cube_layout.h)
//   vcross      vertical cross, 3N x 4N, -Z upside down         (cube_layout.h)
//   hstrip      six faces left to right, 6N x N                 (cube_layout.h)
//   vstrip      six faces top to bottom, N x 6N                 (cube_layout.h)
//   octahedral  Unity's octahedral encoding, N x N              (project_sphere_map.h)
//   angular     Debevec's angular map (light probe), N x N      (project_sphere_map.h)
//   mirrorball  a mirrored ball photographed along +Z, N x N    (project_sphere_map.h)
//   faces       six face files (`convert --faces`), each N x N; never detected from one image
//
// Detection (docs/layouts.md): 2:1 is equirect, 4:3 hcross, 3:4 vcross, 6:1 hstrip, 1:6 vstrip,
// and a 1x1 image is a uniform environment (read as equirect, which handles it exactly). A
// square image is ambiguous (octahedral, angular or mirror ball) and any other shape fits
// no layout: both need the layout named.
#pragma once

#include <cstdint>
#include <string>

namespace shpack {

enum class Layout : std::uint8_t {
  Auto,             // detect from the image size
  Equirect,         // Unity Skybox/Panoramic latitude-longitude (conventions.h)
  HorizontalCross,  // cube_layout.h
  VerticalCross,
  HorizontalStrip,
  VerticalStrip,
  Octahedral,       // project_sphere_map.h
  Angular,
  MirrorBall,
  Faces,            // six face files
};

// The layout's name in the CLI and in the JSON output: "auto", "equirect", "hcross",
// "vcross", "hstrip", "vstrip", "octahedral", "angular", "mirrorball", "faces".
const char* layout_name(Layout layout) noexcept;

// The layout of a width x height image: `requested` unless it is Auto, else the detected
// one, or Auto when the shape does not say (square, or no layout fits).
Layout resolve_layout(Layout requested, std::uint32_t width, std::uint32_t height) noexcept;

// Why a width x height image cannot be read as `requested` (Auto: why it cannot be
// detected), naming the layouts its shape fits, e.g. "the layout of a 512x512 image is
// ambiguous: it fits octahedral, angular and mirrorball"; "" when it can. A 1x1 image fits
// every layout (a uniform environment).
std::string layout_shape_problem(Layout requested, std::uint32_t width, std::uint32_t height);

// True for the four single-image cube layouts and for faces.
bool is_cube_layout(Layout layout) noexcept;

}  // namespace shpack
