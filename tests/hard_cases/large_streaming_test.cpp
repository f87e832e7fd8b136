// large_streaming_test.cpp - a 16384 x 8192 float map (1.5 GiB of RGB floats) is converted by
// streaming scanlines in bounded memory: the peak RSS of the `shpack convert` process stays
// under 256 MiB, and its result is the exact projection of the map.
//
// Not sanitised and not part of the default run: ctest label `large` (scripts/test.sh runs
// it from a Release build with ctest -L large; ASan's shadow memory would make the RSS
// meaningless, so the test skips itself under ASan). "No slower than reading the whole
// image" is a timing ratio and belongs to bench/ (bench/convert_vs_decode.sh); this test
// only prints the convert time.
//
// The map is generated here, never committed: rows of constant radiance (so that ZIP
// compresses it to a few MB and it is written in seconds) plus three suns (equator, top
// and bottom pole rows, on the seam), written in bands of 256 scanlines with OpenImageIO.
// Expected result, in long double (hard_case_support.h): a row of constant v over the full
// circle has the integrals of a 1 x H image's texel (the oracle of width 1), and each sun
// adds (sun - v) times its texel's integral (the oracle of width W).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hard_cases/hard_case_support.h"
#include "shpack/sh_basis.h"
#include "support/test_util.h"

#if defined(__SANITIZE_ADDRESS__)
#define SHPACK_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SHPACK_UNDER_ASAN 1
#endif
#endif

namespace shpack_hard {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kWidth = 16384, kHeight = 8192;
constexpr long kRssLimitKiB = 256 * 1024;  // the target: peak RSS under 256 MB (MiB here: stricter)

float row_value(std::uint32_t j) { return 0.05f + 0.9f * static_cast<float>(j) / (kHeight - 1); }

struct Sun {
  std::uint32_t i, j;
  float value;
};
const Sun kSuns[] = {{kWidth / 4, kHeight / 2, 1e6f}, {0, 0, 5e4f}, {kWidth - 1, kHeight - 1, 2e5f}};

// Writes the map in bands; returns an error message, empty on success.
std::string write_map(const fs::path& path) {
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) return "cannot create " + path.string();
  OIIO::ImageSpec spec(kWidth, kHeight, 3, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  if (!out->open(path.string(), spec)) return out->geterror();
  constexpr std::uint32_t kBand = 256;
  std::vector<float> band(std::size_t{3} * kWidth * kBand);
  for (std::uint32_t y0 = 0; y0 < kHeight; y0 += kBand) {
    for (std::uint32_t y = y0; y < y0 + kBand; ++y) {
      float* row = band.data() + std::size_t{3} * kWidth * (y - y0);
      std::fill(row, row + std::size_t{3} * kWidth, row_value(y));
      for (const Sun& s : kSuns)
        if (s.j == y) std::fill(row + std::size_t{3} * s.i, row + std::size_t{3} * s.i + 3, s.value);
    }
    if (!out->write_scanlines(static_cast<int>(y0), static_cast<int>(y0 + kBand), 0, OIIO::TypeDesc::FLOAT, band.data()))
      return out->geterror();
  }
  if (!out->close()) return out->geterror();
  return {};
}

TEST(Large, StreamingConvertPeakRss) {
#ifdef SHPACK_UNDER_ASAN
  GTEST_SKIP() << "peak RSS means nothing under AddressSanitizer; run from a Release build (ctest -L large)";
#endif
  const ScratchDir dir("large");
  const fs::path map = dir / "large.exr";
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(write_map(map), "");
  const double write_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const ChildRun run = run_child(shpack_cli(), {"convert", map.string(), "-o", (dir / "large.json").string()}, dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // For scale: the command doing nothing. Debian's OpenImageIO pulls in ~260 shared
  // libraries, whose touched pages alone make ~130 MiB of RSS; the limit covers both.
  const ChildRun idle = run_child(shpack_cli(), {"--help"}, dir.path());
  std::cout << "[ measure  ] 16384x8192 float EXR (" << fs::file_size(map) / 1e6 << " MB ZIP, written in "
            << write_seconds << " s): shpack convert peak RSS " << run.max_rss_kib / 1024.0 << " MiB (limit "
            << kRssLimitKiB / 1024 << "; `shpack --help` alone: " << idle.max_rss_kib / 1024.0 << " MiB), "
            << run.seconds << " s\n";
  EXPECT_LT(run.max_rss_kib, kRssLimitKiB) << "the whole image would be 1536 MiB";

  // The result is the projection of the map (radiance_sh is printed exactly). Bound:
  // equirect_sum_tol (checks.h) for W = 16384: ((2048 + 26) 4 + 1) u k_i sum |v| Omega.
  const nlohmann::json doc = nlohmann::json::parse(read_text(dir / "large.json"));
  const EquirectOracle rows(1, kHeight), texels(kWidth, kHeight);
  ShLd want{};
  long double abs_integral = 0;
  for (std::uint32_t j = 0; j < kHeight; ++j) {
    const std::array<long double, 10> t = rows.texel(0, j);
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 9; ++i) want[c][i] += row_value(j) * t[i];
    abs_integral += row_value(j) * t[9];
  }
  for (const Sun& s : kSuns) {
    const std::array<long double, 10> t = texels.texel(s.i, s.j);
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 9; ++i) want[c][i] += (static_cast<long double>(s.value) - row_value(s.j)) * t[i];
    abs_integral += s.value * t[9];
  }
  double worst = 0;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) {
      const double tol = ((2048 + 26) * 4 + 1) * shpack_test::kU * shpack::kBasisScale[i] * static_cast<double>(abs_integral) +
                         2 * shpack_test::kU * static_cast<double>(std::fabs(want[c][i]));
      const double got = doc.at("radiance_sh").at(c).at(i).get<double>();
      const double err = static_cast<double>(std::fabs(got - want[c][i]));
      EXPECT_LE(err, tol) << "c=" << c << " i=" << i;
      worst = std::max(worst, err / tol);
    }
  std::cout << "[ measure  ] 16384x8192 result vs long-double oracle: max err/tol = " << worst << "\n";
}

}  // namespace
}  // namespace shpack_hard
