// Hostile image and JSON inputs (docs/security.md): each gets one line on stderr naming the
// file and the problem, and exit code 1; never a crash, a hang or a runaway allocation.
//
// The CLI tests run the built shpack; SHPACK_CLI_UNDER_TEST=/path/to/shpack runs them on
// another build (an older one, to see them fail), under `ulimit -v` so that the runaway
// allocations they guard against stay bounded.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io_test_files.h"
#include "shpack/io/file_checks.h"
#include "shpack/io/image_file.h"
#include "shpack/io/io_status.h"
#include "shpack/io/json_reader.h"
#include "shpack/io/map_source.h"

namespace {

namespace fs = std::filesystem;
using shpack::io::IoErrc;
using shpack::io::IoStatus;
using shpack_io_test::ScratchDir;

struct CliResult {
  int exit_code = -1;  // 124: killed by the timeout
  std::string out, err;
};

std::string shell_quote(const std::string& text) {
  std::string q = "'";
  for (const char ch : text) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `shpack <args>` in `dir` (names are relative to it), with a 60 s timeout; `before` is
// shell text put in front of the command (e.g. a pipe into it).
CliResult shpack(const ScratchDir& dir, const std::vector<std::string>& args, const std::string& before = {},
           const std::string& as_user = {}) {
  const char* other = std::getenv("SHPACK_CLI_UNDER_TEST");
  std::string command = "cd " + shell_quote(dir.path().string()) + " && ";
  if (other != nullptr && *other != '\0') command += "ulimit -v 3000000; ";
  command += before + as_user + "timeout 60 " + shell_quote(other != nullptr && *other != '\0' ? other : SHPACK_CLI_PATH);
  for (const std::string& a : args) command += " " + shell_quote(a);
  command += " >" + shell_quote((dir / "stdout.txt").string()) + " 2>" + shell_quote((dir / "stderr.txt").string());
  const int status = std::system(("/bin/bash -c " + shell_quote(command)).c_str());
  CliResult run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = slurp(dir / "stdout.txt");
  run.err = slurp(dir / "stderr.txt");
  fs::remove(dir / "stdout.txt");
  fs::remove(dir / "stderr.txt");
  return run;
}

// The run failed with exactly the line "shpack: <message>".
void expect_one_line_error(const CliResult& run, const std::string& message) {
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + message + "\n");
  EXPECT_EQ(run.out, "");
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// An EXR of `channels` (names as given, half), its data window w x h at (x, y), its display
// window full_w x full_h at 0, 0.
void write_exr(const fs::path& path, const std::vector<std::string>& channels, int w, int h, int x = 0, int y = 0,
               int full_w = 0, int full_h = 0) {
  OIIO::ImageSpec spec(w, h, static_cast<int>(channels.size()), OIIO::TypeDesc::HALF);
  spec.channelnames = channels;
  spec.alpha_channel = -1;
  spec.z_channel = -1;
  spec.x = x;
  spec.y = y;
  spec.full_x = spec.full_y = 0;
  spec.full_width = full_w > 0 ? full_w : w;
  spec.full_height = full_h > 0 ? full_h : h;
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), spec)) << OIIO::geterror();
  const std::vector<float> pixels(std::size_t(w) * h * channels.size(), 0.5f);
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

