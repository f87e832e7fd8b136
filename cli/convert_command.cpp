#include "convert_command.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <system_error>

#include "enum_option.h"
#include "report.h"
#include "shpack/io/atomic_write.h"
#include "shpack/io/convert.h"
#include "shpack/io/json_writer.h"
#include "validators.h"

namespace shpack::cli {
namespace {

namespace fs = std::filesystem;

// The io messages state the facts; the remedy is a command-line matter, so it is added here.
std::string with_remedy(const io::IoStatus& st) {
  switch (st.code) {
    case io::IoErrc::NonFiniteTexel: return st.message + "; use --nonfinite=zero to replace them";
    case io::IoErrc::UnknownLayout: return st.message + "; pass --layout equirect if it is one";
    default: return st.message;
  }
}

// Converts one input; writes `output`, or stdout when it is empty. Reports its own error.
bool convert_one(const fs::path& input, const fs::path& output, const io::ConvertSettings& settings) {
  io::ShDocument doc;
  if (io::IoStatus st = io::convert_env_map(input, settings, doc); !st.ok()) {
    report_error(with_remedy(st));
    return false;
  }
  const std::string json = io::to_json(doc);
  if (output.empty()) {
    std::cout << json << std::flush;
    if (!std::cout) report_error("stdout: cannot write the JSON");
    return static_cast<bool>(std::cout);
  }
  if (io::IoStatus st = io::write_file_atomically(output, json); !st.ok()) {
    report_error(st.message);
    return false;
  }
  return true;
}

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);  // false (with ec set) when either does not exist
}

// Input -> output pairs, or a usage problem. One output per input, never an input.
struct Plan {
  std::vector<std::pair<fs::path, fs::path>> jobs;
  std::string problem;
};

Plan plan_outputs(const ConvertOptions& options) {
  Plan plan;
  if (options.out_dir.empty() && options.inputs.size() > 1) {
    plan.problem = "convert: several inputs need --out-dir DIR";
    return plan;
  }
  std::map<fs::path, fs::path> input_of_output;
  for (const std::string& input : options.inputs) {
    const fs::path output = options.out_dir.empty()
                                ? fs::path(options.output)
                                : fs::path(options.out_dir) / fs::path(input).stem().concat(".json");
    if (!output.empty()) {
      if (const auto [it, fresh] = input_of_output.emplace(output, input); !fresh) {
        plan.problem = "convert: " + it->second.string() + " and " + input + " would both write " +
                       output.string();
        return plan;
      }
      if (same_file(input, output)) {
        plan.problem = "convert: " + input + " is both the input and the output";
        return plan;
      }
    }
    plan.jobs.emplace_back(input, output);
  }
  return plan;
}

}  // namespace

CLI::App* add_convert_command(CLI::App& app, ConvertOptions& options) {
  CLI::App* cmd = app.add_subcommand("convert", "Environment maps to Unity L2 SH (JSON)");
  cmd->add_option("inputs", options.inputs, "Environment map files (EXR, HDR, PFM, PNG, ...)")
      ->required();
  CLI::Option* output = cmd->add_option("-o,--output", options.output,
                                        "Output JSON file (default: stdout)");
  cmd->add_option("--out-dir", options.out_dir, "Write DIR/<stem>.json for each input")
      ->excludes(output);
  add_enum_option(*cmd, "--layout", options.layout,
                  {{"auto", io::Layout::Auto}, {"equirect", io::Layout::Equirect}},
                  "Image layout; auto: 2:1 is equirect, 1x1 uniform (default auto)");
  add_enum_option(*cmd, "--method", options.method,
                  {{"exact", Method::Exact}, {"center", Method::Center}},
                  "Projection method (default exact)");
  add_enum_option(*cmd, "--nonfinite", options.nonfinite,
                  {{"error", NonFinite::Error}, {"zero", NonFinite::Zero}},
                  "NaN/Inf texels: fail, or count them as 0 (default error)");
  add_enum_option(*cmd, "--negative", options.negative,
                  {{"keep", Negative::Keep}, {"clamp", Negative::Clamp}},
                  "Negative texels: keep them, or count them as 0 (default keep)");
  cmd->add_option("--intensity", options.intensity, "Multiply the radiance by K (default 1)")
      ->check(non_negative_finite_number());
  cmd->add_option("--exposure", options.exposure, "Multiply the radiance by 2^EV (default 0)")
      ->check(finite_number());
  cmd->add_option("--rotate", options.rotate_deg,
                  "Yaw about +Y in degrees, as Skybox/Panoramic's _Rotation (default 0)")
      ->check(finite_number());
  cmd->add_option("--window", options.window,
                  "Deringing: none, hanning:W, lanczos:W, unity or sloan (default none)")
      ->check([](const std::string& text) {
        Window window;
        const Status st = parse_window(text, window);
        return st.ok() ? std::string() : std::string(st.what);
      });
  cmd->add_option("--threads", options.threads, "Worker threads (default 0: all cores)");
  return cmd;
}

int run_convert(const ConvertOptions& options) {
  const double factor = options.intensity * std::exp2(options.exposure);
  if (!std::isfinite(factor)) {
    report_error("convert: --intensity times 2^--exposure is not a finite number");
    return kExitUsage;
  }
  const Plan plan = plan_outputs(options);
  if (!plan.problem.empty()) {
    report_error(plan.problem);
    return kExitUsage;
  }
  if (!options.out_dir.empty()) {
    std::error_code ec;
    fs::create_directories(options.out_dir, ec);
    if (ec) {
      report_error(options.out_dir + ": cannot create the folder: " + ec.message());
      return kExitFailure;
    }
  }

  io::ConvertSettings settings;
  settings.env_map.layout = options.layout;
  settings.env_map.project = {options.method, options.nonfinite, options.negative, options.threads};
  settings.intensity = factor;
  settings.rotate_deg = options.rotate_deg;
  if (!parse_window(options.window, settings.window).ok()) return kExitUsage;  // checked by CLI11
  bool all_ok = true;
  for (const auto& [input, output] : plan.jobs) all_ok = convert_one(input, output, settings) && all_ok;
  return all_ok ? kExitOk : kExitFailure;
}

}  // namespace shpack::cli
