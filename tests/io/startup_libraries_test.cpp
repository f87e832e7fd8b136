// Which shared libraries the shpack command loads (lib/io/src/oiio_plugin.h): --help,
// convert of an OpenEXR file and eval never load libOpenImageIO (nor the libraries Debian's
// build of it links; for .hdr and PFM see hdr_reader_test.cpp); a format only OpenImageIO
// reads (TIFF here) loads shpack's module on first use,
// and without the module that is one line naming where it was looked for. The dynamic
// linker says what it loaded (LD_DEBUG=libs, into files of a scratch folder).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "io_test_files.h"

namespace {

namespace fs = std::filesystem;
using shpack_io_test::ScratchDir;

struct TracedRun {
  int exit_code = -1;
  std::string err;
  std::string loaded;  // what the dynamic linker reported, all processes together
};

// `cli args` in `dir`, with the dynamic linker's report of the libraries it loads.
TracedRun run_traced(const ScratchDir& dir, const fs::path& cli, const std::string& args) {
  const fs::path trace = dir / "ld";
  fs::create_directories(trace);
  const std::string command = "cd '" + dir.path().string() + "' && LD_DEBUG=libs LD_DEBUG_OUTPUT='" +
                              (trace / "libs").string() + "' '" + cli.string() + "' " + args +
                              " >/dev/null 2>'" + (dir / "stderr.txt").string() + "'";
  const int status = std::system(command.c_str());
  TracedRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const std::vector<char> err = shpack_io_test::read_bytes(dir / "stderr.txt");
  run.err.assign(err.begin(), err.end());
  for (const fs::directory_entry& e : fs::directory_iterator(trace)) {
    const std::vector<char> bytes = shpack_io_test::read_bytes(e.path());
    run.loaded.append(bytes.begin(), bytes.end());
    fs::remove(e.path());
  }
  return run;
}

bool loads(const TracedRun& run, const std::string& library) { return run.loaded.find(library) != std::string::npos; }

TEST(StartupLibraries, HelpConvertOfExrAndEvalNeverLoadOpenImageIO) {
  const ScratchDir dir;
  const TracedRun help = run_traced(dir, SHPACK_CLI_PATH, "--help");
  EXPECT_EQ(help.exit_code, 0) << help.err;
  ASSERT_TRUE(loads(help, "libOpenEXR")) << "the linker's report is empty: " << help.loaded.substr(0, 200);
  const std::string map = shpack_io_test::hdri("studio.exr").string();
  const TracedRun convert = run_traced(dir, SHPACK_CLI_PATH, "convert '" + map + "' -o sky.json");
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  const TracedRun eval = run_traced(dir, SHPACK_CLI_PATH, "eval sky.json --dir 0,1,0");
  EXPECT_EQ(eval.exit_code, 0) << eval.err;
  for (const TracedRun* run : {&help, &convert, &eval}) {
    EXPECT_FALSE(loads(*run, "libOpenImageIO"));
    EXPECT_FALSE(loads(*run, "libshpack_oiio"));
  }
}

TEST(StartupLibraries, OtherFormatsLoadTheModuleOnFirstUse) {
  const ScratchDir dir;
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "sky.tif", 8, 4, {1.0f, 2.0f, 3.0f}));
  const TracedRun convert = run_traced(dir, SHPACK_CLI_PATH, "convert sky.tif -o sky.json");
  EXPECT_EQ(convert.exit_code, 0) << convert.err;
  EXPECT_TRUE(loads(convert, "libshpack_oiio"));
  EXPECT_TRUE(loads(convert, "libOpenImageIO"));
}

TEST(StartupLibraries, WithoutTheModuleOnlyOtherFormatsFailInOneLine) {
  // A copy of the command in a folder of its own, with no module beside it or below it.
  const ScratchDir dir;
  const fs::path cli = dir / "bin" / "shpack";
  fs::create_directories(cli.parent_path());
  fs::copy_file(SHPACK_CLI_PATH, cli);
  ASSERT_TRUE(shpack_io_test::write_constant_image(dir / "sky.tif", 8, 4, {1.0f, 2.0f, 3.0f}));
  const TracedRun tif = run_traced(dir, cli, "convert sky.tif -o sky.json");
  EXPECT_EQ(tif.exit_code, 1);
  const fs::path lib = (cli.parent_path() / SHPACK_PLUGIN_RELDIR).lexically_normal();
  EXPECT_EQ(tif.err, "shpack: sky.tif: formats other than OpenEXR, Radiance .hdr and PFM are read through "
                     "OpenImageIO: shpack's OpenImageIO module libshpack_oiio.so is in neither " +
                         cli.parent_path().string() + " nor " + lib.string() + "\n");
  EXPECT_FALSE(fs::exists(dir / "sky.json"));
  const TracedRun exr = run_traced(dir, cli, "convert '" + shpack_io_test::hdri("studio.exr").string() + "' -o sky.json");
  EXPECT_EQ(exr.exit_code, 0) << exr.err;
}

}  // namespace
