// scene_files.h - scene files for tests/scene and tests/bake, written into a scratch folder.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace shpack_test {

// A fresh folder per test process (ctest runs each test in its own), removed when the
// process's tests end (ScratchCleanup, registered below in every executable that includes this).
inline std::filesystem::path scene_scratch() {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("shpack_scene_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

// Base64 (RFC 4648) of `bytes`, for glTF data: URIs.
inline std::string base64(const std::string& bytes) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t at = 0; at < bytes.size(); at += 3) {
    std::uint32_t v = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at])) << 16;
    if (at + 1 < bytes.size()) v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + 1])) << 8;
    if (at + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[at + 2]);
    out += k[(v >> 18) & 63];
    out += k[(v >> 12) & 63];
    out += at + 1 < bytes.size() ? k[(v >> 6) & 63] : '=';
    out += at + 2 < bytes.size() ? k[v & 63] : '=';
  }
  return out;
}

inline std::filesystem::path write_scene(const std::string& name, const std::string& text) {
  const std::filesystem::path path = scene_scratch() / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

class ScratchCleanup : public testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(scene_scratch(), ec);
  }
};

// The scratch folder of this process goes when its tests end; one registration per
// executable (an inline variable), whichever of its files include this header.
inline testing::Environment* const kSceneScratchCleanup = testing::AddGlobalTestEnvironment(new ScratchCleanup);

}  // namespace shpack_test
