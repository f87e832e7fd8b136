#include "shpack/study/study_inputs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <system_error>
#include <utility>

#include "shpack/conventions.h"
#include "shpack/io/image_file.h"
#include "shpack/io/stdin_spool.h"
#include "shpack/layout.h"

namespace shpack::study {
namespace {

namespace fs = std::filesystem;
using Rgb = std::array<double, 3>;
using RadianceAt = std::function<Rgb(const Dir3&)>;

// The image whose texel (i, j) holds f at its centre (conventions.h: ((i + 0.5)/W, (j + 0.5)/H)).
StudyImage sample_at_centres(std::string name, const RadianceAt& f) {
  StudyImage image{std::move(name), kSyntheticWidth, kSyntheticWidth / 2, 3, {}};
  image.pixels.resize(std::size_t{3} * image.width * image.height);
  for (std::uint32_t j = 0; j < image.height; ++j) {
    for (std::uint32_t i = 0; i < image.width; ++i) {
      const Rgb v = f(equirect_direction((i + 0.5) / image.width, (j + 0.5) / image.height));
      float* texel = &image.pixels[3 * (std::size_t{j} * image.width + i)];
      for (int c = 0; c < 3; ++c) texel[c] = static_cast<float>(v[c]);
    }
  }
  return image;
}

// Positive: per channel 1 + sum_k w_k q_k with sum_k |w_k| max|q_k| < 1 (q below has
// max |q_k| = 1 except xy, yz, xz, whose max is 1/2), times the channel's mean.
StudyImage band_limited(std::string name) {
  constexpr std::array<double, 3> kMean = {1.0, 0.8, 0.6};
  constexpr double kWeights[3][8] = {{0.25, 0.20, -0.15, 0.10, -0.08, 0.06, 0.10, 0.12},
                                     {-0.20, 0.15, 0.25, -0.06, 0.10, 0.08, -0.12, 0.10},
                                     {0.10, -0.25, 0.20, 0.08, 0.06, -0.10, 0.05, -0.15}};
  return sample_at_centres(std::move(name), [&](const Dir3& d) {
    const std::array<double, 8> q = {d.x,       d.y,       d.z,           d.x * d.y,
                                     d.y * d.z, d.x * d.z, d.x * d.x - d.z * d.z,
                                     0.5 * (3 * d.y * d.y - 1)};
    Rgb v{};
    for (int c = 0; c < 3; ++c) {
      double sum = 1.0;
      for (int k = 0; k < 8; ++k) sum += kWeights[c][k] * q[k];
      v[c] = kMean[c] * sum;
    }
    return v;
  });
}

StudyImage single_texel(std::string name) {
  StudyImage image = sample_at_centres(std::move(name), [](const Dir3&) { return Rgb{0.1, 0.1, 0.1}; });
  // Off every axis and seam, so no symmetry hides a wrong lookup.
  const std::size_t x = image.width * 3 / 8, y = image.height / 3;
  std::fill_n(&image.pixels[3 * (y * image.width + x)], 3, 1e6f);
  return image;
}

StudyImage gradient(std::string name) {
  constexpr Rgb kScale = {0.5, 0.7, 1.0};
  return sample_at_centres(std::move(name), [&](const Dir3& d) {
    const double g = std::exp(1.5 * d.y + 0.3 * d.x);
    return Rgb{kScale[0] * g, kScale[1] * g, kScale[2] * g};
  });
}

// The sun's disc: 0.53 degrees across, radiance 1e5 (its irradiance, 1e5 x 6.7e-5 sr = 6.7,
// is about 30 times the sky's), 35 degrees up. Texels near it take the disc's coverage of
// 16 x 16 sub-texel points; a texel further than two texel heights from its rim has none.
StudyImage sun(std::string name) {
  constexpr double kRadius = 0.265 * std::numbers::pi / 180;
  constexpr Rgb kSun = {1e5, 0.95e5, 0.9e5};
  constexpr Rgb kSky = {0.04, 0.06, 0.10}, kGround = {0.02, 0.02, 0.02};
  constexpr int kSub = 16;
  const Dir3 to_sun = equirect_direction(0.3, 55.0 / 180.0);
  const auto cos_to_sun = [&](const Dir3& d) { return d.x * to_sun.x + d.y * to_sun.y + d.z * to_sun.z; };
  StudyImage image = sample_at_centres(std::move(name), [&](const Dir3& d) { return d.y >= 0 ? kSky : kGround; });
  const double near = std::cos(std::min(std::numbers::pi, kRadius + 2 * std::numbers::pi / image.height));
  for (std::uint32_t j = 0; j < image.height; ++j) {
    for (std::uint32_t i = 0; i < image.width; ++i) {
      if (cos_to_sun(equirect_direction((i + 0.5) / image.width, (j + 0.5) / image.height)) < near) continue;
      int inside = 0;
      for (int b = 0; b < kSub; ++b)
        for (int a = 0; a < kSub; ++a)
          inside += cos_to_sun(equirect_direction((i + (a + 0.5) / kSub) / image.width,
                                                  (j + (b + 0.5) / kSub) / image.height)) >= std::cos(kRadius);
      const double covered = inside / double(kSub * kSub);
      float* texel = &image.pixels[3 * (std::size_t{j} * image.width + i)];
      for (int c = 0; c < 3; ++c) texel[c] = static_cast<float>((1 - covered) * texel[c] + covered * kSun[c]);
    }
  }
  return image;
}

struct SyntheticMap {
  std::string_view name;
  StudyImage (*make)(std::string);
};
constexpr SyntheticMap kSynthetic[] = {
    {"band-limited", band_limited}, {"texel", single_texel}, {"sun", sun}, {"gradient", gradient}};

}  // namespace

std::vector<std::string> synthetic_map_names() {
  std::vector<std::string> names;
  for (const SyntheticMap& map : kSynthetic) names.push_back(std::string(kSyntheticPrefix) + std::string(map.name));
  return names;
}

fs::path find_bundled_maps(const char* data_dir, const fs::path& executable) {
  std::error_code ec;
  if (data_dir != nullptr && *data_dir != '\0' && fs::is_directory(data_dir, ec)) return data_dir;
  if (!executable.empty()) {
    // Lexically: /proc/self/exe has no symbolic links left to resolve.
    const fs::path installed = (executable.parent_path() / ".." / "share" / "shpack" / "hdri").lexically_normal();
    if (fs::is_directory(installed, ec)) return installed;
  }
  return {};
}

std::vector<std::string> default_inputs(const fs::path& bundled_dir) {
  std::vector<std::string> inputs;
  std::error_code ec;  // an empty or missing folder: no maps
  for (const fs::directory_entry& entry : fs::directory_iterator(bundled_dir, ec))
    if (entry.path().extension() == ".exr") inputs.push_back(entry.path().string());
  std::sort(inputs.begin(), inputs.end());
  for (std::string& name : synthetic_map_names()) inputs.push_back(std::move(name));
  return inputs;
}

io::IoStatus load_study_input(const std::string& input, StudyImage& out) {
  if (input.starts_with(kSyntheticPrefix)) {
    const std::string_view name = std::string_view(input).substr(kSyntheticPrefix.size());
    for (const SyntheticMap& map : kSynthetic) {
      if (map.name == name) {
        out = map.make(input);
        return io::IoStatus::success();
      }
    }
    return io::IoStatus::error(io::IoErrc::InvalidArgument, input,
                               "no such synthetic map (band-limited, texel, sun, gradient)");
  }
  io::ImageFile file;
  io::StdinSpool spool;  // "-": the map on stdin (stdin_spool.h), named stdin
  if (input == "-") {
    if (io::IoStatus st = spool.fill(io::stdin_budget(io::kDefaultMaxTexels)); !st.ok()) return st;
    if (io::IoStatus st = io::read_image_file(spool.path(), file); !st.ok())
      return {st.code, std::string(io::kStdinName).append(st.message, spool.path().string().size())};
  } else if (io::IoStatus st = io::read_image_file(input, file); !st.ok()) {
    return st;
  }
  if (shpack::resolve_layout(shpack::Layout::Auto, file.width, file.height) != shpack::Layout::Equirect) {
    return io::IoStatus::error(io::IoErrc::UnknownLayout, input,
                               "a " + std::to_string(file.width) + "x" + std::to_string(file.height) +
                                   " image is not an equirect map (2:1); bench reads those only");
  }
  out = {input == "-" ? std::string(io::kStdinName) : input, file.width, file.height, file.channels, std::move(file.pixels)};
  return io::IoStatus::success();
}

}  // namespace shpack::study
