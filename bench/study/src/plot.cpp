#include "shpack/study/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "shpack/study/gnuplot.h"
#include "shpack/study/method_sweep.h"
#include "shpack/study/study_report.h"

namespace shpack::study {
namespace {

namespace fs = std::filesystem;

// One colour per method, far enough apart to tell eleven lines apart.
constexpr const char* kColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                                    "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#393b79"};

bool plottable(const SpecSummary& s) { return s.err_max_pct > 0 && s.time_ms > 0; }  // false for NaN

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
     << "set output " << gnuplot_quoted(png.string()) << "\n"
     << "set title " << gnuplot_quoted(inputs.size() == 1 ? *inputs.begin() : std::to_string(inputs.size()) + " inputs")
     << "\nset logscale xy\nset format x '%g'\nset format y '%g'\n"
     << "set xlabel 'time per projection, ms (median" << (inputs.size() > 1 ? " over the inputs" : "") << ")'\n"
     << "set ylabel 'max error of E/pi, % of its mean" << (inputs.size() > 1 ? " (worst input)" : "")
     << "; random methods: RMS over seeds, band 10-90 %'\n"
     << "set grid xtics ytics mxtics mytics lc rgb '#e0e0e0'\nset key outside right top\n";
  for (const auto& [method, points] : lines) {
    std::vector<SpecSummary> sorted = points;
    std::sort(sorted.begin(), sorted.end(), [](const SpecSummary& a, const SpecSummary& b) { return a.samples < b.samples; });
    // time, error, and the draws' 10th and 90th percentiles (the error itself for one draw)
    gp << "$m" << static_cast<int>(method) << " << EOD\n";
    for (const SpecSummary& s : sorted)
      gp << gnuplot_number(s.time_ms) << " " << gnuplot_number(s.err_max_pct) << " " << gnuplot_number(s.err_max_spread.p10) << " "
         << gnuplot_number(s.err_max_spread.p90) << "\n";
    gp << "EOD\n";
  }
  if (!front.empty()) {
    gp << "$front << EOD\n";
    for (const SpecSummary& s : front) gp << gnuplot_number(s.time_ms) << " " << gnuplot_number(s.err_max_pct) << "\n";
    // The staircase runs on to exact, where the error drops to 0.
    if (exact != nullptr) gp << gnuplot_number(exact->time_ms) << " " << gnuplot_number(front.back().err_max_pct) << "\n";
    gp << "EOD\n";
  }
  if (exact != nullptr) {
    gp << "set arrow 1 from " << gnuplot_number(exact->time_ms) << ", graph 0 to " << gnuplot_number(exact->time_ms)
       << ", graph 1 nohead dt 2 lw 2 lc rgb '#000000'\n"
       << "set label 1 'exact (error 0)' at " << gnuplot_number(exact->time_ms) << ", graph 0.97 left offset 0.5,0\n";
  }
  // The front first, as a wide grey band, so the method lines stay readable on top of it.
  std::string plot = front.empty() ? "plot" : "plot $front using 1:2 with steps lw 8 lc rgb '#c8c8c8' title 'Pareto front'";
  // A random method's band (its draws' spread) under its line, in its colour, see-through.
  for (const auto& [method, points] : lines) {
    const std::string block = "$m" + std::to_string(static_cast<int>(method));
    const std::string colour = kColours[static_cast<int>(method) % std::size(kColours)];
    if (points.front().seeds > 1)
      plot += (plot == "plot" ? " " : ", ") + block + " using 1:3:4 with filledcurves fc rgb '" + colour +
              "' fs transparent solid 0.2 noborder notitle";
    plot += (plot == "plot" ? " " : ", ") + block + " using 1:2 with linespoints lw 2 pt 7 ps 0.8 lc rgb '" +
            colour + "' title " + gnuplot_quoted(family_name(method));
  }
  gp << plot << "\n"
     << "set terminal svg size 1200,800 font 'sans,11' noenhanced background rgb 'white'\n"
     << "set output " << gnuplot_quoted(svg.string()) << "\nreplot\nunset output\n";
  return gp.str();
}

io::IoStatus write_plot(const std::vector<StudyRecord>& records, const std::string& prefix) {
  const std::vector<SpecSummary> summaries = summarize(records);
  if (std::none_of(summaries.begin(), summaries.end(), plottable))
    return io::IoStatus::error(io::IoErrc::InvalidArgument, prefix + ".png", "nothing to plot: no method has an error above 0");
  return run_gnuplot(prefix, [&](const fs::path& png, const fs::path& svg) { return plot_script(records, png, svg); });
}

}  // namespace shpack::study
