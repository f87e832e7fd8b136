// study_inputs.h - the maps `shpack bench` measures: equirect files read whole, and
// synthetic maps made in memory, each a case that separates the methods.
//
//   synthetic:band-limited  a positive L2 polynomial in (x, y, z) sampled at texel centres:
//                           smooth, so quadrature rules show their order
//   synthetic:texel         one 1e6 texel over a uniform 0.1 sky: all of a delta's
//                           energy in one texel, which a sample hits or misses
//   synthetic:sun           a 0.53 degree sun disc (radiance 1e5) 35 degrees above the
//                           horizon over a dim sky, texels weighted by the disc's coverage:
//                           the real-sky case, a few texels carrying most of the light
//   synthetic:gradient      exp(1.5 y + 0.3 x) per channel: a smooth sky, not band-limited
//
// Synthetic maps are kSyntheticWidth x kSyntheticWidth/2, the size of the bundled maps.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "shpack/image_view.h"
#include "shpack/io/io_status.h"

namespace shpack::study {

inline constexpr std::uint32_t kSyntheticWidth = 1024;
inline constexpr std::string_view kSyntheticPrefix = "synthetic:";

// A map held in memory: tightly packed float, 1 (grey) or 3 (RGB) channels.
struct StudyImage {
  std::string name;  // the input as the user gave it, or "synthetic:NAME"
  std::uint32_t width = 0, height = 0, channels = 0;
  std::vector<float> pixels;

  ImageView view() const noexcept { return make_view(pixels.data(), width, height, channels); }
};

// "synthetic:band-limited", "synthetic:texel", "synthetic:sun", "synthetic:gradient".
std::vector<std::string> synthetic_map_names();

// The environment variable that names the folder of the bundled maps, overriding the
// installed one.
inline constexpr const char* kDataDirVariable = "SHPACK_DATA_DIR";

// The folder of the bundled maps (data/hdri, installed as share/shpack/hdri): `data_dir`
// (the value of SHPACK_DATA_DIR, or null) if it names a folder, else
// <folder of `executable`>/../share/shpack/hdri if that is one, else the empty path. The
// source tree's path is never built in: an installed command finds its own data.
std::filesystem::path find_bundled_maps(const char* data_dir, const std::filesystem::path& executable);

// The inputs when none are given: every *.exr in `bundled_dir` (sorted by name; none if
// the folder is empty or does not exist), then the synthetic maps.
std::vector<std::string> default_inputs(const std::filesystem::path& bundled_dir);

// Reads `input`: a synthetic name, or an image file (image_file.h) whose shape says it is
// equirect (2:1, or 1x1); "-" is one on stdin. Errors name the input: InvalidArgument for an unknown synthetic
// name, UnknownLayout for another shape, and those of read_image_file.
io::IoStatus load_study_input(const std::string& input, StudyImage& out);

}  // namespace shpack::study
