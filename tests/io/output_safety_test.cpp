// Output files as every command writes them (docs/security.md, "Output files"): a signal
// leaves no temporary and the old output intact; devices, FIFOs and stdout are written in
// place; "-" is stdout; no command writes over one of its inputs.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "cli_runner.h"
#include "io_test_files.h"

namespace {

namespace fs = std::filesystem;
using shpack_io_test::CliRun;
using shpack_io_test::hdri;
using shpack_io_test::ScratchDir;
using shpack_io_test::text_of;

CliRun shpack(const ScratchDir& dir, const std::vector<std::string>& args) {
  return shpack_io_test::run_shpack(dir, args);
}

void write_text(const fs::path& path, const std::string& text) {
  shpack_io_test::write_bytes(path, std::vector<char>(text.begin(), text.end()));
}

// Entries of `dir` whose name starts with `prefix`.
std::vector<std::string> entries_starting(const fs::path& dir, const std::string& prefix) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().rfind(prefix, 0) == 0) names.push_back(entry.path().filename().string());
  return names;
}

// A small scene in `dir`: three probes over a plane, lit by one directional light, plus the
// `extra` members (a JSON fragment starting with a comma).
fs::path write_scene(const ScratchDir& dir, const std::string& name, const std::string& extra = "",
                     const std::string& geometry = "") {
  const std::string text = R"({"probes": [[0, 1, 0], [1, 1, 0], [2, 1, 0]],
    "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 3}],
    "geometry": [{"type": "plane", "position": [0, 0, 0], "right": [1, 0, 0], "up": [0, 0, 1], "size": [10, 10]})" +
                           geometry + R"(],
    "effects": ["direct", "shadows"])" + extra + "}";
  write_text(dir / name, text);
  return dir / name;
}

// ---- 2. signals --------------------------------------------------------------------------

// Starts `shpack args` with SHPACK_TEST_PAUSE_IN_WRITE set (atomic_write.cpp: the write
// stops after its first chunk), stdout and stderr to files of `dir`.
pid_t start_paused(const ScratchDir& dir, const std::vector<std::string>& args) {
  const pid_t child = ::fork();
  if (child != 0) return child;
  ::setenv("SHPACK_TEST_PAUSE_IN_WRITE", "1", 1);
  const int out = ::open((dir / "child_out.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  const int err = ::open((dir / "child_err.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ::dup2(out, 1);
  ::dup2(err, 2);
  std::vector<char*> argv = {const_cast<char*>(SHPACK_CLI_PATH)};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(SHPACK_CLI_PATH, argv.data());
  _exit(127);
}

// Waits up to 60 s for a temporary of `name` (".<name>.") in `folder`; its name, or "".
std::string wait_for_temporary(const fs::path& folder, const std::string& name, pid_t child) {
  for (int k = 0; k < 6000; ++k) {
    const std::vector<std::string> found = entries_starting(folder, "." + name + ".");
    if (!found.empty() && fs::file_size(folder / found[0]) > 0) return found[0];
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child) return "";  // ended without pausing
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return "";
}

void expect_signal_removes_the_temporary(const ScratchDir& dir, const std::vector<std::string>& command,
                                         const fs::path& out, int sig) {
  SCOPED_TRACE(std::string("signal ") + ::strsignal(sig));
  write_text(out, "the old output");
  std::vector<std::string> args = command;
  args.push_back("-o");
  args.push_back(out.string());
  const pid_t child = start_paused(dir, args);
  ASSERT_GT(child, 0);
  const std::string temp = wait_for_temporary(out.parent_path(), out.filename().string(), child);
  if (temp.empty()) {
    ::kill(child, SIGKILL);
    ::waitpid(child, nullptr, 0);
    FAIL() << "no temporary seen while the output was written";
  }
  // The temporary: hidden, next to the output, ten random characters, private while written.
  EXPECT_EQ(temp.size(), out.filename().string().size() + 2 + 10) << temp;
  struct stat st {};
  ASSERT_EQ(::lstat((out.parent_path() / temp).c_str(), &st), 0);
  EXPECT_TRUE(S_ISREG(st.st_mode));
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  ASSERT_EQ(::kill(child, sig), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "status " << status;
  EXPECT_TRUE(entries_starting(out.parent_path(), "." + out.filename().string() + ".").empty())
      << "the temporary is left behind";
  EXPECT_EQ(text_of(out), "the old output");
}

TEST(OutputSafety, SignalDuringConvertWriteRemovesTheTemporary) {
  const ScratchDir dir;
  for (int sig : {SIGINT, SIGTERM, SIGHUP})
    expect_signal_removes_the_temporary(dir, {"convert", hdri("studio.exr").string()}, dir / "out.json", sig);
}

TEST(OutputSafety, SignalDuringBakeWriteRemovesTheTemporary) {
  const ScratchDir dir;
  const fs::path scene = write_scene(dir, "scene.json");
  expect_signal_removes_the_temporary(dir, {"bake", scene.string(), "--quiet"}, dir / "baked.json", SIGINT);
}

// ---- 3. devices, FIFOs, stdout -----------------------------------------------------------

TEST(OutputSafety, DeviceTargetStaysADevice) {
  // A null device of our own (mknod needs root; /dev/null itself is not put at risk).
  const ScratchDir dir;
  if (::mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) GTEST_SKIP() << "mknod not permitted";
  const CliRun run = shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "null").string()});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  struct stat st {};
  ASSERT_EQ(::lstat((dir / "null").c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode)) << "the device was replaced by a regular file";
  EXPECT_TRUE(entries_starting(dir.path(), ".null.").empty());
}

