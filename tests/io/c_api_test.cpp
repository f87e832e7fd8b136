// The C ABI (shpack_c.h): the same numbers as the CLI's JSON, bit for bit, for the same
// texels and options (every layout, the six faces, the sampling methods, the sun, every
// option of shpack_convert); streaming equals one shot; errors are codes with static
// messages; and the shared library exports nothing but the shpack_* functions.
#include <gtest/gtest.h>

#include <half.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
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

void expect_same_doubles(const double* got, const Json& want, std::size_t count, const char* what) {
  ASSERT_EQ(want.size(), count) << what;
  for (std::size_t k = 0; k < count; ++k)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got[k]), std::bit_cast<std::uint64_t>(want[k].get<double>()))
        << what << "[" << k << "]";
}

// The sun of shpack_convert is the document's "sun", bit for bit.
void expect_light_is_document(const shpack_light& light, const Json& sun) {
  expect_same_doubles(light.direction, sun["direction"], 3, "direction");
  expect_same_doubles(light.irradiance, sun["irradiance"], 3, "irradiance");
  expect_same_doubles(light.sky_level, sun["sky_level"], 3, "sky_level");
  EXPECT_EQ(light.angular_radius_deg, sun["angular_radius_deg"].get<double>());
  EXPECT_EQ(light.solid_angle_sr, sun["solid_angle_sr"].get<double>());
  EXPECT_EQ(light.texels, sun["texels"].get<std::uint64_t>());
  const Json& unity = sun["unity_light"];
  expect_same_doubles(light.forward, unity["forward"], 3, "forward");
  expect_same_doubles(light.euler_deg, unity["euler_deg"], 3, "euler_deg");
  expect_same_doubles(light.quaternion, unity["quaternion"], 4, "quaternion");
  expect_same_doubles(light.color, unity["color"], 3, "color");
  expect_same_doubles(light.color_srgb, unity["color_srgb"], 3, "color_srgb");
  EXPECT_EQ(light.intensity, unity["intensity"].get<double>());
}

// Texels in [-0.125, 2) from a fixed generator, a few negative: the comparisons are bit for
// bit, so any values do, and varied ones exercise every coefficient.
std::vector<float> noise_texels(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
  std::vector<float> pixels(std::size_t{width} * height * 3);
  std::uint32_t state = seed;
  for (float& v : pixels) {
    state = state * 1664525u + 1013904223u;
    v = static_cast<float>(state >> 8) / static_cast<float>(1u << 23) - 0.125f;
  }
  return pixels;
}

shpack_map map_of(const std::vector<float>& pixels, std::uint32_t width, std::uint32_t height, int32_t layout) {
  shpack_map map{};
  map.struct_size = sizeof map;
  map.layout = layout;
  map.image = {pixels.data(), SHPACK_PIXEL_F32, width, height, 3, 0, 0};
  return map;
}

shpack_map equirect_map(const shpack::io::ImageFile& file) {
  shpack_map map{};
  map.struct_size = sizeof map;
  map.layout = SHPACK_LAYOUT_EQUIRECT;
  map.image = image_of(file);
  return map;
}

shpack_convert_options convert_defaults() {
  shpack_convert_options options;
  shpack_default_convert_options(&options);
  return options;
}

// shpack_convert, which must succeed.
shpack_conversion convert_ok(const shpack_map& map, const shpack_convert_options& options) {
  shpack_conversion out{};
  out.struct_size = sizeof out;
  shpack_error error{};
  EXPECT_EQ(shpack_convert(&map, &options, &out, &error), SHPACK_OK) << error.message;
  return out;
}

// `shpack convert` with `args`, which must succeed: its JSON document.
Json command_document(const ScratchDir& dir, std::vector<std::string> args) {
  args.insert(args.begin(), "convert");
  const shpack_io_test::CliRun run = run_shpack(dir, args);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return run.exit_code == 0 ? Json::parse(run.out) : Json::object();
}

