#include "io_test_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>

#include "shpack/io/image_file.h"

namespace shpack_io_test {

ScratchDir::ScratchDir() {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name = test != nullptr
                               ? std::string(test->test_suite_name()) + "." + test->name()
                               : std::string("no_test");
  path_ = std::filesystem::path(::testing::TempDir()) /
          ("shpack_io_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;  // a destructor cannot fail the test; a leftover folder is harmless
  std::filesystem::remove_all(path_, ignored);
}

bool write_image(const std::filesystem::path& path, int width, int height, int channels,
                 const std::vector<float>& pixels, OIIO::TypeDesc file_type,
                 const std::vector<OIIO::ParamValue>& attributes) {
  EXPECT_EQ(pixels.size(), static_cast<std::size_t>(width) * height * channels) << path;
  const std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
  if (!out) {
    ADD_FAILURE() << "cannot create a writer for " << path << ": " << OIIO::geterror();
    return false;
  }
  OIIO::ImageSpec spec(width, height, channels, file_type);
  for (const OIIO::ParamValue& p : attributes) spec.attribute(p.name(), p.type(), p.data());
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) ||
      !out->close()) {
    ADD_FAILURE() << "cannot write " << path << ": " << out->geterror();
    return false;
  }
  return true;
}

bool write_named_constant_image(const std::filesystem::path& path, int width, int height,
                                const std::vector<std::string>& names, const std::vector<float>& texel) {
  const std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
  if (!out) {
    ADD_FAILURE() << "cannot create a writer for " << path << ": " << OIIO::geterror();
    return false;
  }
  OIIO::ImageSpec spec(width, height, static_cast<int>(names.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = names;
  std::vector<float> pixels;
  for (int i = 0; i < width * height; ++i) pixels.insert(pixels.end(), texel.begin(), texel.end());
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close()) {
    ADD_FAILURE() << "cannot write " << path << ": " << out->geterror();
    return false;
  }
  return true;
}

bool write_constant_image(const std::filesystem::path& path, int width, int height,
                          const std::vector<float>& texel, OIIO::TypeDesc file_type,
                          const std::vector<OIIO::ParamValue>& attributes) {
  std::vector<float> pixels;
  for (int i = 0; i < width * height; ++i) pixels.insert(pixels.end(), texel.begin(), texel.end());
  return write_image(path, width, height, static_cast<int>(texel.size()), pixels, file_type, attributes);
}

std::vector<char> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::filesystem::path& path, const std::vector<char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void write_string(const std::filesystem::path& path, const std::string& bytes) {
  write_bytes(path, {bytes.begin(), bytes.end()});
}

RgbImage read_rgb(const std::filesystem::path& path) {
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
  if (!in) {
    ADD_FAILURE() << path << ": " << OIIO::geterror();
    return {};
  }
  const OIIO::ImageSpec& spec = in->spec();
  RgbImage image{spec.width, spec.height, std::vector<float>(std::size_t(spec.width) * spec.height * 3)};
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.rgb.data())) {
    ADD_FAILURE() << path << ": " << in->geterror();
    return {};
  }
  return image;
}

std::string read_failure(const std::filesystem::path& path, const std::string& bytes) {
  write_string(path, bytes);
  shpack::io::ImageFile image;
  const shpack::io::IoStatus st = shpack::io::read_image_file(path, image);
  EXPECT_FALSE(st.ok()) << path;
  EXPECT_EQ(st.message.rfind(path.string() + ": ", 0), 0u) << st.message;
  EXPECT_EQ(st.message.find('\n'), std::string::npos) << st.message;
  return st.message.substr(std::min(st.message.size(), path.string().size() + 2));
}

std::filesystem::path hdri(const std::string& name) {
  return std::filesystem::path(SHPACK_SOURCE_DIR) / "data" / "hdri" / name;
}

}  // namespace shpack_io_test
