// lib/io reads Radiance pictures with its own reader (lib/io/src/hdr_decoder.h), where
// OpenImageIO read them before. The oracles:
//  - OpenImageIO's decode of the same file, for the bundled maps written as .hdr by
//    OpenImageIO's writer (as oiiotool writes them: new-style RLE at 1024 wide). RGBE to
//    float is exact in both readers (rgbe_scanline.h), so the tolerance is zero: the floats
//    are compared bit for bit.
//  - For hand-made files, the RGBE bytes themselves: this file's own small encoders write
//    them flat, new-style RLE and old-style RLE, and each texel must come back as
//    m * 2^(E - 136), computed here in double (exact: m < 2^8) and then rounded to float
//    (exact too: see rgbe_scanline.h), so again compared for equality.
//  - For the eight orderings of the resolution string, images written out by hand from
//    Radiance's definition (resolu.h: y up, the first axis the slow one).
// Hostile files (truncated at every byte, runs past a scanline's end, sizes beyond the file
// or the budget, headers without their blank line) must fail in one line naming the file.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.h"
#include "hdr_decoder.h"
#include "image_open.h"
#include "io_test_files.h"
#include "shpack/io/image_file.h"

namespace {

namespace fs = std::filesystem;
using shpack::io::ImageFile;
using shpack::io::IoErrc;
using shpack::io::IoStatus;
using shpack_io_test::ScratchDir;
using shpack_io_test::write_string;

using Rgbe = std::array<std::uint8_t, 4>;
using Scanline = std::vector<Rgbe>;

constexpr const char* kHeader = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";

void append(std::string& out, const Rgbe& p) { out.append(reinterpret_cast<const char*>(p.data()), 4); }

// ---- the encoders (Radiance's color.c, written from its description in rgbe_scanline.h)

std::string flat(const Scanline& s) {
  std::string out;
  for (const Rgbe& p : s) append(out, p);
  return out;
}

// New-style: the mark, then each component as runs of 3 or more equal bytes (at most 127)
// and literals (at most 128).
std::string new_rle(const Scanline& s) {
  const std::size_t n = s.size();
  std::string out = {2, 2, static_cast<char>(n >> 8), static_cast<char>(n & 255)};
  for (std::size_t c = 0; c < 4; ++c) {
    const auto run_at = [&](std::size_t p) {
      std::size_t run = 1;
      while (p + run < n && run < 127 && s[p + run][c] == s[p][c]) ++run;
      return run;
    };
    for (std::size_t p = 0; p < n;) {
      if (const std::size_t run = run_at(p); run >= 3) {
        out += static_cast<char>(128 + run);
        out += static_cast<char>(s[p][c]);
        p += run;
        continue;
      }
      std::size_t q = p + 1;
      while (q < n && q - p < 128 && run_at(q) < 3) ++q;
      out += static_cast<char>(q - p);
      for (; p < q; ++p) out += static_cast<char>(s[p][c]);
    }
  }
  return out;
}

// Old-style: a pixel equal to the one before starts a run, written as records 1, 1, 1, d
// for the run's base-256 digits d, lowest first.
std::string old_rle(const Scanline& s) {
  std::string out;
  append(out, s[0]);
  for (std::size_t p = 1; p < s.size();) {
    std::size_t run = 0;
    while (p + run < s.size() && s[p + run] == s[p - 1]) ++run;
    if (run == 0) {
      append(out, s[p++]);
      continue;
    }
    for (std::size_t digits = run; digits > 0; digits >>= 8)
      append(out, {1, 1, 1, static_cast<std::uint8_t>(digits & 255)});
    p += run;
  }
  return out;
}

// `rows` scanlines of `width` pixels as a real writer makes them (largest mantissa at least
// 128, so never a run record), with runs of equal pixels and of equal exponents.
std::vector<Scanline> test_scanlines(std::size_t width, std::size_t rows, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255), big(128, 255), exponent(120, 150), coin(0, 3);
  std::vector<Scanline> out(rows, Scanline(width));
  for (Scanline& s : out) {
    for (std::size_t p = 0; p < width; ++p) {
      if (p > 0 && coin(rng) == 0) {
        s[p] = s[p - 1];
        continue;
      }
      const int e = coin(rng) == 0 && p > 0 ? s[p - 1][3] : exponent(rng);
      s[p] = {static_cast<std::uint8_t>(big(rng)), static_cast<std::uint8_t>(byte(rng)),
              static_cast<std::uint8_t>(byte(rng)), static_cast<std::uint8_t>(e)};
    }
  }
  return out;
}

