// lib/io reads PFM with its own reader (lib/io/src/pfm_decoder.h), where OpenImageIO read it
// before. OpenImageIO cannot write PFM, so this file writes its own, little- and big-endian,
// RGB and grey. The oracles: the floats written (a scale of +-1 multiplies by 1, which is
// exact), and OpenImageIO's decode of the same file; both compared bit for bit (no
// arithmetic but one float multiplication by the scale, the same in both readers).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "image_open.h"
#include "io_test_files.h"
#include "shpack/io/image_file.h"

namespace {

namespace fs = std::filesystem;
using shpack::io::ImageFile;
using shpack::io::IoStatus;
using shpack_io_test::ScratchDir;
using shpack_io_test::write_string;

// The PFM bytes of `pixels` (`channels` a texel, top row first): the header with `scale` as
// written, then the rows bottom to top, little-endian if `little` else big-endian.
std::string pfm_bytes(int width, int height, int channels, const std::vector<float>& pixels, bool little,
                      const std::string& scale) {
  std::string out = (channels == 3 ? "PF\n" : "Pf\n") + std::to_string(width) + " " + std::to_string(height) + "\n";
  out += scale + "\n";
  for (int y = height - 1; y >= 0; --y) {
    for (int i = 0; i < width * channels; ++i) {
      const auto bits = std::bit_cast<std::uint32_t>(pixels[static_cast<std::size_t>(y * width * channels + i)]);
      for (int b = 0; b < 4; ++b) out += static_cast<char>(bits >> (little ? 8 * b : 24 - 8 * b));
    }
  }
  return out;
}

std::vector<float> oiio_pixels(const fs::path& path) {
  const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> out(std::size_t(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out.data())) << in->geterror();
  return out;
}

ImageFile read_ok(const fs::path& path) {
  ImageFile image;
  const IoStatus st = shpack::io::read_image_file(path, image);
  EXPECT_TRUE(st.ok()) << st.message;
  return image;
}

void expect_same_floats(const std::vector<float>& got, const std::vector<float>& want, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < want.size(); ++i) {
    if (std::memcmp(&got[i], &want[i], sizeof(float)) != 0) {
      ADD_FAILURE() << what << ": value " << i << " is " << got[i] << ", want " << want[i];
      return;
    }
  }
}

// Radiance over five decades, some negative, zeros, and the non-finite values PFM can hold.
std::vector<float> test_pixels(std::size_t count) {
  std::mt19937_64 rng(0x5eed);
  std::normal_distribution<float> log_radiance(0.0f, 3.0f);
  std::vector<float> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = std::exp(log_radiance(rng)) * (i % 13 == 0 ? -1.0f : 1.0f);
  out[1] = 0.0f;
  if (count > 4) {
    out[3] = std::numeric_limits<float>::infinity();
    out[4] = 1e-42f;  // a subnormal
  }
  return out;
}

// The reason reading `bytes` as a .pfm fails.
std::string failure(const ScratchDir& dir, const std::string& bytes) {
  return shpack_io_test::read_failure(dir / "bad.pfm", bytes);
}

TEST(PfmReader, BundledMapsInBothByteOrdersAreReadAsWrittenAndAsOpenImageIOReadsThem) {
  const ScratchDir dir;
  int maps = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(shpack_io_test::hdri(""))) {
    if (e.path().extension() != ".exr") continue;
    const shpack_io_test::RgbImage exr = shpack_io_test::read_rgb(e.path());
    ASSERT_FALSE(exr.rgb.empty());
    const std::vector<float>& rgb = exr.rgb;
    for (const bool little : {true, false}) {
      const fs::path pfm = dir / (e.path().stem().string() + (little ? "_le.pfm" : "_be.pfm"));
      write_string(pfm, pfm_bytes(exr.width, exr.height, 3, rgb, little, little ? "-1.0" : "1.0"));
      const ImageFile image = read_ok(pfm);
      EXPECT_EQ(image.format, "pnm");  // OpenImageIO's name for the format, kept in documents
      EXPECT_EQ(image.channels, 3u);
      EXPECT_FALSE(image.srgb_decoded);
      expect_same_floats(image.pixels, rgb, pfm.string());
      expect_same_floats(image.pixels, oiio_pixels(pfm), pfm.string() + " (OpenImageIO)");
    }
    ++maps;
  }
  EXPECT_GT(maps, 0);
}

