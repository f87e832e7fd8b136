#include "shpack/study/study_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <limits>
#include <map>
#include <thread>

#include "shpack/study/draws.h"
#include "shpack/study/method_sweep.h"

namespace shpack::study {
namespace {

namespace fs = std::filesystem;
using OrderedJson = nlohmann::ordered_json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string spec_name(const MethodSpec& spec) { return std::string(method_name(spec).view()); }

// Three significant digits: what a timing on a shared machine or an error estimate is worth.
std::string fmt(double v) {
  if (std::isnan(v)) return "n/a";
  if (v == 0) return "0";
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

std::string fmt_count(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", v);
  return text;
}

// Median of the non-NaN values; NaN if there are none.
double median_of(std::vector<double> values) {
  std::erase_if(values, [](double v) { return std::isnan(v); });
  return median(std::move(values));
}

double max_of(const std::vector<double>& values) {
  double worst = kNaN;
  for (const double v : values)
    if (!std::isnan(v) && !(v <= worst)) worst = v;
  return worst;
}

std::vector<std::string> inputs_in_order(const std::vector<StudyRecord>& records) {
  std::vector<std::string> inputs;
  for (const StudyRecord& r : records)
    if (std::find(inputs.begin(), inputs.end(), r.input) == inputs.end()) inputs.push_back(r.input);
  return inputs;
}

// The 1-minute load averages over the runs of `input` (every input if empty), lowest to
// highest: how shared the cores were while the projections were timed.
std::string load_note(const std::vector<StudyRecord>& records, const std::string& input) {
  double low = kNaN, high = kNaN;
  for (const StudyRecord& r : records) {
    const double load = r.load_average[0];
    if ((!input.empty() && r.input != input) || std::isnan(load)) continue;
    if (!(load >= low)) low = load;
    if (!(load <= high)) high = load;
  }
  if (std::isnan(low)) return "Load average: not available.";
  return "Load average (1 min, /proc/loadavg) while timed: " + fmt(low) + (high > low ? " to " + fmt(high) : "") +
         " on " + std::to_string(std::max(1u, std::thread::hardware_concurrency())) + " cores.";
}

// "[p10, p90]" of a random method's draws; "-" for one draw. Built piece by piece: g++ 12
// at -O3 warns falsely (-Wrestrict) on the chain of operator+ from a literal.
std::string fmt_spread(unsigned seeds, const Spread& s) {
  if (seeds <= 1) return "-";
  std::string text = "[";
  text += fmt(s.p10);
  text += ", ";
  text += fmt(s.p90);
  text += "]";
  return text;
}

constexpr const char* kDrawsNote =
    "Random methods (mc, qmc, is): the draws' errors are RMS over `seeds` draws, [p10, p90] the 10th "
    "and 90th percentiles of the draws; the expected error is not drawn for mc and is (their closed form).";

void summary_section(const std::vector<StudyRecord>& records, std::size_t input_count, std::string& md) {
  md += "## All " + std::to_string(input_count) + " inputs\n\n";
  md += "Time: median over the inputs. Expected RMS error of E/pi in % of its mean (its kind: exact "
        "or sampled, expected_error.h): median input. Errors of the draws: worst input (max, with the "
        "spread of its draws), median input (rms). Coefficient error: worst input, relative to L00. ";
  md += kDrawsNote;
  md += " ";
  md += load_note(records, "");
  md += "\n\n| method | samples | seeds | time ms | expected err rms % | kind | err max % | p10, p90 | err rms % "
        "| coef err max |\n";
  md += "|---|---:|---:|---:|---:|---|---:|---:|---:|---:|\n";
  for (const SpecSummary& s : summarize(records)) {
    md += "| " + spec_name(s.spec) + " | " + fmt_count(s.samples) + " | " + std::to_string(s.seeds) + " | " +
          fmt(s.time_ms) + " | " + fmt(s.expected_err_rms_pct) + " | " + s.err_rms_kind + " | " + fmt(s.err_max_pct) +
          " | " + fmt_spread(s.seeds, s.err_max_spread) + " | " + fmt(s.err_rms_pct) + " | " + fmt(s.coef_err_max) +
          " |\n";
  }
  md += "\n";
}

// One row per method: the median slope, then the slope on each input (its file stem).
void convergence_section(const std::vector<StudyRecord>& records, std::string& md) {
  const std::vector<ConvergenceFit> fits = convergence_fits(records);
  if (fits.empty()) return;
  const std::vector<std::string> inputs = inputs_in_order(records);
  std::map<SamplingMethod, std::map<std::string, double>> slope;  // method -> input -> slope
  for (const ConvergenceFit& fit : fits) slope[fit.method][fit.input] = fit.slope;
  md += "## Convergence\n\n";
  md += "Slope of log(expected err rms) against log(samples), fitted per input over the runs with an "
        "error above 0 (mc and is: the closed form from their variance, exactly -0.5; qmc: the RMS over "
        "its draws; the others: their one error): -0.5 is N^-1/2 (Monte Carlo), -1 is h^2 on a 2-D "
        "grid.\n\n";
  md += "| method | median |";
  for (const std::string& input : inputs) md.append(" ").append(fs::path(input).stem().string()).append(" |");
  md += "\n|---|---:|";
  for (std::size_t i = 0; i < inputs.size(); ++i) md += "---:|";
  md += "\n";
  for (const auto& [method, by_input] : slope) {
    std::vector<double> values;
    for (const auto& [input, s] : by_input) values.push_back(s);
    md += "| " + family_name(method) + " | " + fmt(median_of(values)) + " |";
    for (const std::string& input : inputs) {
      const auto it = by_input.find(input);
      md.append(" ").append(it == by_input.end() ? std::string("n/a") : fmt(it->second)).append(" |");
    }
    md += "\n";
  }
  md += "\n";
}

// One row per point of the front: the least expected RMS error a time budget buys.
void front_table(const std::vector<FrontPoint>& front, std::string& md) {
  md += "| at ms | method | expected err rms % | kind |\n|---:|---|---:|---|\n";
  for (const FrontPoint& p : front)
    md.append("| ").append(fmt(p.time_ms)).append(" | ").append(p.spec).append(" | ").append(fmt(p.err_pct))
        .append(" | ").append(p.kind).append(" |\n");
  md += "\n";
}

void front_section(const std::vector<StudyRecord>& records, const std::vector<std::string>& inputs,
                   std::string& md) {
  md += "## Pareto front\n\n";
  md += "For each time budget, the method with the least expected RMS error of E/pi (% of its mean): "
        "\"at T ms\" is the best that T ms buys, until the next row. Exact errors are closed forms or a "
        "deterministic rule's one error; sampled ones are RMS over draws (qmc).\n\n";
  if (inputs.size() > 1) {
    md += "All inputs (median time, median expected error):\n\n";
    front_table(expected_error_front(records), md);
  }
  for (const std::string& input : inputs) {
    md.append(fs::path(input).filename().string()).append(":\n\n");
    std::vector<StudyRecord> of_input;
    std::copy_if(records.begin(), records.end(), std::back_inserter(of_input),
                 [&](const StudyRecord& r) { return r.input == input; });
    front_table(expected_error_front(of_input), md);
  }
}

// "[low, high]" of the draws' 95% interval of the RMS error; "-" for one draw.
std::string fmt_interval(unsigned seeds, const Interval& i) { return fmt_spread(seeds, {i.low, i.high}); }

void input_section(const std::vector<StudyRecord>& records, const std::string& input, std::string& md) {
  const StudyRecord* first = nullptr;
  for (const StudyRecord& r : records)
    if (r.input == input && first == nullptr) first = &r;
  md += "## " + input + " (" + std::to_string(first->width) + "x" + std::to_string(first->height) + ")\n\n";
  md += load_note(records, input) + " " + kDrawsNote + "\n\n";
  md += "Expected errors: exact (a closed form or a deterministic rule's one error), bound (an upper "
        "bound: 3 x the expected RMS, for the max of mc and is), sampled (RMS over draws). Beside them "
        "the draws: their RMS, 95% interval and [p10, p90].\n\n";
  md += "| method | samples | seeds | ms median | ms min | ms max | expected err rms % | kind | expected err max % "
        "| kind | err max % | p10, p90 | err rms % | 95% interval | p10, p90 | coef err max | min E/pi |\n";
  md += "|---|---:|---:|---:|---:|---:|---:|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const StudyRecord& r : records) {
    if (r.input != input) continue;
    const AccuracyMetrics& a = r.accuracy;
    md += "| " + spec_name(r.spec) + " | " + fmt_count(r.samples) + " | " + std::to_string(r.seeds) + " | " +
          fmt(r.time_ms_median) + " | " + fmt(r.time_ms_min) + " | " + fmt(r.time_ms_max) + " | " +
          fmt(r.expected_err_rms_pct) + " | " + std::string(error_kind_name(r.err_rms_kind)) + " | " +
          fmt(r.expected_err_max_pct) + " | " + std::string(error_kind_name(r.err_max_kind)) + " | " +
          fmt(a.err_max_pct) + " | " + fmt_spread(r.seeds, r.err_max_spread) + " | " + fmt(a.err_rms_pct) + " | " +
          fmt_interval(r.seeds, r.err_rms_interval) + " | " + fmt_spread(r.seeds, r.err_rms_spread) + " | " + fmt(a.coef_err_max) + " | " + fmt(a.min_e_over_pi) + " |\n";
  }
  md += "\n";
}

}  // namespace

std::vector<SpecSummary> summarize(const std::vector<StudyRecord>& records) {
  std::vector<std::string> order;
  std::map<std::string, std::vector<const StudyRecord*>> by_spec;
  for (const StudyRecord& r : records) {
    const std::string name = spec_name(r.spec);
    if (by_spec[name].empty()) order.push_back(name);
    by_spec[name].push_back(&r);
  }
  std::vector<SpecSummary> out;
  for (const std::string& name : order) {
    const std::vector<const StudyRecord*>& runs = by_spec[name];
    std::vector<double> time, err_max, err_rms, coef, samples, expected, interval_low, interval_high;
    const StudyRecord* worst = runs.front();  // the input of the largest err_max_pct
    unsigned seeds = 1;
    for (const StudyRecord* r : runs) {
      time.push_back(r->time_ms_median);
      err_max.push_back(r->accuracy.err_max_pct);
      err_rms.push_back(r->accuracy.err_rms_pct);
      expected.push_back(r->expected_err_rms_pct);
      coef.push_back(r->accuracy.coef_err_max);
      samples.push_back(r->samples);
      interval_low.push_back(r->err_rms_interval.low);
      interval_high.push_back(r->err_rms_interval.high);
      seeds = std::max(seeds, r->seeds);
      if (r->accuracy.err_max_pct > worst->accuracy.err_max_pct || std::isnan(worst->accuracy.err_max_pct))
        worst = r;
    }
    out.push_back({runs.front()->spec, static_cast<int>(runs.size()), median_of(time), max_of(err_max),
                   median_of(err_rms), median_of(expected), std::string(error_kind_name(runs.front()->err_rms_kind)),
                   max_of(coef), median_of(samples), seeds, worst->err_max_spread,
                   {median_of(interval_low), median_of(interval_high)}});
  }
  return out;
}

std::vector<FrontPoint> expected_error_front(const std::vector<StudyRecord>& records) {
  std::vector<FrontPoint> points;
  for (const SpecSummary& s : summarize(records))
    points.push_back({spec_name(s.spec), s.time_ms, s.expected_err_rms_pct, s.err_rms_kind, s.samples});
  return pareto_front(std::move(points));
}

std::vector<ConvergenceFit> convergence_fits(const std::vector<StudyRecord>& records) {
  std::vector<ConvergenceFit> fits;
  for (const std::string& input : inputs_in_order(records)) {
    std::map<SamplingMethod, std::vector<std::pair<double, double>>> points;  // log samples, log err
    for (const StudyRecord& r : records) {
      if (r.input == input && r.expected_err_rms_pct > 0)
        points[r.spec.method].emplace_back(std::log(r.samples), std::log(r.expected_err_rms_pct));
    }
    for (const auto& [method, xy] : points) {
      if (xy.size() < 3) continue;
      double mx = 0, my = 0;
      for (const auto& [x, y] : xy) mx += x, my += y;
      mx /= xy.size(), my /= xy.size();
      double sxy = 0, sxx = 0;
      for (const auto& [x, y] : xy) sxy += (x - mx) * (y - my), sxx += (x - mx) * (x - mx);
      if (sxx > 0) fits.push_back({input, method, sxy / sxx, static_cast<int>(xy.size())});
    }
  }
  return fits;
}

std::string markdown_report(const std::vector<StudyRecord>& records) {
  const std::vector<std::string> inputs = inputs_in_order(records);
  std::string md;
  if (inputs.size() > 1) summary_section(records, inputs.size(), md);
  convergence_section(records, md);
  front_section(records, inputs, md);
  for (const std::string& input : inputs) input_section(records, input, md);
  return md;
}

std::string json_report(const std::vector<StudyRecord>& records) {
  OrderedJson array = OrderedJson::array();
  for (const StudyRecord& r : records) {
    const bool has_param = r.spec.method != SamplingMethod::Exact && r.spec.method != SamplingMethod::Center;
    OrderedJson j;
    j["input"] = r.input;
    j["width"] = r.width;
    j["height"] = r.height;
    j["method"] = family_name(r.spec.method);
    j["param"] = has_param ? OrderedJson(r.spec.param) : OrderedJson(nullptr);
    j["spec"] = spec_name(r.spec);
    j["seed"] = uses_seed(r.spec.method) ? OrderedJson(r.spec.seed) : OrderedJson(nullptr);
    j["seeds"] = r.seeds;
    j["threads"] = r.threads;
    j["repeats"] = r.repeats;
    j["samples"] = r.samples;
    j["time_ms_median"] = r.time_ms_median;
    j["time_ms_min"] = r.time_ms_min;
    j["time_ms_max"] = r.time_ms_max;
    j["err_max_pct"] = r.accuracy.err_max_pct;  // nlohmann writes NaN as null
    j["err_max_pct_p10"] = r.err_max_spread.p10;
    j["err_max_pct_p90"] = r.err_max_spread.p90;
    j["err_rms_pct"] = r.accuracy.err_rms_pct;
    j["err_rms_pct_p10"] = r.err_rms_spread.p10;
    j["err_rms_pct_p90"] = r.err_rms_spread.p90;
    j["coef_err_max"] = r.accuracy.coef_err_max;
    j["min_e_over_pi"] = r.accuracy.min_e_over_pi;
    j["load_average"] = r.load_average;
    j["expected_err_rms_pct"] = r.expected_err_rms_pct;
    j["expected_err_max_pct"] = r.expected_err_max_pct;
    j["error_kind"] = error_kind_name(r.err_rms_kind);
    j["err_max_kind"] = error_kind_name(r.err_max_kind);
    j["err_rms_pct_ci95"] = {r.err_rms_interval.low, r.err_rms_interval.high};
    j["err_max_pct_ci95"] = {r.err_max_interval.low, r.err_max_interval.high};
    array.push_back(std::move(j));
  }
  return array.dump(2, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
}

}  // namespace shpack::study
