// The shpack command end to end: exit codes, one-line errors, outputs never clobbered.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <charconv>
#include <fstream>
#include <string>

#include "cli_runner.h"
#include "io_test_files.h"
#include "shpack/io/json_reader.h"
#include "shpack/unity_pack.h"

namespace {

namespace fs = std::filesystem;
using shpack_io_test::hdri;
using shpack_io_test::read_bytes;
using shpack_io_test::CliRun;
using shpack_io_test::ScratchDir;
using shpack_io_test::text_of;

// `shpack <args>`, stdin from `stdin_file` if given (cli_runner.h).
CliRun shpack(const ScratchDir& dir, const std::vector<std::string>& args, const fs::path& stdin_file = {}) {
  return shpack_io_test::run_shpack(dir, args, stdin_file);
}

std::string shortest(float v) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return {buffer, result.ptr};
}

TEST(Cli, ConvertThenEvalGivesUnitysShadeSH9) {
  const ScratchDir dir;
  const CliRun convert = shpack(dir, {"convert", hdri("courtyard.exr").string(), "-o", (dir / "c.json").string()});
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_EQ(convert.out, "");
  EXPECT_EQ(convert.err, "");

  // --dir need not be unit length: (0, 2, 0) is +Y.
  const CliRun eval = shpack(dir, {"eval", (dir / "c.json").string(), "--dir", "0,2,0"});
  ASSERT_EQ(eval.exit_code, 0) << eval.err;
  shpack::io::ShJsonContent content;
  ASSERT_TRUE(shpack::io::read_sh_json(dir / "c.json", content).ok());
  std::string want;
  for (int c = 0; c < 3; ++c)
    want += shortest(shpack::shade_sh9(content.shader, c, 0.0f, 1.0f, 0.0f)) + (c < 2 ? " " : "\n");
  EXPECT_EQ(eval.out, want);
}

TEST(Cli, EvalReadsAPipe) {
  const ScratchDir dir;
  ASSERT_EQ(shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "s.json").string()}).exit_code, 0);
  const CliRun from_file = shpack(dir, {"eval", (dir / "s.json").string(), "--dir", "1,0,0"});
  const CliRun from_pipe = shpack(dir, {"eval", "/dev/stdin", "--dir", "1,0,0"}, dir / "s.json");
  ASSERT_EQ(from_pipe.exit_code, 0) << from_pipe.err;
  EXPECT_EQ(from_pipe.out, from_file.out);
}

TEST(Cli, DashReadsTheDocumentFromStdin) {
  const ScratchDir dir;
  ASSERT_EQ(shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "s.json").string()}).exit_code, 0);
  const CliRun from_file = shpack(dir, {"eval", (dir / "s.json").string(), "--dir", "0,0,1"});
  const CliRun from_stdin = shpack(dir, {"eval", "-", "--dir", "0,0,1"}, dir / "s.json");
  ASSERT_EQ(from_stdin.exit_code, 0) << from_stdin.err;
  EXPECT_EQ(from_stdin.out, from_file.out);
  const CliRun preview = shpack(dir, {"preview", "-", "-o", (dir / "p.png").string()}, dir / "s.json");
  EXPECT_EQ(preview.exit_code, 0) << preview.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "p.png"));
  // Errors name it as the reader sees it.
  std::ofstream(dir / "bad.json") << "{";
  const CliRun bad = shpack(dir, {"eval", "-", "--dir", "0,1,0"}, dir / "bad.json");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.err.rfind("shpack: stdin: not valid JSON", 0), 0u) << bad.err;
  // A scene on stdin, named so; the files it names relative to the current folder (here
  // absolute). Its bake is the same file's, but for the name.
  const CliRun bake = shpack(dir, {"bake", "-"}, dir / "s.json");
  EXPECT_EQ(bake.exit_code, 1);
  EXPECT_EQ(bake.err.rfind("shpack: stdin: ", 0), 0u) << bake.err;
  std::ofstream(dir / "scene.json") << R"({"probes": [[0, 1, 0]], "environment": {"type": "map", "path": ")"
                                     << hdri("sunset.exr").string() << R"("}, "effects": ["environment"]})";
  const CliRun piped = shpack(dir, {"bake", "-"}, dir / "scene.json");
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  const CliRun named = shpack(dir, {"bake", (dir / "scene.json").string()});
  ASSERT_EQ(named.exit_code, 0) << named.err;
  const nlohmann::json a = nlohmann::json::parse(piped.out), b = nlohmann::json::parse(named.out);
  EXPECT_EQ(a["scene"]["file"], "stdin");
  EXPECT_EQ(a["scene"]["sha256"], b["scene"]["sha256"]);
  EXPECT_EQ(a["probes"], b["probes"]);  // (the effects' timings differ from run to run)
}

