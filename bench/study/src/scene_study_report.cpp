// The scene study's reports (scene_study.h): a markdown table, a JSON array, a plot script.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

#include "shpack/study/expected_error.h"
#include "shpack/study/gnuplot.h"
#include "shpack/study/pareto_front.h"
#include "shpack/study/scene_study.h"

namespace shpack::study {
namespace {

using Panel = std::array<std::string, 3>;  // scene, receivers, effect
Panel panel_of(const SceneStudyRecord& r) { return {r.scene, r.receivers, r.effect}; }

// The panels in the records' order, of the records `keep` accepts.
template <typename Keep>
std::vector<Panel> panels(const std::vector<SceneStudyRecord>& records, Keep keep) {
  std::vector<Panel> out;
  for (const SceneStudyRecord& r : records)
    if (keep(r) && std::find(out.begin(), out.end(), panel_of(r)) == out.end()) out.push_back(panel_of(r));
  return out;
}

// The measured error over the bake's own estimate of it: below 1 the estimate is cautious,
// above 1 optimistic. NaN when there is no estimate (an effect exact at every receiver).
double measured_over_estimate(const SceneStudyRecord& r) {
  return r.estimate_pct > 0 ? r.err_max_pct / r.estimate_pct : std::numeric_limits<double>::quiet_NaN();
}

// The Pareto front of one panel over CPU time and error (err_max_pct, RMS over the seeds),
// each point naming its record's estimator and samples.
std::vector<FrontPoint> panel_front(const std::vector<SceneStudyRecord>& records, const Panel& panel) {
  std::vector<FrontPoint> points;
  for (const SceneStudyRecord& r : records)
    if (panel_of(r) == panel)
      points.push_back({r.estimator, r.cpu_ms, r.err_max_pct, std::string(error_kind_name(ErrorKind::Sampled)), r.samples});
  return pareto_front(std::move(points));
}

bool on_front(const SceneStudyRecord& r, const std::vector<FrontPoint>& front) {
  return std::any_of(front.begin(), front.end(),
                     [&](const FrontPoint& p) { return p.spec == r.estimator && p.samples == r.samples; });
}

const SceneStudyRecord& record_of(const std::vector<SceneStudyRecord>& records, const Panel& panel, const FrontPoint& p) {
  return *std::find_if(records.begin(), records.end(), [&](const SceneStudyRecord& r) {
    return panel_of(r) == panel && r.estimator == p.spec && r.samples == p.samples;
  });
}

std::string fmt(const char* format, double v) {
  if (std::isnan(v)) return "n/a";
  char text[32];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

void records_table(const std::vector<SceneStudyRecord>& records, std::ostringstream& md) {
  md << "| scene | receivers | effect | estimator | samples/receiver | CPU ms (median) | max error % (RMS over seeds) "
        "| worst seed % | error estimate % | measured / estimate | reference's estimate % | seeds | receivers/s |\n"
        "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const SceneStudyRecord& r : records) {
    char line[640];
    std::snprintf(line, sizeof line, "| %s | %zu %s | %s | %s | %.0f | %.3g | %.3g | %.3g | %.3g | %s | %.3g | %u | %.3g |\n",
                  r.scene.c_str(), r.count, r.receivers.c_str(), r.effect.c_str(), r.estimator.c_str(), r.samples,
                  r.cpu_ms, r.err_max_pct, r.err_worst_pct, r.estimate_pct, fmt("%.3g", measured_over_estimate(r)).c_str(),
                  r.reference_estimate_pct, r.seeds, r.per_s);
    md << line;
  }
  md << "\n";
}

void front_section(const std::vector<SceneStudyRecord>& records, std::ostringstream& md) {
  md << "Pareto front of each effect: for each CPU-time budget, the estimator and samples with the least error "
        "(max error %, RMS over the seeds: sampled, the seeds column says how many); \"at T ms\" is the best that "
        "T ms buys, until the next row. measured / estimate: that error over the bake's own estimate (error "
        "estimate %, the worst receiver's, mean over the seeds); below 1 the estimate is cautious.\n\n";
  for (const Panel& panel : panels(records, [](const SceneStudyRecord&) { return true; })) {
    md << panel[0] << ", " << panel[1] << ": " << panel[2] << "\n\n"
       << "| at CPU ms | estimator | samples/receiver | error % | kind | seeds | measured / estimate |\n"
       << "|---:|---|---:|---:|---|---:|---:|\n";
    for (const FrontPoint& p : panel_front(records, panel)) {
      const SceneStudyRecord& r = record_of(records, panel, p);
      md << "| " << fmt("%.3g", p.time_ms) << " | " << p.spec << " | " << fmt("%.0f", p.samples) << " | "
         << fmt("%.3g", p.err_pct) << " | " << p.kind << " | " << r.seeds << " | "
         << fmt("%.3g", measured_over_estimate(r)) << " |\n";
    }
    md << "\n";
  }
}

}  // namespace

std::string scene_markdown_report(const std::vector<SceneStudyRecord>& records) {
  std::ostringstream md;
  records_table(records, md);
  front_section(records, md);
  return md.str();
}

std::string scene_json_report(const std::vector<SceneStudyRecord>& records) {
  std::map<Panel, std::vector<FrontPoint>> fronts;
  for (const SceneStudyRecord& r : records)
    if (!fronts.contains(panel_of(r))) fronts[panel_of(r)] = panel_front(records, panel_of(r));
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const SceneStudyRecord& r : records)
    out.push_back({{"scene", r.scene}, {"receivers", r.receivers}, {"count", r.count}, {"effect", r.effect},
                   {"estimator", r.estimator}, {"samples", r.samples}, {"seeds", r.seeds}, {"cpu_ms", r.cpu_ms},
                   {"err_max_pct", r.err_max_pct}, {"err_worst_pct", r.err_worst_pct},
                   {"error_estimate_pct", r.estimate_pct}, {"reference_estimate_pct", r.reference_estimate_pct},
                   {"receivers_per_s", r.per_s}, {"measured_over_estimate", measured_over_estimate(r)},
                   {"error_kind", error_kind_name(ErrorKind::Sampled)}, {"on_front", on_front(r, fronts[panel_of(r)])}});
  return out.dump(2) + "\n";
}

