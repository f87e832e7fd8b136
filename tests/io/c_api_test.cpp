// The C ABI (shpack_c.h): the same numbers as the CLI's JSON, bit for bit, for the same
// texels and options; streaming equals one shot; errors are codes with static messages; and
// the shared library exports nothing but the shpack_* functions.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/io/image_file.h"
#include "shpack/shpack_c.h"
#include "shpack/unity_pack.h"

namespace {

using shpack_io_test::hdri;
using shpack_io_test::run_shpack;
using shpack_io_test::ScratchDir;
using Json = nlohmann::json;

constexpr const char* kShaderKeys[7] = {"unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr",
                                        "unity_SHBg", "unity_SHBb", "unity_SHC"};

shpack_image image_of(const shpack::io::ImageFile& file) {
  return {file.pixels.data(), SHPACK_PIXEL_F32, file.width, file.height, file.channels, 0, 0};
}

// Every number of the JSON document equals the C result's, as the same double or float bits.
void expect_result_is_document(const shpack_result& r, const Json& doc) {
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < 9; ++i) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(r.radiance_sh[9 * c + i]),
                std::bit_cast<std::uint64_t>(doc["radiance_sh"][c][i].get<double>()))
          << "radiance c=" << c << " i=" << i;
      EXPECT_EQ(std::bit_cast<std::uint32_t>(r.unity_sh[9 * c + i]),
                std::bit_cast<std::uint32_t>(static_cast<float>(doc["sphericalHarmonicsL2"][c][i].get<double>())))
          << "sh c=" << c << " i=" << i;
    }
    EXPECT_EQ(r.min_e_over_pi[c], doc["diagnostics"]["min_e_over_pi"][c].get<double>());
    for (int l = 0; l < 3; ++l)
      EXPECT_EQ(r.window_factors[3 * c + l], doc["diagnostics"]["window_factors"][c][l].get<double>());
  }
  for (int v = 0; v < 7; ++v)
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(std::bit_cast<std::uint32_t>(r.shader[4 * v + k]),
                std::bit_cast<std::uint32_t>(static_cast<float>(doc["shader"][kShaderKeys[v]][k].get<double>())))
          << kShaderKeys[v] << "[" << k << "]";
  EXPECT_EQ(r.negative_texels, doc["diagnostics"]["negative_texels"].get<std::uint64_t>());
  EXPECT_EQ(r.nonfinite_texels, doc["diagnostics"]["nonfinite_texels"].get<std::uint64_t>());
}

TEST(CApi, ConvertEquirectMatchesTheCommandLine) {
  const ScratchDir dir;
  struct Case {
    const char* map;
    std::vector<std::string> flags;
    shpack_options options;
  };
  shpack_options defaults;
  shpack_default_options(&defaults);
  shpack_options turned = defaults, centre = defaults;
  turned.rotate_deg = 30;
  turned.intensity = 2.5;
  turned.window = "sloan";
  centre.method = SHPACK_METHOD_CENTER;
  centre.negative = SHPACK_NEGATIVE_CLAMP;
  centre.window = "hanning:3.5";
  const Case cases[] = {
      {"courtyard.exr", {}, defaults},
      {"sunset.exr", {"--rotate", "30", "--intensity", "2.5", "--window", "sloan"}, turned},
      {"night.exr", {"--method", "center", "--negative", "clamp", "--window", "hanning:3.5"}, centre},
  };
  for (const Case& test : cases) {
    std::vector<std::string> args = {"convert", hdri(test.map).string()};
    args.insert(args.end(), test.flags.begin(), test.flags.end());
    const shpack_io_test::CliRun run = run_shpack(dir, args);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    shpack::io::ImageFile file;
    ASSERT_TRUE(shpack::io::read_image_file(hdri(test.map), file).ok());
    const shpack_image image = image_of(file);
    shpack_result result;
    shpack_error error;
    ASSERT_EQ(shpack_convert_equirect(&image, &test.options, &result, &error), SHPACK_OK) << error.message;
    EXPECT_EQ(error.code, SHPACK_OK);
    SCOPED_TRACE(test.map);
    expect_result_is_document(result, Json::parse(run.out));
  }
}