void expect_same_result(const shpack_result& a, const shpack_result& b) {
  for (int k = 0; k < 27; ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a.radiance_sh[k]), std::bit_cast<std::uint64_t>(b.radiance_sh[k])) << k;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(a.unity_sh[k]), std::bit_cast<std::uint32_t>(b.unity_sh[k])) << k;
  }
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
  // Its view error is shpack_convert's on the whole image.
  shpack_view_error view_error{};
  ASSERT_EQ(shpack_projector_view_error(projector, &view_error, nullptr), SHPACK_OK);
  shpack_projector_destroy(projector);
  shpack_map map = equirect_map(file);
  shpack_convert_options convert = convert_defaults();
  const shpack_conversion one_shot = convert_ok(map, convert);
  EXPECT_EQ(std::memcmp(&view_error, &one_shot.view_error, sizeof view_error), 0);
  EXPECT_EQ(view_error.directions, 512u);
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

TEST(CApiConvert, EveryLayoutMatchesTheCommandLine) {
  const ScratchDir dir;
  struct Case {
    const char* name;
    int32_t layout;
    std::uint32_t width, height;
  };
  const Case cases[] = {
      {"equirect", SHPACK_LAYOUT_EQUIRECT, 64, 32},     {"hcross", SHPACK_LAYOUT_HCROSS, 64, 48},
      {"vcross", SHPACK_LAYOUT_VCROSS, 48, 64},         {"hstrip", SHPACK_LAYOUT_HSTRIP, 96, 16},
      {"vstrip", SHPACK_LAYOUT_VSTRIP, 16, 96},         {"octahedral", SHPACK_LAYOUT_OCTAHEDRAL, 32, 32},
      {"angular", SHPACK_LAYOUT_ANGULAR, 32, 32},       {"mirrorball", SHPACK_LAYOUT_MIRRORBALL, 32, 32},
  };
  // Every finish option at once, and the value policy, on every layout.
  shpack_convert_options options = convert_defaults();
  options.negative = SHPACK_NEGATIVE_CLAMP;
  options.intensity = 0.75;
  options.exposure_ev = 1.5;
  options.rotate_deg = 30;
  options.window = "hanning:3";
  const std::vector<std::string> flags = {"--negative", "clamp", "--intensity", "0.75", "--exposure", "1.5",
                                          "--rotate",   "30",    "--window",    "hanning:3"};
  std::uint32_t seed = 1;
  for (const Case& test : cases) {
    SCOPED_TRACE(test.name);
    const std::vector<float> pixels = noise_texels(test.width, test.height, ++seed);
    const std::filesystem::path file = dir / (std::string(test.name) + ".exr");
    ASSERT_TRUE(shpack_io_test::write_image(file, test.width, test.height, 3, pixels));
    const shpack_map map = map_of(pixels, test.width, test.height, test.layout);
    expect_result_is_document(convert_ok(map, convert_defaults()).sh,
                              command_document(dir, {file.string(), "--layout", test.name}));
    std::vector<std::string> args = {file.string(), "--layout", test.name};
    args.insert(args.end(), flags.begin(), flags.end());
    expect_result_is_document(convert_ok(map, options).sh, command_document(dir, args));
  }
}

TEST(CApiConvert, CubeFramesAndL1MatchTheCommandLine) {
  const ScratchDir dir;
  const std::vector<float> pixels = noise_texels(64, 48, 7);
  ASSERT_TRUE(shpack_io_test::write_image(dir / "cross.exr", 64, 48, 3, pixels));
  shpack_map map = map_of(pixels, 64, 48, SHPACK_LAYOUT_AUTO);  // 4:3 is detected as hcross
  shpack_convert_options options = convert_defaults();
  options.l1 = 1;
  const std::string file = (dir / "cross.exr").string();
  const struct {
    int32_t frame;
    const char* name;
  } frames[] = {{SHPACK_CUBE_FRAME_UNITY, "unity"}, {SHPACK_CUBE_FRAME_GL, "gl"}, {SHPACK_CUBE_FRAME_THREEJS, "threejs"}};
  for (const auto& frame : frames) {
    SCOPED_TRACE(frame.name);
    map.cube_frame = frame.frame;
    expect_result_is_document(convert_ok(map, options).sh,
                              command_document(dir, {file, "--cube-frame", frame.name, "--l1"}));
  }
  const std::vector<float> square = noise_texels(32, 32, 8);
  const shpack_map ambiguous = map_of(square, 32, 32, SHPACK_LAYOUT_AUTO);
  shpack_conversion out{};
  out.struct_size = sizeof out;
  shpack_error error;
  EXPECT_EQ(shpack_convert(&ambiguous, &options, &out, &error), SHPACK_INVALID_ARGUMENT);
  EXPECT_NE(std::string(error.message).find("cannot be detected"), std::string::npos) << error.message;
}

