#include "shpack/study/plot.h"

#include <algorithm>
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

// False for NaN, and for an error of 0, which a log axis cannot show.
bool plottable(const SpecSummary& s) {
  return s.spec.method != SamplingMethod::Exact && s.expected_err_rms_pct > 0 && s.time_ms > 0;
}

bool sampled(const SpecSummary& s) { return s.err_rms_kind == error_kind_name(ErrorKind::Sampled); }

// The legend says how each line's error was obtained (expected_error.h).
std::string line_title(SamplingMethod method, const SpecSummary& first) {
  std::string title = family_name(method);
  if (sampled(first)) title += " (sampled)";
  else if (uses_seed(method)) title += " (closed form)";
  return title;
}

// A method's rows, by samples: time, expected error, its band (the draws' 95% interval when
// sampled, else the error itself), the draws' RMS error.
void data_block(SamplingMethod method, std::vector<SpecSummary> points, std::ostringstream& gp) {
  std::sort(points.begin(), points.end(), [](const SpecSummary& a, const SpecSummary& b) { return a.samples < b.samples; });
  gp << "$m" << static_cast<int>(method) << " << EOD\n";
  for (const SpecSummary& s : points) {
    const Interval band = sampled(s) ? s.err_rms_interval : Interval{s.expected_err_rms_pct, s.expected_err_rms_pct};
    gp << gnuplot_number(s.time_ms) << " " << gnuplot_number(s.expected_err_rms_pct) << " " << gnuplot_number(band.low)
       << " " << gnuplot_number(band.high) << " " << gnuplot_number(s.err_rms_pct) << "\n";
  }
  gp << "EOD\n";
}

void add_clause(std::string& plot, const std::string& clause) { plot.append(plot == "plot" ? " " : ", ").append(clause); }

}  // namespace

std::string plot_script(const std::vector<StudyRecord>& records, const fs::path& png, const fs::path& svg) {
  const std::vector<SpecSummary> summaries = summarize(records);
  std::map<SamplingMethod, std::vector<SpecSummary>> lines;
  const SpecSummary* exact = nullptr;
  for (const SpecSummary& s : summaries) {
    if (s.spec.method == SamplingMethod::Exact) exact = &s;
    else if (plottable(s)) lines[s.spec.method].push_back(s);
  }
  const std::string front = gnuplot_front_rows(expected_error_front(records));

  std::set<std::string> inputs;
  for (const StudyRecord& r : records) inputs.insert(r.input);
  const bool several = inputs.size() > 1;
  std::string title = several ? std::to_string(inputs.size()) + " inputs" : *inputs.begin();
  title += ": expected RMS error of E/pi against time";
  // The title's second line says how each curve was obtained; a single-quoted gnuplot string
  // takes no escapes, so the line break is a double-quoted one between two of them.
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1200,800 font 'sans,11' noenhanced\n"
     << "set output " << gnuplot_quoted(png.string()) << "\n"
     << "set title " << gnuplot_quoted(title) << ".\"\\n\"."
     << gnuplot_quoted("mc, is: closed form; qmc: sampled, dashed, band its 95 % interval; "
                       "open points: the draws' RMS; grey: Pareto front")
     << "\nset logscale xy\nset format x '%g'\nset format y '%g'\n"
     << "set xlabel 'time per projection, ms (median" << (several ? " over the inputs" : "") << ")'\n"
     << "set ylabel 'expected RMS error of E/pi, % of its mean" << (several ? " (median over the inputs)" : "")
     << "'\nset grid xtics ytics mxtics mytics lc rgb '#e0e0e0'\nset key outside right top\n";
  for (const auto& [method, points] : lines) data_block(method, points, gp);
  if (!front.empty()) gp << "$front << EOD\n" << front << "EOD\n";
  if (exact != nullptr) {
    gp << "set arrow 1 from " << gnuplot_number(exact->time_ms) << ", graph 0 to " << gnuplot_number(exact->time_ms)
       << ", graph 1 nohead dt 2 lw 2 lc rgb '#000000'\n"
       << "set label 1 'exact (error 0)' at " << gnuplot_number(exact->time_ms) << ", graph 0.97 left offset 0.5,0\n";
  }
  // The front first, as a wide grey band, so the method lines stay readable on top of it.
  std::string plot = "plot";
  if (!front.empty()) add_clause(plot, "$front using 1:2 with steps lw 8 lc rgb '#c8c8c8' title 'Pareto front'");
  for (const auto& [method, points] : lines) {
    const std::string block = "$m" + std::to_string(static_cast<int>(method));
    const std::string rgb = std::string("rgb '") + kColours[static_cast<int>(method) % std::size(kColours)] + "'";
    const std::string colour = "lc " + rgb;
    const bool is_sampled = sampled(points.front());
    if (is_sampled)  // its band under its line, see-through
      add_clause(plot, block + " using 1:3:4 with filledcurves fc " + rgb + " fs transparent solid 0.2 noborder notitle");
    add_clause(plot, block + " using 1:2 with linespoints lw 2 pt 7 ps 0.8 " + (is_sampled ? "dt 2 " : "") + colour +
                         " title " + gnuplot_quoted(line_title(method, points.front())));
    if (points.front().seeds > 1) add_clause(plot, block + " using 1:5 with points pt 6 ps 1.2 " + colour + " notitle");
  }
  gp << plot << "\n"
     << "set terminal svg size 1200,800 font 'sans,11' noenhanced background rgb 'white'\n"
     << "set output " << gnuplot_quoted(svg.string()) << "\nreplot\nunset output\n";
  return gp.str();
}

io::IoStatus write_plot(const std::vector<StudyRecord>& records, const std::string& prefix) {
  const std::vector<SpecSummary> summaries = summarize(records);
  if (std::none_of(summaries.begin(), summaries.end(), plottable))
    return io::IoStatus::error(io::IoErrc::InvalidArgument, prefix + ".png",
                               "nothing to plot: no method has an expected error above 0");
  return run_gnuplot(prefix, [&](const fs::path& png, const fs::path& svg) { return plot_script(records, png, svg); });
}

}  // namespace shpack::study