std::string scene_plot_script(const std::vector<SceneStudyRecord>& records, const std::filesystem::path& png,
                              const std::filesystem::path& svg) {
  // One panel per (scene, receivers, effect) in the records' order, for those with an error to
  // plot (an effect exact at every receiver has none: log axes cannot show 0).
  const auto plottable = [](const SceneStudyRecord& r) { return r.cpu_ms > 0 && r.err_max_pct > 0; };
  const std::vector<Panel> effects = panels(records, plottable);
  const std::map<std::string, std::string> style = {{"next-events", "lc rgb '#1f77b4' pt 7"},
                                                    {"directions", "lc rgb '#d62728' pt 5"},
                                                    {"settings", "lc rgb '#2ca02c' pt 9 ps 2"}};
  const std::size_t cols = std::min<std::size_t>(4, std::max<std::size_t>(1, effects.size()));
  const std::size_t rows = (effects.size() + cols - 1) / cols;
  const std::string size = std::to_string(440 * cols) + "," + std::to_string(380 * std::max<std::size_t>(1, rows));
  std::ostringstream gp;
  gp << "set terminal pngcairo size " << size << " font 'sans,10' noenhanced\n"
     << "set output " << gnuplot_quoted(png.string()) << "\n"
     << "set logscale xy\nset grid\nset xlabel 'CPU time of the effect (ms, all threads)'\n"
     << "set ylabel 'max error of E/pi, worst receiver, RMS over seeds (%)'\n"
     << "set multiplot layout " << std::max<std::size_t>(1, rows) << "," << cols << "\n";
  for (const Panel& panel : effects) {
    // The panel's series, each a plot clause and its inline data; the front first, as a wide
    // grey band, so the estimators' lines stay readable on top of it.
    std::vector<std::pair<std::string, std::string>> series;
    if (const std::string front = gnuplot_front_rows(panel_front(records, panel)); !front.empty())
      series.emplace_back("'-' with steps lw 8 lc rgb '#c8c8c8' title 'Pareto front'", front);
    for (const auto& [estimator, look] : style) {
      std::string data;
      for (const SceneStudyRecord& r : records)
        if (panel_of(r) == panel && r.estimator == estimator && plottable(r))
          data.append(gnuplot_number(r.cpu_ms)).append(" ").append(gnuplot_number(r.err_max_pct)).append("\n");
      if (data.empty()) continue;
      std::string clause = "'-' with ";
      clause.append(estimator == "settings" ? "points " : "linespoints ").append(look).append(" title ");
      series.emplace_back(clause.append(gnuplot_quoted(estimator)), data);
    }
    gp << "set title " << gnuplot_quoted(panel[0] + ", " + panel[1] + ": " + panel[2]) << "\nplot ";
    for (std::size_t i = 0; i < series.size(); ++i) gp << (i ? ", " : "") << series[i].first;
    gp << "\n";
    for (const auto& [clause, data] : series) gp << data << "e\n";
  }
  gp << "unset multiplot\nunset output\n";
  // The SVG: the same commands again under the svg terminal (inline data cannot be replotted).
  std::string body = gp.str();
  const std::size_t from = body.find("set logscale");
  gp << "set terminal svg size " << size << " font 'sans,10' noenhanced background rgb 'white'\n"
     << "set output " << gnuplot_quoted(svg.string()) << "\n"
     << body.substr(from);
  return gp.str();
}

}  // namespace shpack::study
