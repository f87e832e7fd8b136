// scene_files.h - scene files for tests/scene, written into a scratch folder.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace shpack_test {

// A fresh folder per test process (ctest runs each test in its own), removed when the
// process's tests end (ScratchCleanup, registered in scene_loader_test.cpp).
inline std::filesystem::path scene_scratch() {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("shpack_scene_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
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

}  // namespace shpack_test