float rgbe_value(std::uint8_t m, std::uint8_t e) {
  return e == 0 ? 0.0f : static_cast<float>(std::ldexp(static_cast<double>(m), e - 136));
}

// The image the scanlines of a "-Y H +X W" file are: R, G, B a texel, top row first.
std::vector<float> expected_pixels(const std::vector<Scanline>& rows) {
  std::vector<float> out;
  for (const Scanline& s : rows)
    for (const Rgbe& p : s)
      for (int c = 0; c < 3; ++c) out.push_back(rgbe_value(p[c], p[3]));
  return out;
}

std::string resolution(std::size_t width, std::size_t height) {
  return "-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
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

// A failure in one line that starts with the file's name.
void expect_one_line_failure(const IoStatus& st, const fs::path& path, const std::string& what) {
  EXPECT_FALSE(st.ok()) << what;
  EXPECT_EQ(st.message.rfind(path.string() + ": ", 0), 0u) << what << ": " << st.message;
  EXPECT_EQ(st.message.find('\n'), std::string::npos) << what << ": " << st.message;
}

// The reason reading `bytes` as a .hdr fails.
std::string failure(const ScratchDir& dir, const std::string& bytes) {
  return shpack_io_test::read_failure(dir / "bad.hdr", bytes);
}

// ---- values

TEST(HdrReader, BundledMapsAreReadAsOpenImageIOReadsThem) {
  const ScratchDir dir;
  int maps = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(shpack_io_test::hdri(""))) {
    if (e.path().extension() != ".exr") continue;
    // The map as OpenImageIO's .hdr writer stores it (oiiotool's writer), then read back by both.
    const shpack_io_test::RgbImage exr = shpack_io_test::read_rgb(e.path());
    ASSERT_FALSE(exr.rgb.empty());
    const std::vector<float>& rgb = exr.rgb;
    const fs::path hdr = dir / (e.path().stem().string() + ".hdr");
    ASSERT_TRUE(shpack_io_test::write_image(hdr, exr.width, exr.height, 3, rgb));

    const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(hdr.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    std::vector<float> want(rgb.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, want.data())) << in->geterror();
    const ImageFile image = read_ok(hdr);
    EXPECT_EQ(image.format, "hdr");
    EXPECT_EQ(image.width, static_cast<std::uint32_t>(exr.width));
    EXPECT_EQ(image.channels, 3u);
    EXPECT_FALSE(image.srgb_decoded);
    expect_same_floats(image.pixels, want, hdr.string());
    ++maps;
  }
  EXPECT_GT(maps, 0);
}

TEST(HdrReader, RgbeIsMantissaTimesTwoToTheExponentMinus136) {
  // OpenImageIO's rule, pinned: m * 2^(E - 136), E = 0 black whatever the mantissas. Not
  // Radiance's colr_color, (m + 0.5) * 2^(E - 136): 128 at E = 129 would be 1.00390625.
  const ScratchDir dir;
  const Scanline pixels = {{128, 64, 1, 129}, {255, 0, 7, 255}, {1, 2, 3, 1}, {200, 200, 200, 0}};
  write_string(dir / "p.hdr", kHeader + resolution(4, 1) + flat(pixels));
  const ImageFile image = read_ok(dir / "p.hdr");
  const std::vector<float> want = {1.0f,
                                   0.5f,
                                   0.0078125f,  // 2^-7
                                   255.0f * 0x1p119f,
                                   0.0f,
                                   7.0f * 0x1p119f,
                                   0x1p-135f,  // subnormal in float, and exact
                                   0x1p-134f,
                                   3.0f * 0x1p-135f,
                                   0.0f,
                                   0.0f,
                                   0.0f};
  ASSERT_EQ(image.pixels.size(), want.size());
  expect_same_floats(image.pixels, want, "hand-made RGBE");
  EXPECT_NE(image.pixels[0], 1.00390625f);
}