TEST(CApi, StreamingInBandsEqualsOneShot) {
  shpack::io::ImageFile file;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("studio.exr"), file).ok());
  shpack_options options;
  shpack_default_options(&options);
  options.threads = 2;
  shpack_result whole, streamed;
  const shpack_image image = image_of(file);
  ASSERT_EQ(shpack_convert_equirect(&image, &options, &whole, nullptr), SHPACK_OK);

  shpack_projector* projector = nullptr;
  ASSERT_EQ(shpack_projector_create(file.width, file.height, &options, &projector, nullptr), SHPACK_OK);
  ASSERT_NE(projector, nullptr);
  const std::uint32_t band = 100;  // not a multiple of the core's 64-row tiles
  for (std::uint32_t row = 0; row < file.height; row += band) {
    const std::uint32_t rows = std::min(band, file.height - row);
    const shpack_image part = {file.pixels.data() + std::size_t{row} * file.width * file.channels, SHPACK_PIXEL_F32,
                               file.width, rows, file.channels, 0, 0};
    ASSERT_EQ(shpack_projector_add_rows(projector, &part, row, nullptr), SHPACK_OK) << row;
  }
  ASSERT_EQ(shpack_projector_finish(projector, &streamed, nullptr), SHPACK_OK);
  shpack_error error;
  EXPECT_EQ(shpack_projector_finish(projector, &streamed, &error), SHPACK_BAD_SEQUENCE);
  EXPECT_STREQ(error.message, "the projector was already finished");
  shpack_projector_destroy(projector);
  for (int k = 0; k < 27; ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(streamed.radiance_sh[k]), std::bit_cast<std::uint64_t>(whole.radiance_sh[k]));
    EXPECT_EQ(std::bit_cast<std::uint32_t>(streamed.unity_sh[k]), std::bit_cast<std::uint32_t>(whole.unity_sh[k]));
  }
}

TEST(CApi, ErrorsAreCodesWithStaticMessagesAndLeaveTheResult) {
  shpack_options options;
  shpack_default_options(&options);
  std::vector<float> pixels(8 * 4 * 3, 1.0f);
  pixels[(2 * 8 + 5) * 3 + 1] = std::numeric_limits<float>::quiet_NaN();
  shpack_image image = {pixels.data(), SHPACK_PIXEL_F32, 8, 4, 3, 0, 0};
  shpack_result result{};
  result.unity_sh[0] = 42.0f;  // a failed call leaves it
  shpack_error error;

  EXPECT_EQ(shpack_convert_equirect(&image, &options, &result, &error), SHPACK_NONFINITE_TEXEL);
  EXPECT_EQ(error.code, SHPACK_NONFINITE_TEXEL);
  EXPECT_EQ(error.x, 5u);
  EXPECT_EQ(error.y, 2u);
  EXPECT_STREQ(shpack_status_name(error.code), "nonfinite_texel");
  EXPECT_EQ(result.unity_sh[0], 42.0f);

  options.nonfinite = SHPACK_NONFINITE_ZERO;
  ASSERT_EQ(shpack_convert_equirect(&image, &options, &result, &error), SHPACK_OK);
  EXPECT_EQ(result.nonfinite_texels, 1u);

  options.window = "gaussian:2";
  EXPECT_EQ(shpack_convert_equirect(&image, &options, &result, &error), SHPACK_INVALID_ARGUMENT);
  EXPECT_GT(std::string(error.message).size(), 0u);
  options.window = nullptr;
  options.intensity = -1;
  EXPECT_EQ(shpack_convert_equirect(&image, &options, &result, &error), SHPACK_INVALID_ARGUMENT);
  EXPECT_STREQ(error.message, "intensity must be finite and >= 0");
  options.intensity = 1;
  options.method = 7;
  EXPECT_EQ(shpack_convert_equirect(&image, &options, &result, &error), SHPACK_INVALID_ARGUMENT);
  options.method = SHPACK_METHOD_EXACT;
  image.row_stride = 4;  // rows overlap
  EXPECT_EQ(shpack_convert_equirect(&image, &options, &result, &error), SHPACK_BAD_VIEW);
  EXPECT_EQ(shpack_convert_equirect(nullptr, &options, &result, &error), SHPACK_INVALID_ARGUMENT);
  EXPECT_EQ(shpack_convert_equirect(&image, &options, &result, nullptr), SHPACK_BAD_VIEW);  // error may be NULL
  EXPECT_EQ(shpack_projector_create(8, 4, nullptr, nullptr, &error), SHPACK_INVALID_ARGUMENT);
  shpack_projector_destroy(nullptr);
}