TEST(CApiConvert, SixFacesInUnityOrderMatchTheCommandLine) {
  const ScratchDir dir;
  constexpr std::uint32_t n = 16;
  const char* names[6] = {"px", "nx", "py", "ny", "pz", "nz"};  // Unity's CubemapFace order
  std::vector<std::vector<float>> faces;
  shpack_map map{};
  map.struct_size = sizeof map;
  map.layout = SHPACK_LAYOUT_FACES;
  map.cube_frame = SHPACK_CUBE_FRAME_GL;
  for (int f = 0; f < 6; ++f) {
    faces.push_back(noise_texels(n, n, 20 + f));
    ASSERT_TRUE(shpack_io_test::write_image(dir / ("face_" + std::string(names[f]) + ".exr"), n, n, 3, faces[f]));
    map.faces[f] = {faces[f].data(), SHPACK_PIXEL_F32, n, n, 3, 0, 0};
  }
  shpack_convert_options options = convert_defaults();
  options.rotate_deg = 45;
  options.window = "sloan";
  const Json doc = command_document(
      dir, {"--faces", (dir / "face_{face}.exr").string(), "--cube-frame", "gl", "--rotate", "45", "--window", "sloan"});
  const shpack_conversion top_down = convert_ok(map, options);
  expect_result_is_document(top_down.sh, doc);

  // The same +Y face stored bottom-up (as Texture2D.GetPixels returns rows) is a view with a
  // negative row stride onto its last row: the same texels, the same result.
  std::vector<float> bottom_up(faces[2].size());
  for (std::uint32_t y = 0; y < n; ++y)
    std::copy_n(faces[2].begin() + std::ptrdiff_t{3 * n} * y, 3 * n, bottom_up.begin() + std::ptrdiff_t{3 * n} * (n - 1 - y));
  map.faces[2] = {bottom_up.data() + 3 * n * (n - 1), SHPACK_PIXEL_F32, n, n, 3, 0, -static_cast<int64_t>(12 * n)};
  expect_same_result(convert_ok(map, options).sh, top_down.sh);
}

TEST(CApiConvert, SamplingMethodsMatchTheCommandLine) {
  const ScratchDir dir;
  shpack::io::ImageFile file;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("courtyard.exr"), file).ok());
  const shpack_map map = equirect_map(file);
  for (const char* method : {"center", "mip:3", "qmc:4096:7", "fib:2000", "cube-exact:16", "lsq:64"}) {
    SCOPED_TRACE(method);
    shpack_convert_options options = convert_defaults();
    options.method = method;
    options.threads = 2;
    expect_result_is_document(convert_ok(map, options).sh,
                              command_document(dir, {hdri("courtyard.exr").string(), "--method", method}));
  }
}

