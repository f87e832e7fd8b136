// io_test_files.h - files for the io tests: a scratch folder, images of any channel
// count and type written with OpenImageIO, raw bytes, and the repository's data.
#pragma once

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <string>
#include <vector>

namespace shpack_io_test {

// A fresh folder under the test temp dir, named after the running test; removed with
// everything in it when the object dies.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// Writes float `pixels` (width * height * channels, row-major from the top) to `path`, in
// the format its extension names, stored as `file_type` (OpenImageIO converts; k/255 becomes
// exactly k in uint8), with extra spec attributes. Fails the current test (ADD_FAILURE) and
// returns false if OpenImageIO cannot.
bool write_image(const std::filesystem::path& path, int width, int height, int channels,
                 const std::vector<float>& pixels, OIIO::TypeDesc file_type = OIIO::TypeDesc::FLOAT,
                 const std::vector<OIIO::ParamValue>& attributes = {});

// A float image whose channels carry `names` (e.g. {"Y", "A"}), every texel set to `texel`.
bool write_named_constant_image(const std::filesystem::path& path, int width, int height,
                                const std::vector<std::string>& names, const std::vector<float>& texel);

// A width x height image with every texel set to `texel` (its size is the channel count).
bool write_constant_image(const std::filesystem::path& path, int width, int height,
                          const std::vector<float>& texel, OIIO::TypeDesc file_type = OIIO::TypeDesc::FLOAT,
                          const std::vector<OIIO::ParamValue>& attributes = {});

std::vector<char> read_bytes(const std::filesystem::path& path);
void write_bytes(const std::filesystem::path& path, const std::vector<char>& bytes);
void write_string(const std::filesystem::path& path, const std::string& bytes);

// The first three channels of an image, read whole as float by OpenImageIO; empty, with
// the test failed (ADD_FAILURE), if it cannot be read.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // row-major from the top
};
RgbImage read_rgb(const std::filesystem::path& path);

// Writes `bytes` to `path` and reads it with read_image_file, which must fail with one line
// "<path>: <reason>" (the test fails otherwise); returns <reason>.
std::string read_failure(const std::filesystem::path& path, const std::string& bytes);

// data/hdri/<name> in the source tree.
std::filesystem::path hdri(const std::string& name);

}  // namespace shpack_io_test