TEST(HdrReader, EveryScanlineEncodingGivesTheSamePixels) {
  const ScratchDir dir;
  // Below 8 and above 0x7fff pixels only records exist; between, all three forms. 128 and
  // 129 put a literal of exactly 128 and one past it, runs of 127 come with the repeats.
  for (const std::size_t width : {1, 7, 8, 127, 128, 129, 300, 32767, 32768}) {
    const std::vector<Scanline> rows = test_scanlines(width, 3, 0x5eed + width);
    const bool rle = width >= 8 && width <= 0x7fff;
    std::vector<std::pair<const char*, std::string (*)(const Scanline&)>> forms = {{"flat", flat}, {"old", old_rle}};
    if (rle) forms.push_back({"new", new_rle});
    for (const auto& [name, encode] : forms) {
      std::string body;
      for (const Scanline& s : rows) body += encode(s);
      const fs::path path = dir / (std::string(name) + std::to_string(width) + ".hdr");
      write_string(path, kHeader + resolution(width, rows.size()) + body);
      expect_same_floats(read_ok(path).pixels, expected_pixels(rows), path.string());
    }
    if (rle) {  // each scanline chooses its own form
      const std::string body = new_rle(rows[0]) + flat(rows[1]) + old_rle(rows[2]);
      const fs::path path = dir / ("mixed" + std::to_string(width) + ".hdr");
      write_string(path, kHeader + resolution(width, rows.size()) + body);
      expect_same_floats(read_ok(path).pixels, expected_pixels(rows), path.string());
    }
  }
}

TEST(HdrReader, OldStyleRunsCountInBase256) {
  // Records 1,1,1,d repeat the pixel before d << 8k times, k counting the run records just
  // before: 0 then 2 is 512 repeats (Radiance's oldreadcolrs).
  const ScratchDir dir;
  const Rgbe p = {200, 100, 50, 130};
  std::string body;
  append(body, p);
  append(body, {1, 1, 1, 0});
  append(body, {1, 1, 1, 2});
  append(body, {128, 128, 128, 128});
  write_string(dir / "old.hdr", kHeader + resolution(514, 1) + body);
  const std::vector<float> got = read_ok(dir / "old.hdr").pixels;
  ASSERT_EQ(got.size(), 514u * 3);
  for (std::size_t t = 0; t < 513; ++t) EXPECT_EQ(got[3 * t], rgbe_value(200, 130)) << t;
  EXPECT_EQ(got[3 * 513], rgbe_value(128, 128));
}

TEST(HdrReader, HeaderLinesOtherThanFormatChangeNoValue) {
  // EXPOSURE, COLORCORR, PRIMARIES, GAMMA are read past (hdr_decoder.h), as OpenImageIO did;
  // "#?RGBE", no FORMAT line, CRLF line ends and blanks around the sizes are all read.
  const ScratchDir dir;
  const std::vector<Scanline> rows = test_scanlines(16, 2, 7);
  const std::string body = new_rle(rows[0]) + new_rle(rows[1]);
  const std::vector<float> want = expected_pixels(rows);
  const std::vector<std::string> headers = {
      "#?RADIANCE\n# made by hand\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=4\nCOLORCORR=1 2 3\n"
      "PRIMARIES=0.64 0.33 0.29 0.6 0.15 0.06 0.333 0.333\nGAMMA=2.2\n\n-Y 2 +X 16\n",
      "#?RGBE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 16\n",
      "#?RADIANCE\n\n-Y 2 +X 16\n",
      "#?RADIANCE\r\nFORMAT=32-bit_rle_rgbe  \r\n\r\n  -Y   2\t+X 16 \r\n",
  };
  for (std::size_t k = 0; k < headers.size(); ++k) {
    const fs::path path = dir / ("h" + std::to_string(k) + ".hdr");
    write_string(path, headers[k] + body);
    expect_same_floats(read_ok(path).pixels, want, path.string());
  }
}