TEST(CApiConvert, TheExtractedSunMatchesTheCommandLine) {
  const ScratchDir dir;
  shpack::io::ImageFile file;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("sunset.exr"), file).ok());
  shpack_map map = equirect_map(file);
  shpack_convert_options options = convert_defaults();
  options.extract_sun = 1;
  options.rotate_deg = 20;
  options.exposure_ev = -1;
  const Json doc = command_document(
      dir, {hdri("sunset.exr").string(), "--extract-sun", "--rotate", "20", "--exposure", "-1"});
  const shpack_conversion out = convert_ok(map, options);
  ASSERT_EQ(out.has_sun, 1);
  ASSERT_TRUE(doc["sun"].is_object());
  expect_result_is_document(out.sh, doc);
  expect_light_is_document(out.sun, doc["sun"]);

  // The caller's pixels are not written: the sun is taken out of a copy.
  shpack::io::ImageFile again;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("sunset.exr"), again).ok());
  EXPECT_EQ(file.pixels, again.pixels);

  // Bottom-up rows (a negative row stride) are copied in image order: the same sun.
  const std::size_t row = std::size_t{file.width} * file.channels;
  std::vector<float> flipped(file.pixels.size());
  for (std::uint32_t y = 0; y < file.height; ++y)
    std::copy_n(file.pixels.begin() + row * y, row, flipped.begin() + row * (file.height - 1 - y));
  map.image = {flipped.data() + row * (file.height - 1), SHPACK_PIXEL_F32, file.width, file.height, file.channels, 0,
               -static_cast<int64_t>(row * sizeof(float))};
  const shpack_conversion flipped_out = convert_ok(map, options);
  expect_same_result(flipped_out.sh, out.sh);
  expect_light_is_document(flipped_out.sun, doc["sun"]);

  // A map without a sun: has_sun 0, as the document's null.
  ASSERT_TRUE(shpack::io::read_image_file(hdri("studio.exr"), file).ok());
  map.image = image_of(file);
  EXPECT_EQ(convert_ok(map, options).has_sun, 0);
}

// The view error of a result is the document's diagnostics, bit for bit.
void expect_view_error_is_document(const shpack_view_error& e, const Json& doc) {
  const Json& d = doc["diagnostics"];
  EXPECT_EQ(e.max_pct, d["unity_view_error_max_pct"].get<double>());
  EXPECT_EQ(e.rms_pct, d["unity_view_error_rms_pct"].get<double>());
  EXPECT_EQ(e.bound_pct, d["unity_view_error_bound_pct"].get<double>());
  EXPECT_EQ(e.directions, d["unity_view_error_directions"].get<std::uint32_t>());
}

TEST(CApiConvert, ExtractedLightsAndTheViewErrorMatchTheCommandLine) {
  const ScratchDir dir;
  shpack::io::ImageFile file;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("studio.exr"), file).ok());
  const shpack_map map = equirect_map(file);
  shpack_convert_options options = convert_defaults();
  options.extract_lights = 3;
  options.rotate_deg = 40;
  const Json doc = command_document(dir, {hdri("studio.exr").string(), "--extract-lights", "3", "--rotate", "40"});
  const shpack_conversion out = convert_ok(map, options);
  expect_result_is_document(out.sh, doc);
  expect_view_error_is_document(out.view_error, doc);
  ASSERT_TRUE(doc["lights"].is_array());
  ASSERT_EQ(out.light_count, doc["lights"].size());
  EXPECT_EQ(out.light_candidates, doc["light_candidates"].get<std::uint32_t>());
  EXPECT_GE(out.light_count, 1u);  // the studio's softbox is the brightest candidate
  for (std::uint32_t k = 0; k < out.light_count; ++k) {
    SCOPED_TRACE(k);
    const Json& light = doc["lights"][k];
    expect_light_is_document(out.lights[k].light, light);
    EXPECT_EQ(out.lights[k].error_before_pct, light["unity_view_error_before_pct"].get<double>());
    EXPECT_EQ(out.lights[k].error_after_pct, light["unity_view_error_after_pct"].get<double>());
    EXPECT_LT(out.lights[k].error_after_pct, out.lights[k].error_before_pct);
  }
  // The optimal window on a map that rings (sunrise): what it changed, as the document says.
  shpack::io::ImageFile sunrise;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("sunrise.exr"), sunrise).ok());
  shpack_convert_options optimal = convert_defaults();
  optimal.window = "optimal";
  const shpack_conversion fitted = convert_ok(equirect_map(sunrise), optimal);
  const Json fitted_doc = command_document(dir, {hdri("sunrise.exr").string(), "--window", "optimal"});
  expect_same_doubles(fitted.window_rms_change, fitted_doc["diagnostics"]["window_rms_change"], 3, "window_rms_change");
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(fitted.window_planes[c], fitted_doc["diagnostics"]["window_planes"][c].get<int>());
  EXPECT_GT(fitted.window_planes[0] + fitted.window_planes[1] + fitted.window_planes[2], 0);
  EXPECT_EQ(fitted.window_impossible, 0);
  // Without lights, the plain document's view error.
  const Json plain = command_document(dir, {hdri("studio.exr").string()});
  expect_view_error_is_document(convert_ok(map, convert_defaults()).view_error, plain);
}