TEST(OutputSafety, FifoTargetIsWrittenInPlace) {
  const ScratchDir dir;
  ASSERT_TRUE(shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "want.json").string()}).exit_code == 0);
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  const int reader = ::open((dir / "pipe").c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  const CliRun run = shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "pipe").string()});
  std::string got;
  char buffer[4096];
  for (ssize_t n; (n = ::read(reader, buffer, sizeof buffer)) > 0;) got.append(buffer, static_cast<std::size_t>(n));
  ::close(reader);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(got, text_of(dir / "want.json"));
  struct stat st {};
  ASSERT_EQ(::lstat((dir / "pipe").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced by a regular file";
}

TEST(OutputSafety, DashIsStdoutForEveryCommand) {
  const ScratchDir dir;
  const std::string map = hdri("studio.exr").string();
  ASSERT_EQ(shpack(dir, {"convert", map, "-o", (dir / "s.json").string()}).exit_code, 0);
  const CliRun convert = shpack(dir, {"convert", map, "-o", "-"});
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_EQ(convert.out, text_of(dir / "s.json"));

  const fs::path scene = write_scene(dir, "scene.json");
  ASSERT_EQ(shpack(dir, {"bake", scene.string(), "--quiet", "-o", (dir / "b.json").string()}).exit_code, 0);
  const CliRun bake = shpack(dir, {"bake", scene.string(), "--quiet", "-o", "-"});
  EXPECT_EQ(bake.exit_code, 0) << bake.err;
  EXPECT_EQ(nlohmann::json::parse(bake.out).at("probes"),  // the costs (timings) differ from run to run
            nlohmann::json::parse(text_of(dir / "b.json")).at("probes"));

  ASSERT_EQ(shpack(dir, {"preview", (dir / "s.json").string(), "-o", (dir / "p.png").string()}).exit_code, 0);
  const CliRun preview = shpack(dir, {"preview", (dir / "s.json").string(), "-o", "-"});
  EXPECT_EQ(preview.exit_code, 0) << preview.err;
  EXPECT_EQ(preview.out, text_of(dir / "p.png")) << "stdout holds the PNG bytes, and only them";
  EXPECT_NE(preview.err.find("tone mapping:"), std::string::npos) << "the report goes to stderr";
  EXPECT_FALSE(fs::exists(fs::current_path() / "-")) << "a file named - was written";
}

TEST(OutputSafety, DevStdoutIsWrittenInPlace) {
  const ScratchDir dir;
  const std::string map = hdri("studio.exr").string();
  ASSERT_EQ(shpack(dir, {"convert", map, "-o", (dir / "s.json").string()}).exit_code, 0);
  const CliRun run = shpack(dir, {"convert", map, "-o", "/dev/stdout"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, text_of(dir / "s.json"));
  EXPECT_TRUE(fs::is_symlink("/dev/stdout") || !fs::is_regular_file(fs::symlink_status("/dev/stdout")));
}

TEST(OutputSafety, DirectoryTargetIsAnErrorNamingIt) {
  const ScratchDir dir;
  fs::create_directory(dir / "out");
  const CliRun run = shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "out").string()});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "shpack: " + (dir / "out").string() + ": is a directory\n");
  EXPECT_TRUE(fs::is_directory(dir / "out"));
}