TEST(HdrReader, AllEightOrderingsGiveTheTopDownLeftToRightImage) {
  // The image  a b c   (a..f below), stored in each ordering as Radiance defines it: the
  //            d e f   first axis is the slow one, "-Y" runs from the top, "-X" from the right.
  const ScratchDir dir;
  const std::array<Rgbe, 6> texel = {Rgbe{128, 0, 0, 128}, Rgbe{129, 0, 0, 128}, Rgbe{130, 0, 0, 128},
                                     Rgbe{131, 0, 0, 128}, Rgbe{132, 0, 0, 128}, Rgbe{133, 0, 0, 128}};
  enum { a, b, c, d, e, f };
  const std::vector<std::pair<const char*, std::array<int, 6>>> orderings = {
      {"-Y 2 +X 3", {a, b, c, d, e, f}}, {"-Y 2 -X 3", {c, b, a, f, e, d}}, {"+Y 2 +X 3", {d, e, f, a, b, c}},
      {"+Y 2 -X 3", {f, e, d, c, b, a}}, {"+X 3 -Y 2", {a, d, b, e, c, f}}, {"+X 3 +Y 2", {d, a, e, b, f, c}},
      {"-X 3 -Y 2", {c, f, b, e, a, d}}, {"-X 3 +Y 2", {f, c, e, b, d, a}}};
  std::vector<float> want;
  for (const Rgbe& t : texel) want.insert(want.end(), {rgbe_value(t[0], 128), 0.0f, 0.0f});
  for (const auto& [res, stored] : orderings) {
    Scanline s;
    for (const int k : stored) s.push_back(texel[static_cast<std::size_t>(k)]);
    write_string(dir / "o.hdr", std::string(kHeader) + res + "\n" + flat(s));
    const ImageFile image = read_ok(dir / "o.hdr");
    EXPECT_EQ(image.width, 3u) << res;
    EXPECT_EQ(image.height, 2u) << res;
    expect_same_floats(image.pixels, want, res);
  }
}

TEST(HdrReader, ColumnsAreDecodedWithTheirOwnRunLengths) {
  // "+X 10 -Y 12": ten RLE scanlines of 12 pixels, each a column from the top.
  const ScratchDir dir;
  const std::vector<Scanline> columns = test_scanlines(12, 10, 11);
  std::string body;
  for (const Scanline& s : columns) body += new_rle(s);
  write_string(dir / "cols.hdr", kHeader + std::string("+X 10 -Y 12\n") + body);
  std::vector<float> want;
  for (std::size_t y = 0; y < 12; ++y)
    for (std::size_t x = 0; x < 10; ++x)
      for (int c = 0; c < 3; ++c) want.push_back(rgbe_value(columns[x][y][c], columns[x][y][3]));
  expect_same_floats(read_ok(dir / "cols.hdr").pixels, want, "columns");
}

TEST(HdrReader, BandsInAnyOrderAreTheRowsOfTheWholeImage) {
  // The projector asks for increasing bands; any other order (backwards, repeated) must give
  // the same rows, for files stored top-down, bottom-up and by columns, any channel choice.
  const ScratchDir dir;
  const std::size_t w = 20, h = 13;
  const std::vector<Scanline> scans = test_scanlines(w, h, 21);
  const std::vector<Scanline> columns = test_scanlines(h, w, 22);
  std::string rows_body, columns_body;
  for (const Scanline& s : scans) rows_body += new_rle(s);
  for (const Scanline& s : columns) columns_body += old_rle(s);
  const std::vector<std::pair<std::string, std::string>> files = {
      {"-Y 13 +X 20\n", rows_body}, {"+Y 13 -X 20\n", rows_body}, {"-X 20 +Y 13\n", columns_body}};
  const std::vector<std::vector<int>> choices = {{0, 1, 2}, {2}, {2, 0}};
  for (const auto& [res, body] : files) {
    write_string(dir / "b.hdr", kHeader + res + body);
    for (const std::vector<int>& channels : choices) {
      using shpack::io::detail::ImageDecoder;
      const auto open = [&] {
        std::unique_ptr<ImageDecoder> decoder;
        const IoStatus st = shpack::io::detail::open_image(dir / "b.hdr", {shpack::io::kDefaultMaxTexels, 1}, decoder);
        EXPECT_TRUE(st.ok()) << st.message;
        return decoder;
      };
      const std::unique_ptr<ImageDecoder> whole = open(), bands = open();
      ASSERT_TRUE(whole && bands);
      const std::size_t k = channels.size();
      std::vector<float> all(w * h * k);
      std::string error;
      ASSERT_TRUE(whole->read_rows(0, 0, h, channels, all.data(), error)) << error;
      for (const long long first : {10LL, 6LL, 0LL, 3LL, 12LL, 0LL}) {  // bands of 1 to 4 rows
        const long long end = std::min<long long>(h, first + 4);
        std::vector<float> band(w * static_cast<std::size_t>(end - first) * k);
        ASSERT_TRUE(bands->read_rows(0, first, end, channels, band.data(), error)) << error;
        const std::vector<float> want(all.begin() + static_cast<long long>(w * k) * first,
                                      all.begin() + static_cast<long long>(w * k) * end);
        expect_same_floats(band, want, res + " rows " + std::to_string(first));
      }
    }
  }
}

