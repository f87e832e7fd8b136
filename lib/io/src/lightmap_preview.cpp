#include "shpack/io/lightmap_preview.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "shpack/light_extraction.h"  // kRec709Luminance
#include "shpack/srgb.h"
#include "shpack/vec3.h"

namespace shpack::io {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

constexpr std::uint64_t kMaxSidecarBytes = 16u << 20;

struct Rgba {
  std::uint32_t width = 0, height = 0;
  std::vector<float> pixels;  // 4 per texel
};

// One image of the lightmap: RGBA float, the size the sidecar states.
IoStatus read_rgba(const fs::path& path, std::uint32_t width, std::uint32_t height, Rgba& out) {
  try {
    if (fs::is_symlink(path)) return IoStatus::error(IoErrc::Unreadable, path, "is a symbolic link");
    Imf::InputFile file(path.string().c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    const auto w = static_cast<std::int64_t>(dw.max.x) - dw.min.x + 1, h = static_cast<std::int64_t>(dw.max.y) - dw.min.y + 1;
    if (w != width || h != height)
      return IoStatus::error(IoErrc::Unreadable, path, "is " + std::to_string(w) + " x " + std::to_string(h) +
                                                         ", not the sidecar's " + std::to_string(width) + " x " +
                                                         std::to_string(height));
    out = {width, height, std::vector<float>(std::size_t{4} * width * height, 0.0f)};
    Imf::FrameBuffer frame;
    const char* names[4] = {"R", "G", "B", "A"};
    const std::size_t xs = 4 * sizeof(float), ys = xs * width;
    char* base = reinterpret_cast<char*>(out.pixels.data()) - (dw.min.x * static_cast<std::ptrdiff_t>(xs)) -
                 (dw.min.y * static_cast<std::ptrdiff_t>(ys));
    for (int c = 0; c < 4; ++c) frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys, 1, 1, 0.0));
    file.setFrameBuffer(frame);
    file.readPixels(dw.min.y, dw.max.y);
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::Unreadable, path, std::string("OpenEXR: ") + e.what());
  }
  return IoStatus::success();
}

std::uint8_t encode(double linear) { return static_cast<std::uint8_t>(std::lround(255.0 * linear_to_srgb(std::clamp(linear, 0.0, 1.0)))); }

}  // namespace

IoStatus render_lightmap_preview(const fs::path& sidecar, std::uint32_t size, Rgb8Image& out) {
  Json doc;
  try {
    std::ifstream in(sidecar, std::ios::binary);
    if (!in) return IoStatus::error(IoErrc::NotFound, sidecar, "cannot be opened");
    if (fs::file_size(sidecar) > kMaxSidecarBytes) return IoStatus::error(IoErrc::Unreadable, sidecar, "is too large for a sidecar");
    doc = Json::parse(in);
    if (doc.value("kind", "") != "shpack-sh-lightmap") return IoStatus::error(IoErrc::BadDocument, sidecar, "is not an shpack lightmap sidecar");
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::BadDocument, sidecar, std::string("not valid JSON: ") + e.what());
  }
  std::uint32_t W = 0, H = 0;
  std::array<std::string, 4> files;
  try {
    W = doc.at("width").get<std::uint32_t>();
    H = doc.at("height").get<std::uint32_t>();
    const char* keys[4] = {"SHAr", "SHAg", "SHAb", "texels"};
    for (int k = 0; k < 4; ++k) {
      files[k] = doc.at("files").at(keys[k]).get<std::string>();
      if (files[k].find('/') != std::string::npos || files[k].find('\\') != std::string::npos || files[k].starts_with("."))
        return IoStatus::error(IoErrc::BadDocument, sidecar, "files." + std::string(keys[k]) + " must name a file beside it");
    }
  } catch (const std::exception& e) {
    return IoStatus::error(IoErrc::BadDocument, sidecar, std::string("a key is missing or wrong: ") + e.what());
  }
  if (W == 0 || H == 0 || std::uint64_t{W} * H > (std::uint64_t{1} << 26))
    return IoStatus::error(IoErrc::BadDocument, sidecar, "its width and height are out of range");
  std::array<Rgba, 4> images;
  for (int k = 0; k < 4; ++k)
    if (IoStatus st = read_rgba(sidecar.parent_path() / files[k], W, H, images[k]); !st.ok()) return st;
  const std::uint32_t zoom = std::max<std::uint32_t>(1, size / std::max(W, H));
  const std::uint32_t gap = 4;
  out.width = 3 * W * zoom + 2 * gap;
  out.height = H * zoom;
  out.pixels.assign(std::size_t{3} * out.width * out.height, 0);
  // Tone mapping: k = 1 / mean luminance of the L0 term over used texels.
  double sum = 0;
  std::size_t used = 0;
  for (std::size_t t = 0; t < std::size_t{W} * H; ++t) {
    if (images[3].pixels[4 * t + 1] == 0) continue;
    double lum = 0;
    for (int c = 0; c < 3; ++c) lum += kRec709Luminance[c] * images[c].pixels[4 * t + 3];
    sum += lum;
    ++used;
  }
  const double k = used && sum > 0 ? static_cast<double>(used) / sum : 1.0;
  for (std::uint32_t j = 0; j < H; ++j)
    for (std::uint32_t i = 0; i < W; ++i) {
      const std::size_t t = std::size_t{j} * W + i;
      const float state = images[3].pixels[4 * t + 1];
      std::array<std::array<std::uint8_t, 3>, 3> panel{};
      if (state == 0) {
        const std::uint8_t g = ((i + j) % 2) ? 96 : 64;
        panel = {{{g, g, g}, {g, g, g}, {g, g, g}}};
      } else {
        Vec3 d{0, 0, 0};
        for (int c = 0; c < 3; ++c) {
          const double l0 = images[c].pixels[4 * t + 3];
          panel[0][c] = encode(k * l0 / (1.0 + k * l0));
          d = d + kRec709Luminance[c] * Vec3{images[c].pixels[4 * t], images[c].pixels[4 * t + 1], images[c].pixels[4 * t + 2]};
        }
        const double len = std::sqrt(dot(d, d));
        const Vec3 u = len > 0 ? (1.0 / len) * d : Vec3{0, 0, 0};
        panel[1] = {encode(0.5 + 0.5 * u.x), encode(0.5 + 0.5 * u.y), encode(0.5 + 0.5 * u.z)};
        const std::uint8_t cov = encode(0.25 + 0.5 * images[3].pixels[4 * t]);
        panel[2] = state == 2 ? std::array<std::uint8_t, 3>{40, 80, 230}
                   : state == 3 ? std::array<std::uint8_t, 3>{40, 200, 80}
                                : std::array<std::uint8_t, 3>{cov, cov, cov};
      }
      for (int p = 0; p < 3; ++p)
        for (std::uint32_t y = 0; y < zoom; ++y)
          for (std::uint32_t x = 0; x < zoom; ++x) {
            std::uint8_t* px = out.at(p * (W * zoom + gap) + i * zoom + x, j * zoom + y);
            std::copy(panel[p].begin(), panel[p].end(), px);
          }
    }
  return IoStatus::success();
}

}  // namespace shpack::io
