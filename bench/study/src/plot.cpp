#include "shpack/study/plot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <system_error>

#include "shpack/study/method_sweep.h"
#include "shpack/study/study_report.h"

extern char** environ;

namespace shpack::study {
namespace {

namespace fs = std::filesystem;

// One colour per method, far enough apart to tell eleven lines apart.
constexpr const char* kColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                                    "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#393b79"};

// gnuplot's single-quoted string: no escapes but '' for a quote, so any path survives.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char ch : text) out += ch == '\'' ? std::string("''") : std::string(1, ch);
  return out + "'";
}

bool plottable(const SpecSummary& s) { return s.err_max_pct > 0 && s.time_ms > 0; }  // false for NaN

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

}  // namespace

std::string plot_script(const std::vector<StudyRecord>& records, const fs::path& png, const fs::path& svg) {
  const std::vector<SpecSummary> summaries = summarize(records);
  std::map<SamplingMethod, std::vector<SpecSummary>> lines;
  const SpecSummary* exact = nullptr;
  for (const SpecSummary& s : summaries) {
    if (s.spec.method == SamplingMethod::Exact) exact = &s;
    else if (plottable(s)) lines[s.spec.method].push_back(s);
  }
  std::vector<SpecSummary> by_time;
  for (const auto& [method, points] : lines) by_time.insert(by_time.end(), points.begin(), points.end());
  std::sort(by_time.begin(), by_time.end(),
            [](const SpecSummary& a, const SpecSummary& b) { return a.time_ms < b.time_ms; });
  std::vector<SpecSummary> front;  // by time; each beats every faster spec in error
  for (const SpecSummary& s : by_time) {
    const bool slower_than_exact = exact != nullptr && s.time_ms >= exact->time_ms;  // exact beats it
    if (!slower_than_exact && (front.empty() || s.err_max_pct < front.back().err_max_pct)) front.push_back(s);
  }

  std::set<std::string> inputs;
  for (const StudyRecord& r : records) inputs.insert(r.input);
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1200,800 font 'sans,11' noenhanced\n"
     << "set output " << quoted(png.string()) << "\n"
     << "set title " << quoted(inputs.size() == 1 ? *inputs.begin() : std::to_string(inputs.size()) + " inputs")
     << "\nset logscale xy\nset format x '%g'\nset format y '%g'\n"
     << "set xlabel 'time per projection, ms (median" << (inputs.size() > 1 ? " over the inputs" : "") << ")'\n"
     << "set ylabel 'max error of E/pi, % of its mean" << (inputs.size() > 1 ? " (worst input)" : "") << "'\n"
     << "set grid xtics ytics mxtics mytics lc rgb '#e0e0e0'\nset key outside right top\n";
  for (const auto& [method, points] : lines) {
    std::vector<SpecSummary> sorted = points;
    std::sort(sorted.begin(), sorted.end(), [](const SpecSummary& a, const SpecSummary& b) { return a.samples < b.samples; });
    gp << "$m" << static_cast<int>(method) << " << EOD\n";
    for (const SpecSummary& s : sorted) gp << number(s.time_ms) << " " << number(s.err_max_pct) << "\n";
    gp << "EOD\n";
  }
  if (!front.empty()) {
    gp << "$front << EOD\n";
    for (const SpecSummary& s : front) gp << number(s.time_ms) << " " << number(s.err_max_pct) << "\n";
    // The staircase runs on to exact, where the error drops to 0.
    if (exact != nullptr) gp << number(exact->time_ms) << " " << number(front.back().err_max_pct) << "\n";
    gp << "EOD\n";
  }
  if (exact != nullptr) {
    gp << "set arrow 1 from " << number(exact->time_ms) << ", graph 0 to " << number(exact->time_ms)
       << ", graph 1 nohead dt 2 lw 2 lc rgb '#000000'\n"
       << "set label 1 'exact (error 0)' at " << number(exact->time_ms) << ", graph 0.97 left offset 0.5,0\n";
  }
  // The front first, as a wide grey band, so the method lines stay readable on top of it.
  std::string plot = front.empty() ? "plot" : "plot $front using 1:2 with steps lw 8 lc rgb '#c8c8c8' title 'Pareto front'";
  for (const auto& [method, points] : lines) {
    plot += (plot == "plot" ? " " : ", ") + std::string("$m") + std::to_string(static_cast<int>(method)) +
            " using 1:2 with linespoints lw 2 pt 7 ps 0.8 lc rgb '" +
            kColours[static_cast<int>(method) % std::size(kColours)] + "' title " + quoted(family_name(method));
  }
  gp << plot << "\n"
     << "set terminal svg size 1200,800 font 'sans,11' noenhanced background rgb 'white'\n"
     << "set output " << quoted(svg.string()) << "\nreplot\nunset output\n";
  return gp.str();
}

io::IoStatus write_plot(const std::vector<StudyRecord>& records, const std::string& prefix) {
  const fs::path png = prefix + ".png", svg = prefix + ".svg";
  const std::vector<SpecSummary> summaries = summarize(records);
  if (std::none_of(summaries.begin(), summaries.end(), plottable))
    return io::IoStatus::error(io::IoErrc::InvalidArgument, png, "nothing to plot: no method has an error above 0");
  const std::string tag = ".tmp." + std::to_string(::getpid());
  const fs::path png_tmp = png.string() + tag, svg_tmp = svg.string() + tag;
  const fs::path script = prefix + ".gp" + tag, errors = prefix + ".gnuplot-errors" + tag;
  {
    std::ofstream out(script);
    out << plot_script(records, png_tmp, svg_tmp);
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