TEST(PfmReader, GreyIsOneChannelNamedY) {
  const ScratchDir dir;
  const std::vector<float> grey = test_pixels(5 * 3);
  write_string(dir / "g.pfm", pfm_bytes(5, 3, 1, grey, false, "1"));
  const ImageFile image = read_ok(dir / "g.pfm");
  EXPECT_EQ(image.channels, 1u);
  EXPECT_EQ(image.file_channels, 1u);
  expect_same_floats(image.pixels, grey, "grey");
  expect_same_floats(image.pixels, oiio_pixels(dir / "g.pfm"), "grey (OpenImageIO)");
}

TEST(PfmReader, RowsAreStoredBottomUp) {
  // Written by hand: the file's first row (1, 2) is the image's bottom row.
  const ScratchDir dir;
  std::string bytes = "Pf\n2 2\n-1.0\n";
  for (const float v : {1.0f, 2.0f, 3.0f, 4.0f}) {
    const auto bits = std::bit_cast<std::uint32_t>(v);
    for (int b = 0; b < 4; ++b) bytes += static_cast<char>(bits >> (8 * b));
  }
  write_string(dir / "r.pfm", bytes);
  expect_same_floats(read_ok(dir / "r.pfm").pixels, {3.0f, 4.0f, 1.0f, 2.0f}, "rows");
}

TEST(PfmReader, TheScaleMultipliesEveryValueAsOpenImageIODoes) {
  // |scale| * value in float, as OpenImageIO's reader computes it; 2.5 * 2 = 5 exactly.
  const ScratchDir dir;
  const std::vector<float> rgb = test_pixels(4 * 2 * 3);
  write_string(dir / "s.pfm", pfm_bytes(4, 2, 3, rgb, true, "-2.5"));
  const ImageFile image = read_ok(dir / "s.pfm");
  std::vector<float> want(rgb.size());
  std::transform(rgb.begin(), rgb.end(), want.begin(), [](float v) { return v * 2.5f; });
  expect_same_floats(image.pixels, want, "scaled");
  expect_same_floats(image.pixels, oiio_pixels(dir / "s.pfm"), "scaled (OpenImageIO)");
  write_string(dir / "two.pfm", "Pf\n1 1\n+2\n" + std::string("\x40\x00\x00\x00", 4));  // big-endian 2.0
  expect_same_floats(read_ok(dir / "two.pfm").pixels, {4.0f}, "+2");
}

TEST(PfmReader, HeaderCommentsAndBlanksAreRead) {
  const ScratchDir dir;
  const std::vector<float> rgb = test_pixels(3 * 2 * 3);
  const std::string rows = pfm_bytes(3, 2, 3, rgb, true, "-1").substr(std::string("PF\n3 2\n-1\n").size());
  for (const std::string& header : {std::string("PF\n# a comment\n3 2\n# another\n-1\n"),
                                    std::string("PF  3\t2 \n  -1.000000 "), std::string("PF 3 2 -1\n")}) {
    write_string(dir / "h.pfm", header + rows);
    expect_same_floats(read_ok(dir / "h.pfm").pixels, rgb, header);
  }
}