// ---- hostile files

TEST(HdrReader, TruncatedAtEveryByteFailsInOneLine) {
  const ScratchDir dir;
  const std::vector<Scanline> rows = test_scanlines(9, 3, 5);
  const std::string file = kHeader + resolution(9, 3) + new_rle(rows[0]) + flat(rows[1]) + old_rle(rows[2]);
  for (std::size_t size = 0; size < file.size(); ++size) {
    const fs::path path = dir / "cut.hdr";
    write_string(path, file.substr(0, size));
    ImageFile image;
    expect_one_line_failure(shpack::io::read_image_file(path, image), path, "cut at " + std::to_string(size));
  }
  write_string(dir / "whole.hdr", file);
  expect_same_floats(read_ok(dir / "whole.hdr").pixels, expected_pixels(rows), "the whole file");
}

TEST(HdrReader, ATruncatedMapFailsConvertInOneLineStreamedOrWhole) {
  // 64 x 32, cut inside scanline 20: the streamed projector and the sun's extraction (which
  // reads the image whole) both stop there, print one line and write nothing.
  const ScratchDir dir;
  const std::vector<Scanline> rows = test_scanlines(64, 32, 9);
  std::string file = kHeader + resolution(64, 32);
  for (std::size_t y = 0; y < 20; ++y) file += new_rle(rows[y]);
  file += new_rle(rows[20]).substr(0, 30);
  write_string(dir / "cut.hdr", file);
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{}, std::vector<std::string>{"--extract-sun"}}) {
    std::vector<std::string> args = {"convert", (dir / "cut.hdr").string(), "-o", (dir / "cut.json").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const shpack_io_test::CliRun run = shpack_io_test::run_shpack(dir, args);
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err.rfind("shpack: " + (dir / "cut.hdr").string() + ": cannot read rows ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find("(scanline 20 of 32: the file ends inside it)"), std::string::npos) << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
    EXPECT_FALSE(fs::exists(dir / "cut.json"));
  }
}

TEST(HdrReader, SizesBeyondTheBudgetOrTheFileAreRefusedAtOpen) {
  const ScratchDir dir;
  EXPECT_EQ(failure(dir, kHeader + std::string("-Y 2147483647 +X 2147483647\n")),
            "the image is 2147483647x2147483647 (4611686014132420609 texels), above the budget of 268435456 "
            "(--max-texels)");
  EXPECT_EQ(failure(dir, kHeader + std::string("-Y 2147483648 +X 1\n")),
            "the Radiance resolution string '-Y 2147483648 +X 1' is not of the form '-Y height +X width' (or "
            "another ordering of the axes)");
  // 1000 scanlines need at least 4000 bytes: this file has 8.
  EXPECT_EQ(failure(dir, kHeader + std::string("-Y 1000 +X 10\n") + std::string(8, '\x80')),
            "the Radiance header declares 1000 scanlines, at least 4 bytes each, but the file holds 8 bytes after "
            "its header (it is truncated)");
  EXPECT_EQ(failure(dir, kHeader + std::string("+X 1000 -Y 10\n") + std::string(8, '\x80')),
            "the Radiance header declares 1000 scanlines, at least 4 bytes each, but the file holds 8 bytes after "
            "its header (it is truncated)");
  for (const char* res : {"-Y 0 +X 4", "-Y 4 +Y 4", "-Y -4 +X 4", "Y 4 X 4", "-Y 4 +X 4 +Z 1", "-Y 4", ""}) {
    EXPECT_EQ(failure(dir, kHeader + std::string(res) + "\n" + std::string(64, '\x80'))
                  .rfind("the Radiance resolution string", 0),
              0u)
        << res;
  }
}

TEST(HdrReader, RunsNeverWritePastTheScanline) {
  const ScratchDir dir;
  const std::string head = kHeader + resolution(8, 1);
  const std::string mark = {2, 2, 0, 8};
  // A run of 9 (128 + 9) in a scanline of 8.
  EXPECT_EQ(failure(dir, head + mark + "\x89\x80" + std::string(16, '\0')),
            "cannot read rows 0..0 (scanline 0 of 1: a run of 9 from pixel 0 goes past its 8 pixels)");
  // A literal of 5 after a run of 4.
  EXPECT_EQ(failure(dir, head + mark + "\x84\x80\x05" + std::string(16, '\x80')),
            "cannot read rows 0..0 (scanline 0 of 1: a literal of 5 from pixel 4 goes past its 8 pixels)");
  EXPECT_EQ(failure(dir, head + mark + std::string(1, '\0') + std::string(16, '\x80')),
            "cannot read rows 0..0 (scanline 0 of 1: a literal of 0 bytes at pixel 0)");
  EXPECT_EQ(failure(dir, head + std::string{2, 2, 0, 9} + std::string(32, '\x80')),
            "cannot read rows 0..0 (scanline 0 of 1: its run-length header gives a width of 9, not 8)");
  // Old style: a run of 8 after one pixel; a run with no pixel before it.
  const std::string pixel = "\x80\x80\x80\x80";
  EXPECT_EQ(failure(dir, head + pixel + std::string{1, 1, 1, 8} + std::string(64, '\x80')),
            "cannot read rows 0..0 (scanline 0 of 1: an old-style run of 8 from pixel 1 goes past its 8 pixels)");
  EXPECT_EQ(failure(dir, head + std::string{1, 1, 1, 2} + std::string(64, '\x80')),
            "cannot read rows 0..0 (scanline 0 of 1: an old-style run at its start has no pixel to repeat)");
  EXPECT_EQ(failure(dir, kHeader + resolution(4, 1) + std::string{1, 1, 1, 2} + std::string(64, '\x80')),
            "cannot read rows 0..0 (scanline 0 of 1: an old-style run at its start has no pixel to repeat)");
  // Five run records in a row would count past 2^32.
  std::string five = pixel;
  for (int k = 0; k < 5; ++k) five += std::string{1, 1, 1, 0};
  EXPECT_EQ(failure(dir, kHeader + resolution(4, 1) + five),
            "cannot read rows 0..0 (scanline 0 of 1: more than four old-style run records in a row)");
}

TEST(HdrReader, MalformedHeadersAreNamed) {
  const ScratchDir dir;
  EXPECT_EQ(failure(dir, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n-Y 1 +X 1\n\x80\x80\x80\x80"),
            "the Radiance header has no blank line before its resolution string '-Y 1 +X 1'");
  EXPECT_EQ(failure(dir, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n"),
            "the file ends inside the Radiance header, before its blank line");
  EXPECT_EQ(failure(dir, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1"),
            "the file ends inside the Radiance header, before its resolution string");
  EXPECT_EQ(failure(dir, "#?RADIANCE\n" + std::string(70000, 'x') + "\n\n-Y 1 +X 1\n"),
            "the Radiance header has no blank line in the file's first 65536 bytes");
  const fs::path xyze = dir / "xyz.hdr";
  write_string(xyze, "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\x80\x80\x80\x80");
  ImageFile image;
  const IoStatus st = shpack::io::read_image_file(xyze, image);
  EXPECT_EQ(st.code, IoErrc::Unsupported);
  EXPECT_EQ(st.message, xyze.string() +
                            ": the Radiance header says FORMAT=32-bit_rle_xyze (CIE XYZ pixels), which "
                            "shpack does not read: only 32-bit_rle_rgbe");
  EXPECT_EQ(failure(dir, "#?RADIANCE\nFORMAT=24-bit_rgb\n\n-Y 1 +X 1\n\x80\x80\x80\x80"),
            "the Radiance header's FORMAT '24-bit_rgb' is not 32-bit_rle_rgbe");
}

TEST(HdrReader, OnlyARadianceMagicLineChoosesThisReader) {
  using shpack::io::detail::is_radiance_magic;
  EXPECT_TRUE(is_radiance_magic("#?RADIANCE\n"));
  EXPECT_TRUE(is_radiance_magic("#?RADIANCE\r\n"));
  EXPECT_TRUE(is_radiance_magic("#?RGBE\n"));
  EXPECT_FALSE(is_radiance_magic("#?RADIANCE"));  // nothing after it: no line
  EXPECT_FALSE(is_radiance_magic("#?RADIANCEX\n"));
  EXPECT_FALSE(is_radiance_magic("#?RGB\n"));
  EXPECT_FALSE(is_radiance_magic("#RADIANCE\n"));
  EXPECT_FALSE(is_radiance_magic(""));
  // The reader itself refuses a file without it (image_open.h sends such files elsewhere).
  const ScratchDir dir;
  const fs::path path = dir / "nomagic.hdr";
  write_string(path, "#?RADIANCX\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n\x80\x80\x80\x80");
  shpack::io::detail::FileBytes file;
  ASSERT_EQ(file.open(path), 0);
  std::unique_ptr<shpack::io::detail::ImageDecoder> decoder;
  const IoStatus st = shpack::io::detail::open_hdr(path, std::move(file), {shpack::io::kDefaultMaxTexels, 1}, decoder);
  EXPECT_EQ(st.message, path.string() + ": not a Radiance picture: it does not start with #?RADIANCE or #?RGBE");
  EXPECT_FALSE(decoder);
}

// ---- the process: no OpenImageIO for a float map

// The libraries `shpack convert <map>` loads, as the dynamic linker reports them.
std::string libraries_loaded(const ScratchDir& dir, const std::string& map, int& exit_code) {
  const fs::path trace = dir / "ld";
  fs::create_directories(trace);
  const std::string command = "cd '" + dir.path().string() + "' && LD_DEBUG=libs LD_DEBUG_OUTPUT='" +
                              (trace / "libs").string() + "' '" + SHPACK_CLI_PATH + "' convert " + map +
                              " -o sky.json >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::string loaded;
  for (const fs::directory_entry& e : fs::directory_iterator(trace)) {
    const std::vector<char> bytes = shpack_io_test::read_bytes(e.path());
    loaded.append(bytes.begin(), bytes.end());
    fs::remove(e.path());
  }
  return loaded;
}

TEST(HdrReader, ConvertOfHdrOrPfmNeverLoadsOpenImageIO) {
  const ScratchDir dir;
  const std::vector<Scanline> rows = test_scanlines(16, 8, 3);
  std::string body;
  for (const Scanline& s : rows) body += new_rle(s);
  write_string(dir / "sky.hdr", kHeader + resolution(16, 8) + body);
  write_string(dir / "sky.pfm", "PF\n16 8\n-1.0\n" + std::string(16 * 8 * 12, '\0'));
  for (const char* map : {"sky.hdr", "sky.pfm"}) {
    int exit_code = -1;
    const std::string loaded = libraries_loaded(dir, map, exit_code);
    EXPECT_EQ(exit_code, 0) << map;
    ASSERT_NE(loaded.find("libOpenEXR"), std::string::npos)
        << "the linker's report is empty: " << loaded.substr(0, 200);
    EXPECT_EQ(loaded.find("libOpenImageIO"), std::string::npos) << map;
    EXPECT_EQ(loaded.find("libshpack_oiio"), std::string::npos) << map;
  }
}

}  // namespace