// A PNG of 4x2 RGB texels, its IDAT chunk's CRC wrong: libpng fails while decoding.
std::string png_with_bad_idat_crc() {
  // Made by zlib and struct; the last four bytes of the IDAT chunk are its CRC, flipped.
  static const unsigned char bytes[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
      0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x02, 0x08, 0x02, 0x00, 0x00, 0x00, 0xf0, 0xca, 0xea,
      0x34, 0x00, 0x00, 0x00, 0x10, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x68, 0x70, 0x50, 0x80,
      0x23, 0x06, 0x64, 0x0e, 0x00, 0x5e, 0x1a, 0x07, 0x01, 0xcd, 0x2c, 0x70, 0x34, 0x00, 0x00, 0x00,
      0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
  return {reinterpret_cast<const char*>(bytes), sizeof bytes};
}

// ---- 1. declared sizes are budgeted before anything is allocated or decoded

TEST(HostileInputs, HdrHeaderAboveTheBudgetIsRefusedUnread) {
  ScratchDir dir;
  // 41 bytes that claim 20000 x 20000 texels (4.8 GB of floats) and hold none.
  write_text(dir / "sky.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 20000 +X 20000\n");
  const std::string message =
      "sky.hdr: the image is 20000x20000 (400000000 texels), above the budget of 268435456 (--max-texels)";
  expect_one_line_error(shpack(dir, {"convert", "sky.hdr", "--layout", "angular"}), message);
  expect_one_line_error(shpack(dir, {"convert", "sky.hdr"}), message);
}

TEST(HostileInputs, ExrDisplayWindowAboveTheBudgetIsRefusedUnread) {
  ScratchDir dir;
  // One texel of data; the display window (what shpack would project) is 4e6 x 2e6.
  write_exr(dir / "wide.exr", {"B", "G", "R"}, 1, 1, 0, 0, 4000000, 2000000);
  expect_one_line_error(shpack(dir, {"convert", "wide.exr"}),
                        "wide.exr: the image is 4000000x2000000 (8000000000000 texels), above the budget of "
                        "268435456 (--max-texels)");
}

TEST(HostileInputs, ExrDataWindowAboveTheBudgetIsRefused) {
  ScratchDir dir;
  write_exr(dir / "data.exr", {"B", "G", "R"}, 64, 64, -30, -30, 8, 4);
  expect_one_line_error(shpack(dir, {"convert", "data.exr", "--max-texels", "100"}),
                        "data.exr: the data window is 64x64 (4096 texels), above the budget of 100 (--max-texels)");
  const CliResult ok = shpack(dir, {"convert", "data.exr", "--max-texels", "4096"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

TEST(HostileInputs, MaxTexelsIsTheBudgetOfOneMapAndOfSixFaces) {
  ScratchDir dir;
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "sky.exr", 8, 4, {1.0f, 1.0f, 1.0f}));
  expect_one_line_error(shpack(dir, {"convert", "sky.exr", "--max-texels", "31"}),
                        "sky.exr: the image is 8x4 (32 texels), above the budget of 31 (--max-texels)");
  const CliResult ok = shpack(dir, {"convert", "sky.exr", "--max-texels", "32"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "f.exr", 4, 4, {1.0f, 1.0f, 1.0f}));
  const std::vector<std::string> faces = {"convert", "--faces", "f.exr", "f.exr", "f.exr", "f.exr", "f.exr", "f.exr"};
  std::vector<std::string> tight = faces, enough = faces;
  tight.insert(tight.end(), {"--max-texels", "95"});
  enough.insert(enough.end(), {"--max-texels", "96"});
  expect_one_line_error(shpack(dir, tight), "f.exr: the image is 4x4 (16 texels, 96 for 6 images), above the budget "
                                            "of 95 (--max-texels)");
  const CliResult faces_ok = shpack(dir, enough);
  EXPECT_EQ(faces_ok.exit_code, 0) << faces_ok.err;
  const CliResult zero = shpack(dir, {"convert", "sky.exr", "--max-texels", "0"});
  EXPECT_EQ(zero.exit_code, 2);
}

TEST(HostileInputs, ReadImageFileAndMapSourceCheckTheBudgetFromTheHeader) {
  ScratchDir dir;
  write_text(dir / "sky.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 20000 +X 20000\n");
  shpack::io::ImageFile image;  // preview --input and the bake's environment maps read this way
  const IoStatus st = shpack::io::read_image_file(dir / "sky.hdr", image);
  EXPECT_EQ(st.code, IoErrc::Unsupported);
  EXPECT_EQ(st.message, (dir / "sky.hdr").string() +
                            ": the image is 20000x20000 (400000000 texels), above the budget of 268435456 "
                            "(--max-texels)");
  shpack::io::MapSource source;
  shpack::io::SourceOptions options;
  EXPECT_EQ(options.max_texels, shpack::io::kDefaultMaxTexels);
  EXPECT_GE(shpack::io::kDefaultMaxTexels, std::uint64_t{16384} * 8192);
  options.layout = shpack::Layout::Angular;
  EXPECT_EQ(source.open(dir / "sky.hdr", options).message, st.message);
}

// ---- 2. documents are read through one checked open, within a size limit

TEST(HostileInputs, EvalAndPreviewRefuseADeviceUnread) {
  ScratchDir dir;
  expect_one_line_error(shpack(dir, {"eval", "/dev/zero", "--dir", "0,1,0"}),
                        "/dev/zero: is a device, not a regular file");
  expect_one_line_error(shpack(dir, {"preview", "/dev/zero", "-o", "lit.png"}),
                        "/dev/zero: is a device, not a regular file");
  EXPECT_FALSE(fs::exists(dir / "lit.png"));
}

TEST(HostileInputs, EvalRefusesANamedPipeWithoutWaitingForAWriter) {
  ScratchDir dir;
  ASSERT_EQ(::mkfifo((dir / "doc.json").c_str(), 0600), 0);
  expect_one_line_error(shpack(dir, {"eval", "doc.json", "--dir", "0,1,0"}),
                        "doc.json: is a named pipe (FIFO), not a regular file");
}

TEST(HostileInputs, DocumentsAboveTheLimitAreRefused) {
  ScratchDir dir;
  const auto size = static_cast<std::uintmax_t>(shpack::io::detail::kMaxDocumentBytes + 1);
  { std::ofstream(dir / "big.json", std::ios::binary); }
  fs::resize_file(dir / "big.json", size);  // sparse: no disk used
  expect_one_line_error(shpack(dir, {"eval", "big.json", "--dir", "0,1,0"}),
                        "big.json: the file is 67108865 bytes, above the limit of 67108864 bytes");
  // A pipe is read up to the limit, then refused.
  expect_one_line_error(shpack(dir, {"eval", "/dev/stdin", "--dir", "0,1,0"}, "head -c 70000000 /dev/zero | "),
                        "/dev/stdin: the input goes on past the limit of 67108864 bytes");
}

TEST(HostileInputs, ReadTextFileReadsFilesAndRefusesWhatIsNotOne) {
  ScratchDir dir;
  write_text(dir / "a.txt", "12345");
  std::string text;
  ASSERT_TRUE(shpack::io::detail::read_text_file(dir / "a.txt", 5, text).ok());
  EXPECT_EQ(text, "12345");
  const IoStatus over = shpack::io::detail::read_text_file(dir / "a.txt", 4, text);
  EXPECT_EQ(over.message, (dir / "a.txt").string() + ": the file is 5 bytes, above the limit of 4 bytes");
  EXPECT_EQ(shpack::io::detail::read_text_file(dir.path(), 4, text).message, dir.path().string() + ": is a directory");
  EXPECT_EQ(shpack::io::detail::read_text_file(dir / "none", 4, text).code, IoErrc::NotFound);
  EXPECT_EQ(shpack::io::detail::read_text_file("/dev/null", 4, text).message,
            "/dev/null: is a device, not a regular file");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(shpack::io::detail::read_text_file(dir / "fifo", 4, text).code, IoErrc::NotAFile);
  EXPECT_EQ(text, "12345");  // untouched on failure
}

TEST(HostileInputs, DeeplyNestedSchemaVersionIsNotDumped) {
  ScratchDir dir;
  write_text(dir / "deep.json",
             "{\"schema_version\": " + std::string(100000, '[') + std::string(100000, ']') + "}");
  shpack::io::ShJsonContent content;
  const IoStatus st = shpack::io::read_sh_json(dir / "deep.json", content);
  EXPECT_FALSE(st.ok());
  EXPECT_EQ(st.message.find('\n'), std::string::npos);
  EXPECT_LT(st.message.size(), 300u);
}

// ---- 3. colour comes from colour channels only

TEST(HostileInputs, AnImageWithoutColourChannelsIsRefusedNamingItsChannels) {
  ScratchDir dir;
  write_exr(dir / "az.exr", {"A", "Z"}, 8, 4);
  expect_one_line_error(shpack(dir, {"convert", "az.exr"}), "az.exr: no colour channels (R, G, B or Y); it has A, Z");
  write_exr(dir / "a.exr", {"A"}, 8, 4);
  expect_one_line_error(shpack(dir, {"convert", "a.exr"}), "a.exr: no colour channels (R, G, B or Y); it has A");
}

TEST(HostileInputs, AnImageWithSomeButNotAllOfRgbIsRefused) {
  ScratchDir dir;
  write_exr(dir / "rg.exr", {"R", "G"}, 8, 4);
  expect_one_line_error(shpack(dir, {"convert", "rg.exr"}),
                        "rg.exr: incomplete colour channels: no B (R, G and B, or Y, are read); it has R, G");
}

TEST(HostileInputs, GreyIsYOrOneUnnamedChannel) {
  ScratchDir dir;
  write_exr(dir / "y.exr", {"Y", "A"}, 8, 4);
  const CliResult y = shpack(dir, {"convert", "y.exr"});
  EXPECT_EQ(y.exit_code, 0) << y.err;
  write_text(dir / "grey.pfm", std::string("Pf\n8 4\n-1.0\n") + std::string(8 * 4 * 4, '\0'));
  const CliResult pfm = shpack(dir, {"convert", "grey.pfm"});
  EXPECT_EQ(pfm.exit_code, 0) << pfm.err;
}

// ---- 4. one line, always

TEST(HostileInputs, LibpngPrintsNothingOfItsOwn) {
  ScratchDir dir;
  write_text(dir / "bad.png", png_with_bad_idat_crc());
  const CliResult run = shpack(dir, {"convert", "bad.png", "--layout", "equirect"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err.rfind("shpack: bad.png: ", 0), 0u) << run.err;
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;  // exactly one line
  EXPECT_NE(run.err.find("CRC error"), std::string::npos) << run.err;  // libpng's reason is kept
}

TEST(HostileInputs, ControlCharactersInNamesAreEscaped) {
  ScratchDir dir;
  const std::string name = "a\x1b[31m\nb.exr";
  write_text(dir / name, "not an image");
  const CliResult run = shpack(dir, {"convert", name});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err.rfind("shpack: a\\x1b[31m\\x0ab.exr: ", 0), 0u) << run.err;
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
  EXPECT_EQ(run.err.find('\x1b'), std::string::npos);

  EXPECT_EQ(IoStatus::error(IoErrc::Unreadable, "x\ty\x7f", "bad\x01 name\nnext").message,
            "x\\x09y\\x7f: bad\\x01 name; next");
  EXPECT_EQ(IoStatus::error(IoErrc::Unreadable, "caf\xc3\xa9.exr", "ok").message, "caf\xc3\xa9.exr: ok");
}

TEST(HostileInputs, PermissionDeniedIsSaid) {
  EXPECT_EQ(shpack::io::detail::file_error("x.exr", EACCES).message, "x.exr: permission denied");
  ScratchDir dir;
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "x.exr", 8, 4, {1.0f, 1.0f, 1.0f}));
  fs::permissions(dir / "x.exr", fs::perms::none);
  std::string as_user;
  if (::geteuid() == 0) {  // root reads a mode-000 file: run as nobody instead
    if (std::system("command -v setpriv >/dev/null") != 0) GTEST_SKIP() << "root without setpriv";
    fs::permissions(dir.path(), fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                    fs::perms::others_read | fs::perms::others_exec);
    as_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
  }
  const CliResult run = shpack(dir, {"convert", "x.exr"}, {}, as_user);
  fs::permissions(dir / "x.exr", fs::perms::owner_read | fs::perms::owner_write);
  if (run.exit_code == 126 || run.exit_code == 127) GTEST_SKIP() << "nobody cannot run the command: " << run.err;
  expect_one_line_error(run, "x.exr: permission denied");
}

TEST(HostileInputs, AReadErrorWithoutAReasonPrintsNoEmptyParentheses) {
  ScratchDir dir;
  // Two flat scanlines of 4 texels need 32 bytes: 8 pass the header's check (4 a scanline),
  // and the read fails in the first scanline.
  write_text(dir / "short.hdr", std::string("#?RADIANCE\n\n-Y 2 +X 4\n") + std::string(8, '\x80'));
  const CliResult run = shpack(dir, {"convert", "short.hdr"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err.rfind("shpack: short.hdr: cannot read rows 0..1", 0), 0u) << run.err;
  EXPECT_EQ(run.err.find("()"), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
}

}  // namespace