TEST(PfmReader, BandsInAnyOrderAreTheRowsOfTheWholeImage) {
  const ScratchDir dir;
  const long long w = 7, h = 9;
  write_string(dir / "b.pfm", pfm_bytes(7, 9, 3, test_pixels(7 * 9 * 3), false, "1"));
  using shpack::io::detail::ImageDecoder;
  for (const std::vector<int>& channels : {std::vector<int>{0, 1, 2}, std::vector<int>{1}, std::vector<int>{2, 0}}) {
    std::unique_ptr<ImageDecoder> decoder;
    const IoStatus st = shpack::io::detail::open_image(dir / "b.pfm", {shpack::io::kDefaultMaxTexels, 1}, decoder);
    ASSERT_TRUE(st.ok()) << st.message;
    const std::size_t row = static_cast<std::size_t>(w) * channels.size();
    std::vector<float> all(row * static_cast<std::size_t>(h));
    std::string error;
    ASSERT_TRUE(decoder->read_rows(0, 0, h, channels, all.data(), error)) << error;
    for (const long long first : {6LL, 2LL, 0LL, 8LL, 3LL}) {
      const long long end = std::min(h, first + 3);
      std::vector<float> band(row * static_cast<std::size_t>(end - first));
      ASSERT_TRUE(decoder->read_rows(0, first, end, channels, band.data(), error)) << error;
      expect_same_floats(
          band, {all.begin() + static_cast<long long>(row) * first, all.begin() + static_cast<long long>(row) * end},
          "rows " + std::to_string(first));
    }
  }
}

// ---- hostile files

TEST(PfmReader, TruncatedAtEveryByteFailsInOneLine) {
  const ScratchDir dir;
  const std::string file = pfm_bytes(3, 2, 3, test_pixels(18), true, "-1.0");
  for (std::size_t size = 0; size < file.size(); ++size) {
    SCOPED_TRACE("cut at " + std::to_string(size));
    failure(dir, file.substr(0, size));
  }
  write_string(dir / "whole.pfm", file);
  expect_same_floats(read_ok(dir / "whole.pfm").pixels, test_pixels(18), "the whole file");
}

TEST(PfmReader, SizesBeyondTheBudgetOrTheFileAreRefusedAtOpen) {
  const ScratchDir dir;
  EXPECT_EQ(failure(dir, "PF\n2147483647 2147483647\n-1\n"),
            "the image is 2147483647x2147483647 (4611686014132420609 texels), above the budget of 268435456 "
            "(--max-texels)");
  EXPECT_EQ(failure(dir, "PF\n4 2\n-1.0\n" + std::string(8, '\0')),
            "the PFM header declares 4x2 texels of 12 bytes, but the file holds 8 bytes after its header (it is "
            "truncated)");
  EXPECT_EQ(failure(dir, "Pf\n16384 8192\n-1\n"),
            "the PFM header declares 16384x8192 texels of 4 bytes, but the file holds 0 bytes after its header (it is "
            "truncated)");
}

TEST(PfmReader, MalformedHeadersAreNamed) {
  const ScratchDir dir;
  EXPECT_EQ(failure(dir, "PF\n0 2\n-1\n"), "the PFM header's width '0' is not a whole number from 1 to 2147483647");
  EXPECT_EQ(failure(dir, "PF\n4 -2\n-1\n"), "the PFM header's height '-2' is not a whole number from 1 to 2147483647");
  EXPECT_EQ(failure(dir, "PF\n4 2147483648\n-1\n"),
            "the PFM header's height '2147483648' is not a whole number from 1 to 2147483647");
  EXPECT_EQ(failure(dir, "PF\n4x 2\n-1\n"), "the PFM header's width '4x' is not a whole number from 1 to 2147483647");
  for (const char* scale : {"0", "-0.0", "nan", "inf", "1e39", "one"}) {
    EXPECT_EQ(failure(dir, "PF\n1 1\n" + std::string(scale) + "\n" + std::string(12, '\0')),
              "the PFM header's scale '" + std::string(scale) +
                  "' is not a finite number other than 0 (its sign gives the byte order)");
  }
  EXPECT_EQ(failure(dir, "PF\n1 1\n-1"), "the file ends inside the PFM header");
  EXPECT_EQ(failure(dir, "PF\n# " + std::string(70000, 'c') + "\n1 1\n-1\n"),
            "the PFM header does not end in the file's first 65536 bytes");
}

}  // namespace