TEST(CApiConvert, AnOlderCallersStructsAreReadAndWrittenToTheirOwnSize) {
  // A caller built against the first release: its options end before extract_lights (read
  // as 0, whatever lies beyond), its conversion before view_error (nothing written there).
  shpack::io::ImageFile file;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("sunset.exr"), file).ok());
  const shpack_map map = equirect_map(file);
  shpack_convert_options options = convert_defaults();
  options.struct_size = offsetof(shpack_convert_options, extract_lights);
  options.extract_lights = 99;  // beyond its struct: not read
  options.extract_sun = 1;
  shpack_conversion out;
  std::memset(&out, 0xA5, sizeof out);
  out.struct_size = offsetof(shpack_conversion, view_error);
  shpack_error error{};
  ASSERT_EQ(shpack_convert(&map, &options, &out, &error), SHPACK_OK) << error.message;
  EXPECT_EQ(out.struct_size, offsetof(shpack_conversion, view_error));
  EXPECT_EQ(out.has_sun, 1);
  const auto* tail = reinterpret_cast<const unsigned char*>(&out) + offsetof(shpack_conversion, view_error);
  EXPECT_TRUE(std::all_of(tail, reinterpret_cast<const unsigned char*>(&out + 1),
                          [](unsigned char b) { return b == 0xA5; }));
  options = convert_defaults();
  options.extract_sun = 1;
  const shpack_conversion current = convert_ok(map, options);
  expect_same_result(out.sh, current.sh);
  EXPECT_EQ(std::memcmp(&out.sun, &current.sun, sizeof(shpack_light)), 0);
}

TEST(CApiConvert, HalfFloatTexelsAreCopiedExactlyForTheSun) {
  // extract_sun works on an F32 copy of the caller's view: F16 texels become the floats they
  // are exactly, so an F16 map and the F32 map of the same values give the same bits.
  shpack::io::ImageFile file;
  ASSERT_TRUE(shpack::io::read_image_file(hdri("sunset.exr"), file).ok());
  std::vector<std::uint16_t> halves(file.pixels.size());
  std::vector<float> floats(file.pixels.size());
  for (std::size_t k = 0; k < halves.size(); ++k) {
    const half h(file.pixels[k] / 64.0f);  // / 64: exact, and the sun stays below half's largest value
    halves[k] = h.bits();
    floats[k] = static_cast<float>(h);
  }
  shpack_map map = map_of(floats, file.width, file.height, SHPACK_LAYOUT_EQUIRECT);
  shpack_convert_options options = convert_defaults();
  options.extract_sun = 1;
  const shpack_conversion from_floats = convert_ok(map, options);
  map.image = {halves.data(), SHPACK_PIXEL_F16, file.width, file.height, 3, 0, 0};
  const shpack_conversion from_halves = convert_ok(map, options);
  ASSERT_EQ(from_floats.has_sun, 1);
  ASSERT_EQ(from_halves.has_sun, 1);
  expect_same_result(from_halves.sh, from_floats.sh);
  EXPECT_EQ(std::memcmp(&from_halves.sun, &from_floats.sun, sizeof(shpack_light)), 0);
}

