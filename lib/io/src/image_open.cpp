#include "image_open.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string_view>
#include <utility>

#include "exr_decoder.h"
#include "file_bytes.h"
#include "hdr_decoder.h"
#include "oiio_plugin.h"
#include "pfm_decoder.h"
#include "shpack/io/file_checks.h"

namespace shpack::io::detail {
namespace {

constexpr std::size_t kMagicBytes = 16;  // enough for every magic number below

// Whether a file's first bytes are OpenEXR's magic number.
bool is_openexr(std::string_view head) {
  static constexpr std::string_view kExr("\x76\x2f\x31\x01", 4);
  return head.substr(0, kExr.size()) == kExr;
}

// A name at `at` as OpenEXR reads it: at most `max` bytes and a NUL; `at` moves past it.
// False at the end of the file or without the NUL (OpenEXR refuses the file then).
bool read_name(const FileBytes& file, std::uint64_t& at, std::size_t max, std::string& out) {
  out.clear();
  for (char ch = 0; out.size() <= max;) {
    if (!file.read(at, &ch, 1)) return false;
    ++at;
    if (ch == '\0') return true;
    out += ch;
  }
  return false;  // not NUL-terminated: OpenEXR refuses it
}

std::int32_t little_i32(const unsigned char* b) {
  const std::uint32_t u = std::uint32_t{b[0]} | std::uint32_t{b[1]} << 8 | std::uint32_t{b[2]} << 16 |
                          std::uint32_t{b[3]} << 24;
  std::int32_t v;
  std::memcpy(&v, &u, sizeof v);
  return v;
}

// Scanlines per chunk of an OpenEXR compression.
std::uint64_t exr_lines_per_chunk(int compression) {
  switch (compression) {
    case 3: case 5: return 16;          // ZIP, PXR24
    case 4: case 6: case 7: case 8: return 32;  // PIZ, B44, B44A, DWAA
    case 9: return 256;                 // DWAB
    default: return 1;                  // NONE, RLE, ZIPS
  }
}

// The bytes OpenEXR reads for a value of a fixed-size attribute type, or 0.
std::uint64_t exr_fixed_size(const std::string& type) {
  static const std::pair<const char*, std::uint64_t> kSizes[] = {
      {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"double", 8}, {"envmap", 1},
      {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1}, {"m33f", 36}, {"m33d", 72}, {"m44f", 64},
      {"m44d", 128}, {"rational", 8}, {"tiledesc", 9}, {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16},
      {"v3i", 12}, {"v3f", 12}, {"v3d", 24}, {"deepImageState", 1}};
  for (const auto& [name, size] : kSizes)
    if (type == name) return size;
  return 0;
}

// The problem with an OpenEXR header that would make OpenEXR allocate more than the file or
// the budget allows, or "" (also for what is merely malformed: OpenEXR says that).
std::string exr_header_problem(const FileBytes& file, const TexelBudget& budget) {
  std::string problem;
  std::array<unsigned char, 8> head{};
  if (file.read(0, head.data(), head.size())) {
    const std::uint32_t flags = static_cast<std::uint32_t>(little_i32(head.data() + 4));
    const bool multipart = (flags & 0x1000) != 0, single_tiled = (flags & 0x200) != 0;
    constexpr std::size_t max_name = 255;  // OpenEXR reads 255 whatever the long-names flag
    std::uint64_t at = 8;
    for (int part = 0; problem.empty(); ++part) {
      // One header: attributes until an empty name.
      std::array<std::int32_t, 4> data{0, 0, -1, -1}, display{0, 0, -1, -1};
      bool has_data = false, has_display = false, tiled = single_tiled;
      int compression = 0;
      std::uint32_t tile_w = 0, tile_h = 0;
      std::string name, type;
      bool any = false;
      for (;;) {
        if (!read_name(file, at, max_name, name)) return std::string();
        if (name.empty()) break;
        any = true;
        unsigned char size_bytes[4];
        if (!read_name(file, at, max_name, type) || !file.read(at, size_bytes, 4)) return std::string();
        at += 4;
        const std::int32_t size = little_i32(size_bytes);
        if (size < 0) return std::string();  // OpenEXR refuses it
        // OpenEXR reads a value of a known fixed-size type by its type, whatever `size` says;
        // the others (strings, vectors, opaque) by `size`.
        std::uint64_t length = static_cast<std::uint64_t>(size);
        if (const std::uint64_t fixed = exr_fixed_size(type); fixed != 0) {
          length = fixed;
        } else if (type == "chlist") {  // entries "name\0" + 16 bytes, until an empty name
          std::uint64_t p = at;
          for (std::string channel;;) {
            if (!read_name(file, p, max_name, channel)) return std::string();
            if (channel.empty()) break;
            p += 16;
          }
          length = p - at;
        } else if (type == "preview") {  // width, height, then 4 bytes a texel
          unsigned char wh[8];
          if (!file.read(at, wh, 8)) return std::string();
          const std::uint64_t texels = std::uint64_t{static_cast<std::uint32_t>(little_i32(wh))} *
                                       static_cast<std::uint32_t>(little_i32(wh + 4));
          if (texels > (file.size() - at) / 4) {
            problem = "the header's preview image declares " + std::to_string(texels) +
                      " texels, more than the file holds";
            break;
          }
          length = 8 + 4 * texels;
        }
        if (length > file.size() - at) {
          problem = "the header's attribute '" + name.substr(0, 64) + "' declares " + std::to_string(length) +
                    " bytes, more than the file holds";
          break;
        }
        unsigned char value[16] = {};
        const bool small = length <= 16 && file.read(at, value, static_cast<std::size_t>(length));
        if (small && type == "box2i") {
          std::array<std::int32_t, 4>& box = name == "dataWindow" ? data : display;
          if (name == "dataWindow" || name == "displayWindow") {
            for (int k = 0; k < 4; ++k) box[k] = little_i32(value + 4 * k);
            (name == "dataWindow" ? has_data : has_display) = true;
          }
        } else if (small && name == "compression" && type == "compression") {
          compression = value[0];
        } else if (small && type == "tiledesc") {
          tile_w = static_cast<std::uint32_t>(little_i32(value));
          tile_h = static_cast<std::uint32_t>(little_i32(value + 4));
          tiled = true;
        } else if (name == "type" && type == "string") {
          std::string kind(static_cast<std::size_t>(std::min(size, 32)), '\0');
          if (file.read(at, kind.data(), kind.size())) tiled = kind.rfind("tiled", 0) == 0 || kind.rfind("deeptile", 0) == 0;
        }
        at += length;
      }
      if (!problem.empty() || (multipart && !any)) break;  // the empty header ends the parts
      const long long dw = has_data ? static_cast<long long>(data[2]) - data[0] + 1 : 0;
      const long long dh = has_data ? static_cast<long long>(data[3]) - data[1] + 1 : 0;
      const long long fw = has_display ? static_cast<long long>(display[2]) - display[0] + 1 : 0;
      const long long fh = has_display ? static_cast<long long>(display[3]) - display[1] + 1 : 0;
      if (problem.empty() && fw > 0 && fh > 0) problem = budget_problem("the image", fw, fh, budget);
      if (problem.empty() && dw > 0 && dh > 0) problem = budget_problem("the data window", dw, dh, budget);
      if (problem.empty() && dw > 0 && dh > 0) {
        // The chunk offset table OpenEXR allocates: at least one 8-byte entry a chunk of level 0.
        const std::uint64_t chunks =
            tiled && tile_w > 0 && tile_h > 0
                ? ((static_cast<std::uint64_t>(dw) + tile_w - 1) / tile_w) * ((static_cast<std::uint64_t>(dh) + tile_h - 1) / tile_h)
                : (static_cast<std::uint64_t>(dh) + exr_lines_per_chunk(compression) - 1) / exr_lines_per_chunk(compression);
        if (chunks > file.size() / 8)
          problem = "the header declares " + std::to_string(chunks) + " chunks, more than the file of " +
                    std::to_string(file.size()) + " bytes can hold";
      }
      if (!multipart) break;
      if (part > 10000) break;
    }
  }
  return problem;
}

}  // namespace

std::string budget_problem(const char* what, long long w, long long h, const TexelBudget& budget) {
  const auto texels = static_cast<std::uint64_t>(std::max(0LL, w)) * static_cast<std::uint64_t>(std::max(0LL, h));
  const std::uint64_t images = std::max<std::uint32_t>(1, budget.images);
  // texels * images > max, without overflow (texels < 2^64 / 4, images small).
  if (texels <= budget.max_texels / images) return {};
  std::string line = std::string(what) + " is " + std::to_string(w) + "x" + std::to_string(h) + " (" +
                     std::to_string(texels) + " texels";
  if (images > 1) line += ", " + std::to_string(texels * images) + " for " + std::to_string(images) + " images";
  return line + "), above the budget of " + std::to_string(budget.max_texels) + " (--max-texels)";
}

std::string with_reason(std::string what, const std::string& reason) {
  if (reason.find_first_not_of(" \t\r\n") != std::string::npos) what += " (" + reason + ")";
  return what;
}

IoStatus open_image(const std::filesystem::path& path, const TexelBudget& budget,
                    std::unique_ptr<ImageDecoder>& decoder) {
  decoder.reset();
  if (IoStatus st = check_readable_file(path); !st.ok()) return st;
  FileBytes file;
  if (const int error = file.open(path); error != 0) return file_error(path, error);
  const std::string head = file.read_some(0, kMagicBytes);
  if (is_radiance_magic(head)) return open_hdr(path, std::move(file), budget, decoder);
  if (is_pfm_magic(head)) return open_pfm(path, std::move(file), budget, decoder);
  std::string reason;
  if (is_openexr(head)) {
    if (const std::string problem = exr_header_problem(file, budget); !problem.empty())
      return IoStatus::error(IoErrc::Unsupported, path, problem);
    decoder = open_exr(path, reason);
  } else {
    std::string problem;
    const OiioPlugin* plugin = oiio_plugin(problem);
    if (plugin == nullptr) {
      std::string what = "formats other than OpenEXR, Radiance .hdr and PFM are read through OpenImageIO: ";
      what += problem;
      return IoStatus::error(IoErrc::Unreadable, path, what);
    }
    decoder.reset(plugin->open(path.c_str(), &reason));
  }
  if (!decoder) return IoStatus::error(IoErrc::Unreadable, path, with_reason("not an image that can be read", reason));
  return IoStatus::success();
}

std::string part_problem(const ImagePart& part) {
  if (part.data.width <= 0 || part.data.height <= 0 || part.display.width <= 0 || part.display.height <= 0)
    return "the image has zero size";
  if (part.channels.empty()) return "the image has no channels";
  // A data window other than the display window is fine: image_source.h reads it.
  return part.problem;
}

}  // namespace shpack::io::detail