TEST(CApi, HalfFloatsAndBottomUpRowsAreViews) {
  // A 4 x 2 map stored as F16, bottom row first (a negative row stride), against F32 top-down.
  const std::vector<float> top_down = {1, 2, 3, 4, 5, 6, 7, 8, 0.5f, 0.25f, 2, 4};  // grey, 1 channel
  std::vector<std::uint16_t> half_bottom_up(8);
  const auto to_half = [](float v) {  // exact for these values: small integers and powers of two
    const std::uint32_t b = std::bit_cast<std::uint32_t>(v);
    return static_cast<std::uint16_t>(((b >> 16) & 0x8000) | ((((b >> 23) & 0xff) - 112) << 10) | ((b >> 13) & 0x3ff));
  };
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) half_bottom_up[(1 - y) * 4 + x] = to_half(top_down[y * 4 + x]);
  shpack_options options;
  shpack_default_options(&options);
  const shpack_image f32 = {top_down.data(), SHPACK_PIXEL_F32, 4, 2, 1, 0, 0};
  const shpack_image f16 = {half_bottom_up.data() + 4, SHPACK_PIXEL_F16, 4, 2, 1, 0, -8};
  shpack_result a, b;
  ASSERT_EQ(shpack_convert_equirect(&f32, &options, &a, nullptr), SHPACK_OK);
  shpack_error error;
  ASSERT_EQ(shpack_convert_equirect(&f16, &options, &b, &error), SHPACK_OK) << error.message;
  for (int k = 0; k < 27; ++k) EXPECT_EQ(a.radiance_sh[k], b.radiance_sh[k]) << k;
}

TEST(CApi, ShadeSh9IsUnitysShaderOnTheResult) {
  shpack::io::ImageFile file;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("forest.exr"), file).ok());
  shpack_options options;
  shpack_default_options(&options);
  const shpack_image image = image_of(file);
  shpack_result r;
  ASSERT_EQ(shpack_convert_equirect(&image, &options, &r, nullptr), SHPACK_OK);
  shpack::UnityShaderVectors v;
  shpack::UnityShaderVectors::Float4* vectors[7] = {&v.SHAr, &v.SHAg, &v.SHAb, &v.SHBr, &v.SHBg, &v.SHBb, &v.SHC};
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 4; ++j) (*vectors[k])[j] = r.shader[4 * k + j];
  float rgb[3];
  ASSERT_EQ(shpack_shade_sh9(r.shader, 0.6f, 0.0f, -0.8f, rgb), SHPACK_OK);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(rgb[c], shpack::shade_sh9(v, c, 0.6f, 0.0f, -0.8f));
  EXPECT_EQ(shpack_shade_sh9(nullptr, 0, 1, 0, rgb), SHPACK_INVALID_ARGUMENT);
}

TEST(CApi, SharedLibraryExportsOnlyTheCFunctions) {
#if defined(__linux__)
  const std::string command = std::string("nm -D --defined-only '") + SHPACK_C_LIBRARY_PATH + "'";
  std::FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char line[512];
  int functions = 0;
  while (std::fgets(line, sizeof line, pipe) != nullptr) {
    const std::string text(line);
    const std::string name = text.substr(text.find_last_of(' ') + 1, text.size() - text.find_last_of(' ') - 2);
    if (text.find(" T ") == std::string::npos) continue;  // code symbols only
    EXPECT_EQ(name.rfind("shpack_", 0), 0u) << name;
    ++functions;
  }
  EXPECT_EQ(::pclose(pipe), 0);
  EXPECT_EQ(functions, 10);  // the functions of shpack_c.h
#else
  GTEST_SKIP() << "nm -D is the check on Linux";
#endif
}

}  // namespace
