#include "shpack/study/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <system_error>

extern char** environ;

namespace shpack::study {

namespace fs = std::filesystem;

std::string gnuplot_quoted(const std::string& text) {
  std::string out = "'";
  for (const char ch : text) out += ch == '\'' ? std::string("''") : std::string(1, ch);
  return out + "'";
}

std::string gnuplot_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

std::string gnuplot_front_rows(const std::vector<FrontPoint>& front) {
  std::string rows;
  double last = 0;  // the error of the last row written
  for (const FrontPoint& p : front) {
    if (!(p.time_ms > 0)) continue;
    if (p.err_pct > 0) last = p.err_pct;
    else if (last == 0) break;  // nothing above 0 before it: no staircase
    rows.append(gnuplot_number(p.time_ms)).append(" ").append(gnuplot_number(last)).append("\n");
  }
  return rows;
}

io::IoStatus run_gnuplot(const std::string& prefix,
                         const std::function<std::string(const fs::path& png, const fs::path& svg)>& script_of) {
  const fs::path png = prefix + ".png", svg = prefix + ".svg";
  const std::string tag = ".tmp." + std::to_string(::getpid());
  const fs::path png_tmp = png.string() + tag, svg_tmp = svg.string() + tag;
  const fs::path script = prefix + ".gp" + tag, errors = prefix + ".gnuplot-errors" + tag;
  {
    std::ofstream out(script);
    out << script_of(png_tmp, svg_tmp);
    if (!out.flush()) return io::IoStatus::error(io::IoErrc::WriteFailed, script, "cannot write the gnuplot script");
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::string script_arg = script.string();
  char gnuplot[] = "gnuplot";
  char* argv[] = {gnuplot, script_arg.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (spawned == 0) waitpid(pid, &status, 0);

  std::string problem;
  if (spawned == ENOENT) {
    problem = "gnuplot is not installed (Debian: gnuplot-nox, see scripts/install-deps.sh)";
  } else if (spawned != 0) {
    problem = "cannot run gnuplot: " + std::generic_category().message(spawned);
  } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    // gnuplot quotes the script line and then says what is wrong, on the last line.
    std::ifstream in(errors);
    std::string line, last;
    while (std::getline(in, line))
      if (line.find_first_not_of(" \t^") != std::string::npos) last = line.substr(line.find_first_not_of(" \t"));
    problem = "gnuplot failed" + (last.empty() ? std::string() : ": " + last);
  }
  std::error_code ec;
  if (problem.empty()) {
    fs::rename(png_tmp, png, ec);
    if (ec) problem = "cannot replace the file: " + ec.message();
  }
  if (problem.empty()) {
    fs::rename(svg_tmp, svg, ec);
    if (ec) problem = "cannot replace " + svg.string() + ": " + ec.message();
  }
  for (const fs::path& temp : {png_tmp, svg_tmp, script, errors}) fs::remove(temp, ec);
  if (!problem.empty())
    return io::IoStatus::error(spawned == ENOENT ? io::IoErrc::NotFound : io::IoErrc::WriteFailed, png, problem);
  return io::IoStatus::success();
}

}  // namespace shpack::study
