// `shpack convert -`: the image on stdin gives the document its file gives (named "stdin",
// with the same SHA-256), its temporary copy is removed, and an empty, truncated or
// over-budget stdin, or `-` beside other inputs, is a one-line error.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"

namespace {

namespace fs = std::filesystem;
using shpack_io_test::CliRun;
using shpack_io_test::run_shpack;
using shpack_io_test::ScratchDir;

// TMPDIR for the commands run while it lives, so that the test sees what they leave there.
struct TempDirFor {
  explicit TempDirFor(const fs::path& dir) {
    fs::create_directories(dir);
    setenv("TMPDIR", dir.c_str(), 1);
  }
  ~TempDirFor() { unsetenv("TMPDIR"); }
};

TEST(StdinInput, TheImageOnStdinIsItsFilesDocument) {
  const ScratchDir dir;
  const TempDirFor tmp(dir / "tmp");
  const fs::path map = shpack_io_test::hdri("studio.exr");
  const CliRun piped = run_shpack(dir, {"convert", "-", "--rotate", "30"}, map);
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  const CliRun direct = run_shpack(dir, {"convert", map.string(), "--rotate", "30"});
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  nlohmann::json a = nlohmann::json::parse(piped.out), b = nlohmann::json::parse(direct.out);
  EXPECT_EQ(a["source"]["files"], nlohmann::json::array({"stdin"}));
  EXPECT_EQ(a["source"]["sha256"], b["source"]["sha256"]);
  a["source"]["files"] = b["source"]["files"];
  EXPECT_EQ(a, b);
  EXPECT_TRUE(fs::is_empty(dir / "tmp"));  // the temporary copy is gone
}

TEST(StdinInput, BadStdinIsAOneLineErrorAndLeavesNothing) {
  const ScratchDir dir;
  const TempDirFor tmp(dir / "tmp");
  const std::vector<char> empty;
  shpack_io_test::write_bytes(dir / "empty", empty);
  CliRun run = run_shpack(dir, {"convert", "-"}, dir / "empty");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: stdin: empty: no image on it\n");
  std::vector<char> bytes = shpack_io_test::read_bytes(shpack_io_test::hdri("studio.exr"));
  bytes.resize(1000);
  shpack_io_test::write_bytes(dir / "truncated", bytes);
  run = run_shpack(dir, {"convert", "-", "-o", (dir / "out.json").string()}, dir / "truncated");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err.rfind("shpack: stdin: ", 0), 0u) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out.json"));
  // The budget: 16 bytes a texel of --max-texels and 1 MiB, checked while it is read.
  std::vector<char> big((std::size_t{1} << 20) + 16 * 10 + 1, 'x');
  shpack_io_test::write_bytes(dir / "big", big);
  run = run_shpack(dir, {"convert", "-", "--max-texels", "10"}, dir / "big");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("shpack: stdin: more than 1048736 bytes"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::is_empty(dir / "tmp"));
  run = run_shpack(dir, {"convert", "-", shpack_io_test::hdri("studio.exr").string(), "--out-dir", dir.path().string()});
  EXPECT_EQ(run.exit_code, 2) << run.err;
}

TEST(StdinInput, PreviewTakesItsInputMapFromStdin) {
  const ScratchDir dir;
  const TempDirFor tmp(dir / "tmp");
  const fs::path map = shpack_io_test::hdri("studio.exr");
  ASSERT_EQ(run_shpack(dir, {"convert", map.string(), "-o", (dir / "s.json").string()}).exit_code, 0);
  const CliRun piped = run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "a.png").string(), "--input", "-"}, map);
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.err, "");  // its SHA-256 is the document's: no warning
  const CliRun direct = run_shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "b.png").string(), "--input", map.string()});
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  EXPECT_EQ(piped.out, direct.out);
  EXPECT_TRUE(fs::is_empty(dir / "tmp"));
  const CliRun both = run_shpack(dir, {"preview", "-", "-o", (dir / "c.png").string(), "--input", "-"}, map);
  EXPECT_EQ(both.exit_code, 2) << both.err;
}

TEST(StdinInput, BenchMeasuresAMapOnStdin) {
  const ScratchDir dir;
  const TempDirFor tmp(dir / "tmp");
  const CliRun run = run_shpack(dir, {"bench", "-", "--methods", "center", "--quick", "--repeats", "1", "--json"},
                                shpack_io_test::hdri("studio.exr"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json records = nlohmann::json::parse(run.out);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0]["input"], "stdin");
  EXPECT_TRUE(fs::is_empty(dir / "tmp"));
}

}  // namespace
