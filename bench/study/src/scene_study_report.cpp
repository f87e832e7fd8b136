// The scene study's reports (scene_study.h): a markdown table, a JSON array, a plot script.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "shpack/study/gnuplot.h"
#include "shpack/study/scene_study.h"

namespace shpack::study {

std::string scene_markdown_report(const std::vector<SceneStudyRecord>& records) {
  std::ostringstream md;
  md << "| scene | receivers | effect | estimator | samples/receiver | CPU ms (median) | max error % (RMS over seeds) "
        "| worst seed % | error estimate % | reference's estimate % | seeds | receivers/s |\n"
        "|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const SceneStudyRecord& r : records) {
    char line[640];
    std::snprintf(line, sizeof line, "| %s | %zu %s | %s | %s | %.0f | %.3g | %.3g | %.3g | %.3g | %.3g | %u | %.3g |\n",
                  r.scene.c_str(), r.count, r.receivers.c_str(), r.effect.c_str(), r.estimator.c_str(), r.samples,
                  r.cpu_ms, r.err_max_pct, r.err_worst_pct, r.estimate_pct, r.reference_estimate_pct, r.seeds, r.per_s);
    md << line;
  }
  return md.str();
}

std::string scene_json_report(const std::vector<SceneStudyRecord>& records) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const SceneStudyRecord& r : records)
    out.push_back({{"scene", r.scene}, {"receivers", r.receivers}, {"count", r.count}, {"effect", r.effect},
                   {"estimator", r.estimator}, {"samples", r.samples}, {"seeds", r.seeds}, {"cpu_ms", r.cpu_ms},
                   {"err_max_pct", r.err_max_pct}, {"err_worst_pct", r.err_worst_pct},
                   {"error_estimate_pct", r.estimate_pct}, {"reference_estimate_pct", r.reference_estimate_pct},
                   {"receivers_per_s", r.per_s}});
  return out.dump(2) + "\n";
}

std::string scene_plot_script(const std::vector<SceneStudyRecord>& records, const std::filesystem::path& png,
                              const std::filesystem::path& svg) {
  // One panel per (scene, receivers, effect) in the records' order, for those with an error to
  // plot (an effect exact at every receiver has none: log axes cannot show 0).
  const auto plottable = [](const SceneStudyRecord& r) { return r.cpu_ms > 0 && r.err_max_pct > 0; };
  using Panel = std::array<std::string, 3>;  // scene, receivers, effect
  const auto panel_of = [](const SceneStudyRecord& r) { return Panel{r.scene, r.receivers, r.effect}; };
  std::vector<Panel> effects;
  for (const SceneStudyRecord& r : records)
    if (plottable(r) && std::find(effects.begin(), effects.end(), panel_of(r)) == effects.end())
      effects.push_back(panel_of(r));
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
     << "set ylabel 'max error of E/pi, worst probe or texel (%)'\n"
     << "set multiplot layout " << std::max<std::size_t>(1, rows) << "," << cols << "\n";
  for (const Panel& panel : effects) {
    gp << "set title " << gnuplot_quoted(panel[0] + ", " + panel[1] + ": " + panel[2]) << "\nplot ";
    bool first = true;
    for (const auto& [estimator, look] : style) {
      std::ostringstream data;
      for (const SceneStudyRecord& r : records)
        if (panel_of(r) == panel && r.estimator == estimator && plottable(r))
          data << gnuplot_number(r.cpu_ms) << " " << gnuplot_number(r.err_max_pct) << "\n";
      if (data.str().empty()) continue;
      gp << (first ? "" : ", ") << "'-' with " << (estimator == "settings" ? "points" : "linespoints") << " " << look
         << " title " << gnuplot_quoted(estimator);
      first = false;
    }
    gp << "\n";
    for (const auto& [estimator, look] : style) {
      std::ostringstream data;
      for (const SceneStudyRecord& r : records)
        if (panel_of(r) == panel && r.estimator == estimator && plottable(r))
          data << gnuplot_number(r.cpu_ms) << " " << gnuplot_number(r.err_max_pct) << "\n";
      if (!data.str().empty()) gp << data.str() << "e\n";
    }
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
