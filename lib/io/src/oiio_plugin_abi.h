// oiio_plugin_abi.h (private) - the entry points of shpack's OpenImageIO module
// (libshpack_oiio.so, built from lib/io/oiio). lib/io opens the module with dlopen the first
// time a file needs it (oiio_plugin.h), so that reading OpenEXR, --help and eval never load
// libOpenImageIO and the hundreds of libraries Debian's build of it links.
//
// Both sides are built from the same tree with the same compiler; kOiioPluginAbi guards
// against a module left over from another build.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image_decoder.h"

namespace shpack::io::detail {

inline constexpr int kOiioPluginAbi = 2;
inline constexpr const char* kOiioPluginFile = "libshpack_oiio.so";

using OiioAbiFn = int();
// The decoder of `path` (any format OpenImageIO reads), or null with the reason in `error`.
using OiioOpenFn = ImageDecoder*(const char* path, std::string* error);
// An 8-bit sRGB RGB image encoded as PNG into `bytes`, or false with the reason in `error`.
using OiioEncodePngFn = bool(std::uint32_t width, std::uint32_t height, const std::uint8_t* rgb,
                             std::vector<unsigned char>* bytes, std::string* error);

// One line of UTF-8 text drawn by FreeType (through OpenImageIO) with the TrueType font at
// `font`, `size` pixels high: its coverage, 0..255 per pixel, `width` x `height` (= size)
// row-major, the baseline at 4/5 of the height; or false with the reason in `error` (no such font, ...).
using OiioRenderTextFn = bool(const char* utf8, const char* font, int size, std::vector<std::uint8_t>* coverage,
                              std::uint32_t* width, std::uint32_t* height, std::string* error);

}  // namespace shpack::io::detail

extern "C" {
int shpack_oiio_abi();
shpack::io::detail::ImageDecoder* shpack_oiio_open(const char* path, std::string* error);
bool shpack_oiio_encode_png(std::uint32_t width, std::uint32_t height, const std::uint8_t* rgb,
                            std::vector<unsigned char>* bytes, std::string* error);
bool shpack_oiio_render_text(const char* utf8, const char* font, int size, std::vector<std::uint8_t>* coverage,
                             std::uint32_t* width, std::uint32_t* height, std::string* error);
}