// ---- 4. an output is never an input ------------------------------------------------------

// Runs `args`, expects exit 2 and "shpack: <output>: is both an input and the output (see
// shpack <command> --help)", and `output` unchanged.
void expect_refused(const ScratchDir& dir, const std::vector<std::string>& args, const fs::path& output) {
  const std::vector<char> before = shpack_io_test::read_bytes(output);
  const CliRun run = shpack(dir, args);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err, "shpack: " + output.string() + ": is both an input and the output (see shpack " + args[0] +
                         " --help)\n");
  EXPECT_EQ(shpack_io_test::read_bytes(output), before) << "the input was overwritten";
}

TEST(OutputSafety, BakeRefusesToWriteOverItsSceneMeshOrMap) {
  const ScratchDir dir;
  const fs::path scene = write_scene(dir, "v.json");
  expect_refused(dir, {"bake", scene.string(), "--quiet", "-o", scene.string()}, scene);

  write_text(dir / "tri.obj", "v -1 0 -1\nv 1 0 -1\nv 0 0 1\nf 1 2 3\n");
  const fs::path with_mesh = write_scene(dir, "mesh.json", "", R"(, {"type": "mesh", "path": "tri.obj"})");
  expect_refused(dir, {"bake", with_mesh.string(), "--quiet", "-o", (dir / "tri.obj").string()}, dir / "tri.obj");

  // A .gltf mesh and its external buffer: one triangle, three float positions, three indices.
  const float positions[9] = {-1, 0, -1, 1, 0, -1, 0, 0, 1};
  const std::uint16_t indices[4] = {0, 1, 2, 0};
  std::vector<char> bin(sizeof positions + sizeof indices);
  std::memcpy(bin.data(), positions, sizeof positions);
  std::memcpy(bin.data() + sizeof positions, indices, sizeof indices);
  shpack_io_test::write_bytes(dir / "tri.bin", bin);
  write_text(dir / "tri.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "buffers": [{"uri": "tri.bin", "byteLength": 44}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [-1, 0, -1], "max": [1, 0, 1]},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})");
  const fs::path with_gltf = write_scene(dir, "gltf.json", "", R"(, {"type": "mesh", "path": "tri.gltf"})");
  ASSERT_EQ(shpack(dir, {"bake", with_gltf.string(), "--quiet", "-o", (dir / "g.json").string()}).exit_code, 0);
  expect_refused(dir, {"bake", with_gltf.string(), "--quiet", "-o", (dir / "tri.bin").string()}, dir / "tri.bin");

  fs::copy_file(hdri("studio.exr"), dir / "sky.exr");
  const fs::path with_map = write_scene(dir, "map.json", R"(, "environment": {"type": "map", "path": "sky.exr"})");
  expect_refused(dir, {"bake", with_map.string(), "--quiet", "-o", (dir / "sky.exr").string()}, dir / "sky.exr");
}

TEST(OutputSafety, PreviewRefusesToWriteOverItsInputMap) {
  const ScratchDir dir;
  ASSERT_EQ(shpack(dir, {"convert", hdri("studio.exr").string(), "-o", (dir / "s.json").string()}).exit_code, 0);
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "map.png", 16, 8, {0.5f, 0.5f, 0.5f}, OIIO::TypeDesc::UINT8));
  expect_refused(dir, {"preview", (dir / "s.json").string(), "--input", (dir / "map.png").string(), "-o",
                       (dir / "map.png").string()},
                 dir / "map.png");
}

TEST(OutputSafety, ConvertRefusesAnInputUnderAnotherName) {
  const ScratchDir dir;
  fs::copy_file(hdri("studio.exr"), dir / "in.exr");
  fs::create_hard_link(dir / "in.exr", dir / "hard.json");
  expect_refused(dir, {"convert", (dir / "in.exr").string(), "-o", (dir / "hard.json").string()}, dir / "hard.json");
  // --out-dir: one input's output is another input.
  fs::copy_file(hdri("studio.exr"), dir / "in.json");
  expect_refused(dir, {"convert", (dir / "in.exr").string(), (dir / "in.json").string(), "--out-dir", dir.path().string()},
                 dir / "in.json");
}

}  // namespace
