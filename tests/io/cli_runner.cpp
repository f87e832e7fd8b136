#include "cli_runner.h"

#include <sys/wait.h>

#include <cstdlib>

namespace shpack_io_test {

std::string text_of(const std::filesystem::path& path) {
  const std::vector<char> bytes = read_bytes(path);
  return {bytes.begin(), bytes.end()};
}

CliRun run_shpack(const ScratchDir& dir, const std::vector<std::string>& args, const std::filesystem::path& stdin_file) {
  std::string command = std::string("'") + SHPACK_CLI_PATH + "'";
  if (!stdin_file.empty()) command = "cat '" + stdin_file.string() + "' | " + command;
  for (const std::string& a : args) command += " '" + a + "'";
  command += " >'" + (dir / "stdout.txt").string() + "' 2>'" + (dir / "stderr.txt").string() + "'";
  const int status = std::system(command.c_str());
  CliRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = text_of(dir / "stdout.txt");
  run.err = text_of(dir / "stderr.txt");
  std::filesystem::remove(dir / "stdout.txt");
  std::filesystem::remove(dir / "stderr.txt");
  return run;
}

}  // namespace shpack_io_test
