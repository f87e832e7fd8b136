// cli_runner.h - runs the built shpack command with its output captured, for CLI tests.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io_test_files.h"

namespace shpack_io_test {

struct CliRun {
  int exit_code = -1;  // -1 if the command did not exit normally
  std::string out, err;
};

// Runs `shpack <args>` (each argument single-quoted for the shell) with stdout and stderr
// captured in files of `dir`, which are removed afterwards, and stdin a pipe from
// `stdin_file` if one is given.
CliRun run_shpack(const ScratchDir& dir, const std::vector<std::string>& args,
                  const std::filesystem::path& stdin_file = {});

// The whole file as a string.
std::string text_of(const std::filesystem::path& path);

}  // namespace shpack_io_test
