// cli_runner.h - runs the built shpack command with its output captured, for CLI tests.
#pragma once

#include <string>
#include <vector>

#include "io_test_files.h"

namespace shpack_io_test {

struct CliRun {
  int exit_code = -1;  // -1 if the command did not exit normally
  std::string out, err;
};

// Runs `shpack <args>` (each argument single-quoted for the shell) with stdout and stderr
// captured in files of `dir`, which are removed afterwards.
CliRun run_shpack(const ScratchDir& dir, const std::vector<std::string>& args);

}  // namespace shpack_io_test