TEST(Cli, ConvertWithoutOutputPrintsTheJson) {
  const ScratchDir dir;
  ASSERT_EQ(shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "s.json").string()}).exit_code, 0);
  const CliRun run = shpack(dir, {"convert", hdri("studio.exr").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, text_of(dir / "s.json"));
}

TEST(Cli, ExposureAndIntensityMultiply) {
  const ScratchDir dir;
  const CliRun run = shpack(dir, {"convert", hdri("studio.exr").string(), "--intensity", "3", "--exposure", "-1"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(nlohmann::json::parse(run.out)["options"]["intensity"].get<double>(), 1.5);
}

TEST(Cli, FailedConvertKeepsTheExistingOutput) {
  const ScratchDir dir;
  const fs::path out = dir / "out.json";
  ASSERT_EQ(shpack(dir, {"convert", hdri("studio.exr").string(), "-o", out.string()}).exit_code, 0);
  const std::string good = text_of(out);
  std::vector<char> bytes = read_bytes(hdri("courtyard.exr"));
  bytes.resize(bytes.size() / 2);
  shpack_io_test::write_bytes(dir / "half.exr", bytes);

  const CliRun run = shpack(dir, {"convert", (dir / "half.exr").string(), "-o", out.string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err.rfind("shpack: " + (dir / "half.exr").string() + ": cannot read rows", 0), 0u) << run.err;
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "one line: " << run.err;
  EXPECT_EQ(text_of(out), good);
  // No temporary is left: they are hidden files beside the output (atomic_write.h).
  for (const auto& entry : fs::directory_iterator(dir.path()))
    EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();
}

TEST(Cli, ErrorsAreOneLineNamingTheFile) {
  const ScratchDir dir;
  const fs::path missing = dir / "missing.exr";
  const CliRun run = shpack(dir, {"convert", missing.string(), "-o", (dir / "out.json").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + missing.string() + ": no such file\n");
  EXPECT_FALSE(fs::exists(dir / "out.json"));
}

TEST(Cli, ErrorsSayHowToGoOn) {
  const ScratchDir dir;
  std::vector<float> pixels(8 * 4 * 3, 1.0f);
  pixels[(1 * 8 + 3) * 3] = std::numeric_limits<float>::quiet_NaN();
  ASSERT_TRUE(shpack_io_test::write_image(dir / "nan.exr", 8, 4, 3, pixels));
  CliRun run = shpack(dir, {"convert", (dir / "nan.exr").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "nan.exr").string() +
                         ": 1 NaN/Inf texels (first at x=3, y=1); use --nonfinite=zero to replace them\n");
  run = shpack(dir, {"convert", (dir / "nan.exr").string(), "--nonfinite=zero"});
  EXPECT_EQ(run.exit_code, 0) << run.err;

  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "odd.exr", 6, 4, {1.0f, 1.0f, 1.0f}));
  run = shpack(dir, {"convert", (dir / "odd.exr").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("; name the layout with --layout\n"), std::string::npos) << run.err;
  EXPECT_EQ(shpack(dir, {"convert", (dir / "odd.exr").string(), "--layout", "equirect"}).exit_code, 0);
}

TEST(Cli, OutDirConvertsEveryGoodInput) {
  const ScratchDir dir;
  const fs::path out_dir = dir / "out";
  const CliRun run = shpack(dir, {"convert", hdri("studio.exr").string(), (dir / "missing.exr").string(),
                               hdri("night.exr").string(), "--out-dir", out_dir.string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "missing.exr").string() + ": no such file\n");
  EXPECT_TRUE(fs::is_regular_file(out_dir / "studio.json"));
  EXPECT_TRUE(fs::is_regular_file(out_dir / "night.json"));
  EXPECT_FALSE(fs::exists(out_dir / "missing.json"));
}

TEST(Cli, UsageErrorsExitWithTwo) {
  const ScratchDir dir;
  const std::string studio = hdri("studio.exr").string();
  const std::vector<std::vector<std::string>> usage_errors = {
      {},
      {"convert"},
      {"convert", studio, "--method", "fast"},
      {"convert", studio, "--intensity", "nan"},
      {"convert", studio, "--intensity", "-1"},
      {"convert", studio, hdri("night.exr").string()},  // two inputs need --out-dir
      {"convert", studio, "-o", "a.json", "--out-dir", "b"},
      {"convert", studio, "--out-dir", (dir / "o").string(), "--out-dir", (dir / "p").string()},
      {"eval", "x.json", "--dir", "0,0,0"},
      {"eval", "x.json", "--dir", "0,1"},
  };
  for (const std::vector<std::string>& args : usage_errors) {
    const CliRun run = shpack(dir, args);
    std::string joined;
    for (const std::string& a : args) joined += a + " ";
    EXPECT_EQ(run.exit_code, 2) << joined << "\n" << run.err;
    EXPECT_EQ(run.err.rfind("shpack: ", 0), 0u) << joined << "\n" << run.err;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << joined << "\n" << run.err;
    // Each names where the options it got wrong are listed.
    const std::string help = args.empty() ? "(see shpack --help)\n" : "(see shpack " + args[0] + " --help)\n";
    EXPECT_TRUE(run.err.ends_with(help)) << joined << "\n" << run.err;
  }
}

TEST(Cli, AnUnknownCommandIsNamedWithTheNearestOne) {
  const ScratchDir dir;
  CliRun run = shpack(dir, {"convrt", "map.exr"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "shpack: 'convrt' is not a command; did you mean 'convert'? (see shpack --help)\n");
  run = shpack(dir, {"bkae", "scene.json"});  // a transposition is one edit
  EXPECT_EQ(run.err, "shpack: 'bkae' is not a command; did you mean 'bake'? (see shpack --help)\n");
  run = shpack(dir, {"frobnicate"});  // nothing near: no guess
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "shpack: 'frobnicate' is not a command (see shpack --help)\n");
}

TEST(Cli, HelpShowsTypesAPersonReads) {
  // CLI11's own type and validator names (UINT, FLOAT:NUMBER >= 0, UINT:(UINT) AND (UINT in
  // [1 - 1000000])) say nothing to a person; every option names what it takes (N, K, DEG, FILE).
  const ScratchDir dir;
  for (const char* command : {"convert", "eval", "bench", "preview", "bake"}) {
    const CliRun run = shpack(dir, {command, "--help"});
    EXPECT_EQ(run.exit_code, 0) << command;
    for (const char* jargon : {"UINT", "INT", "FLOAT", "TEXT", " AND ", ":NUMBER", "[1 - "})
      EXPECT_EQ(run.out.find(jargon), std::string::npos) << command << " --help shows " << jargon << ":\n" << run.out;
  }
  const CliRun convert = shpack(dir, {"convert", "--help"});
  for (const char* shown : {"--intensity K", "--rotate DEG", "--threads N", "-o,--output FILE", "--window W"})
    EXPECT_NE(convert.out.find(shown), std::string::npos) << shown << "\n" << convert.out;
}

TEST(Cli, EveryCommandPrintsTheVersion) {
  const ScratchDir dir;
  const CliRun top = shpack(dir, {"--version"});
  ASSERT_EQ(top.exit_code, 0);
  ASSERT_TRUE(top.out.starts_with("shpack ")) << top.out;
  for (const char* command : {"convert", "eval", "bench", "preview", "bake"}) {
    const CliRun run = shpack(dir, {command, "--version"});
    EXPECT_EQ(run.exit_code, 0) << command << ": " << run.err;
    EXPECT_EQ(run.out, top.out) << command;
  }
}

TEST(Cli, InputIsNeverItsOwnOutput) {
  const ScratchDir dir;
  const fs::path sky = dir / "sky.exr";
  fs::copy_file(hdri("studio.exr"), sky);
  const CliRun run = shpack(dir, {"convert", sky.string(), "-o", sky.string()});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(read_bytes(sky), read_bytes(hdri("studio.exr")));
}

}  // namespace