TEST(CApiConvert, NonFiniteTexelsAreLocatedInTheCallersImage) {
  // A NaN in the vertical cross's -Z cell (1, 3), which is stored rotated by 180 degrees: the
  // error names the image's texel, not the face's.
  constexpr std::uint32_t n = 8;
  std::vector<float> pixels = noise_texels(3 * n, 4 * n, 3);
  const std::uint32_t x = n + 2, y = 3 * n + 5;
  pixels[(std::size_t{y} * 3 * n + x) * 3 + 1] = std::numeric_limits<float>::quiet_NaN();
  shpack_map map = map_of(pixels, 3 * n, 4 * n, SHPACK_LAYOUT_VCROSS);
  shpack_convert_options options = convert_defaults();
  shpack_conversion out{};
  out.struct_size = sizeof out;
  shpack_error error;
  EXPECT_EQ(shpack_convert(&map, &options, &out, &error), SHPACK_NONFINITE_TEXEL);
  EXPECT_EQ(error.x, x);
  EXPECT_EQ(error.y, y);
  options.nonfinite = SHPACK_NONFINITE_ZERO;
  EXPECT_EQ(convert_ok(map, options).sh.nonfinite_texels, 1u);

  // Six faces: the face and its texel.
  std::vector<std::vector<float>> faces(6, noise_texels(n, n, 4));
  faces[4][(std::size_t{6} * n + 1) * 3] = std::numeric_limits<float>::infinity();
  map.layout = SHPACK_LAYOUT_FACES;
  for (int f = 0; f < 6; ++f) map.faces[f] = {faces[f].data(), SHPACK_PIXEL_F32, n, n, 3, 0, 0};
  options.nonfinite = SHPACK_NONFINITE_ERROR;
  EXPECT_EQ(shpack_convert(&map, &options, &out, &error), SHPACK_NONFINITE_TEXEL);
  EXPECT_EQ(error.face, 4u);
  EXPECT_EQ(error.x, 1u);
  EXPECT_EQ(error.y, 6u);
}

TEST(CApiConvert, BadArgumentsAreRefusedAndLeaveTheResult) {
  const std::vector<float> pixels = noise_texels(16, 8, 5);
  shpack_map map = map_of(pixels, 16, 8, SHPACK_LAYOUT_EQUIRECT);
  shpack_conversion out{};
  out.struct_size = sizeof out;
  out.sh.unity_sh[0] = 42.0f;  // a failed call leaves it
  shpack_error error;
  const auto refused = [&](const shpack_map& m, const shpack_convert_options& o) {
    return shpack_convert(&m, &o, &out, &error) == SHPACK_INVALID_ARGUMENT && out.sh.unity_sh[0] == 42.0f;
  };
  shpack_convert_options options = convert_defaults();
  options.struct_size -= 4;  // a caller compiled against no version
  EXPECT_TRUE(refused(map, options));
  EXPECT_NE(std::string(error.message).find("struct_size"), std::string::npos);
  options = convert_defaults();
  options.method = "gauss:4";
  EXPECT_TRUE(refused(map, options));
  options.method = "exact";
  options.exposure_ev = 2000;  // 2^2000 is not a double
  EXPECT_TRUE(refused(map, options));
  EXPECT_STREQ(error.message, "intensity times 2^exposure_ev is not a finite number");
  options.exposure_ev = 0;
  options.extract_sun = 2;
  EXPECT_TRUE(refused(map, options));
  options.extract_sun = 0;
  options.extract_lights = SHPACK_MAX_EXTRACTED_LIGHTS + 1;
  EXPECT_TRUE(refused(map, options));
  options.extract_lights = 1;
  options.extract_sun = 1;  // the sun is the first of the lights: one or the other
  EXPECT_TRUE(refused(map, options));
  options.extract_lights = 0;
  options.extract_sun = 0;
  map.layout = 42;
  EXPECT_TRUE(refused(map, options));
  map.layout = SHPACK_LAYOUT_EQUIRECT;
  map.cube_frame = 3;
  EXPECT_TRUE(refused(map, options));
  // What `convert` refuses on a cube: a sampling method, the sun.
  const std::vector<float> cross = noise_texels(64, 48, 6);
  const shpack_map cube = map_of(cross, 64, 48, SHPACK_LAYOUT_HCROSS);
  options.method = "mc:100";
  EXPECT_TRUE(refused(cube, options));
  options.method = nullptr;
  options.extract_sun = 1;
  EXPECT_TRUE(refused(cube, options));
  EXPECT_EQ(shpack_convert(nullptr, &options, &out, &error), SHPACK_INVALID_ARGUMENT);
  EXPECT_STREQ(shpack_status_name(SHPACK_OUT_OF_RANGE), "out_of_range");
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
  EXPECT_EQ(functions, 13);  // the functions of shpack_c.h
#else
  GTEST_SKIP() << "nm -D is the check on Linux";
#endif
}

}  // namespace
