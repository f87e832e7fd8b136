// view_error_report.cpp - the reports of the view-error study (view_error_study.h).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "shpack/study/draws.h"
#include "shpack/study/gnuplot.h"
#include "shpack/study/view_error_study.h"

namespace shpack::study {
namespace {

constexpr double kGoalPct = 5.0;  // the goal's bound on the max error (docs/accuracy.md)
constexpr const char* kGoalConfig = "extract-lights 4, window optimal";

std::string fixed(double v, int digits) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, v);
  return text;
}

// The inputs and configurations in the order they first appear, and each record by both.
struct Grid {
  std::vector<std::string> inputs, configs;
  std::map<std::pair<std::string, std::string>, const ViewErrorRecord*> at;
};

Grid grid_of(const std::vector<ViewErrorRecord>& records) {
  Grid g;
  for (const ViewErrorRecord& r : records) {
    if (std::find(g.inputs.begin(), g.inputs.end(), r.input) == g.inputs.end()) g.inputs.push_back(r.input);
    if (std::find(g.configs.begin(), g.configs.end(), r.config) == g.configs.end()) g.configs.push_back(r.config);
    g.at[{r.input, r.config}] = &r;
  }
  return g;
}

// One table: a row per input of `value` (with the lights count where lights were taken out),
// then the worst input.
void table(std::ostringstream& md, const Grid& g, const char* what, double (*value)(const ViewErrorRecord&)) {
  md << "| " << what;
  for (const std::string& c : g.configs) md << " | " << c;
  md << " |\n|---";
  for (std::size_t k = 0; k < g.configs.size(); ++k) md << "|---:";
  md << "|\n";
  std::vector<double> worst(g.configs.size(), 0.0);
  for (const std::string& input : g.inputs) {
    md << "| " << input;
    for (std::size_t k = 0; k < g.configs.size(); ++k) {
      const auto it = g.at.find({input, g.configs[k]});
      if (it == g.at.end()) {
        md << " | -";
        continue;
      }
      const ViewErrorRecord& r = *it->second;
      worst[k] = std::max(worst[k], value(r));
      md << " | " << fixed(value(r), 1);
      if (r.config.rfind("extract", 0) == 0) md << " [" << r.lights << "]";
    }
    md << " |\n";
  }
  md << "| **worst**";
  for (double w : worst) md << " | **" << fixed(w, 1) << "**";
  md << " |\n";
}

}  // namespace

std::string view_error_markdown(const std::vector<ViewErrorRecord>& records) {
  const Grid g = grid_of(records);
  std::ostringstream md;
  md << "Max |error| of what Unity shows (ShadeSH9 + extracted lights) against the exact E/pi, % of the mean "
        "E/pi, worst channel: the max at 512 directions, at 1024 others when lights are shown, and "
        "searched for between them (view_error.h); [n]: lights taken out\n\n";
  table(md, g, "max %", [](const ViewErrorRecord& r) { return r.error.max_pct; });
  md << "\nRMS error, % of the mean E/pi, worst channel, over the 512 directions\n\n";
  table(md, g, "rms %", [](const ViewErrorRecord& r) { return r.error.rms_pct; });
  md << "\nEach error is within the bound of the error against the exact E/pi (largest bound: ";
  double bound = 0;
  for (const ViewErrorRecord& r : records) bound = std::max(bound, r.error.bound_pct);
  md << fixed(bound, 2) << " %).\n\nTime of the whole conversion, ms (median over the inputs, one thread)\n\n| ";
  for (const std::string& c : g.configs) md << " | " << c;
  md << " |\n|---";
  for (std::size_t k = 0; k < g.configs.size(); ++k) md << "|---:";
  md << "|\n| ms";
  for (const std::string& c : g.configs) {
    std::vector<double> ms;
    for (const ViewErrorRecord& r : records)
      if (r.config == c) ms.push_back(r.time_ms_median);
    md << " | " << fixed(median(ms), 1);
  }
  md << " |\n\n";
  std::size_t met = 0, measured = 0;
  for (const ViewErrorRecord& r : records)
    if (r.config == kGoalConfig) {
      ++measured;
      if (r.error.max_pct <= kGoalPct && r.min_e_over_pi_pct >= 0) ++met;
    }
  md << "Goal (" << kGoalConfig << ": max error <= " << fixed(kGoalPct, 0) << " %, E/pi never negative): met on "
     << met << " of " << measured << " inputs\n";
  return md.str();
}

std::string view_error_json(const std::vector<ViewErrorRecord>& records) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const ViewErrorRecord& r : records)
    out.push_back({{"input", r.input},
                   {"config", r.config},
                   {"max_pct", r.error.max_pct},
                   {"rms_pct", r.error.rms_pct},
                   {"bound_pct", r.error.bound_pct},
                   {"min_e_over_pi_pct", r.min_e_over_pi_pct},
                   {"lights", r.lights},
                   {"time_ms_median", r.time_ms_median},
                   {"time_ms_min", r.time_ms_min},
                   {"time_ms_max", r.time_ms_max}});
  return out.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

io::IoStatus write_view_error_plot(const std::vector<ViewErrorRecord>& records, const std::string& prefix) {
  if (records.empty()) return io::IoStatus::error(io::IoErrc::InvalidArgument, prefix + ".png", "nothing to plot");
  const Grid g = grid_of(records);
  return run_gnuplot(prefix, [&](const std::filesystem::path& png, const std::filesystem::path& svg) {
    std::ostringstream gp;
    gp << "set terminal pngcairo size 1200,700 font 'sans,11' noenhanced\nset output " << gnuplot_quoted(png.string())
       << "\nset title 'What Unity shows against the exact E/pi of the map'\n"
       << "set ylabel 'max error, % of the mean E/pi (worst channel)'\nset yrange [0:*]\n"
       << "set xtics rotate by -35 nomirror\nset grid ytics lc rgb '#e0e0e0'\nset key outside right top\n"
       << "set xrange [-0.5:" << g.configs.size() - 0.5 << "]\nset xtics (";
    for (std::size_t k = 0; k < g.configs.size(); ++k) gp << (k ? ", " : "") << gnuplot_quoted(g.configs[k]) << " " << k;
    gp << ")\nset arrow 1 from graph 0, first " << fixed(kGoalPct, 1) << " to graph 1, first " << fixed(kGoalPct, 1)
       << " nohead dt 2 lw 2 lc rgb '#000000'\n"
       << "set label 2 'goal' at graph 0.005, first " << fixed(kGoalPct, 1) << " offset 0,0.7\n";
    for (std::size_t i = 0; i < g.inputs.size(); ++i) {
      gp << "$i" << i << " << EOD\n";
      for (std::size_t k = 0; k < g.configs.size(); ++k)
        if (const auto it = g.at.find({g.inputs[i], g.configs[k]}); it != g.at.end())
          gp << k << " " << gnuplot_number(it->second->error.max_pct) << "\n";
      gp << "EOD\n";
    }
    gp << "plot ";
    for (std::size_t i = 0; i < g.inputs.size(); ++i)
      gp << (i ? ", " : "") << "$i" << i << " using 1:2 with linespoints lw 2 pt 7 title "
         << gnuplot_quoted(std::filesystem::path(g.inputs[i]).stem().string());
    gp << "\nset terminal svg size 1200,700 font 'sans,11' noenhanced background rgb 'white'\n"
       << "set output " << gnuplot_quoted(svg.string()) << "\nreplot\nunset output\n";
    return gp.str();
  });
}

}  // namespace shpack::study
