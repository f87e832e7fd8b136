// shpack: HDR environment maps to Unity L2 spherical harmonics. Each subcommand lives in
// its own file; main only wires them to CLI11 and maps usage errors to exit code 2, each
// one line that names the help of the command it is in.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "bake_command.h"
#include "bench_command.h"
#include "command_names.h"
#include "convert_command.h"
#include "eval_command.h"
#include "irradiance_command.h"
#include "merge_command.h"
#include "preview_command.h"
#include "report.h"
#include "shpack/io/version.h"

namespace {

using namespace shpack::cli;

// "convrt": not a command of `app`; suggests the nearest. Empty if `word` is one.
std::string unknown_command(const CLI::App& app, const std::string& word) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (sub->get_name() == word) return {};
    names.push_back(sub->get_name());
  }
  const std::string nearest = nearest_name(word, names);
  std::string line = "'" + word + "' is not a command";
  if (!nearest.empty()) line += "; did you mean '" + nearest + "'?";
  return line;
}

// The command a usage error is in ("convert"), or "" before any.
std::string parsed_command(const CLI::App& app) {
  std::string command;
  for (const CLI::App* sub : app.get_subcommands()) command += (command.empty() ? "" : " ") + sub->get_name();
  return command;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string version = std::string("shpack ") + shpack::io::shpack_version();
  CLI::App app{"shpack: HDR environment maps to Unity L2 spherical harmonics", "shpack"};
  app.set_version_flag("--version", version);
  app.require_subcommand(1);

  ConvertOptions convert;
  EvalOptions eval;
  BenchOptions bench;
  PreviewOptions preview;
  BakeCommandOptions bake;
  IrradianceOptions irradiance;
  MergeOptions merge;
  const CLI::App* convert_app = add_convert_command(app, convert);
  const CLI::App* eval_app = add_eval_command(app, eval);
  add_bench_command(app, bench);
  const CLI::App* preview_app = add_preview_command(app, preview);
  const CLI::App* bake_app = add_bake_command(app, bake);
  const CLI::App* irradiance_app = add_irradiance_command(app, irradiance);
  const CLI::App* merge_app = add_merge_command(app, merge);
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) sub->set_version_flag("--version", version);

  if (argc > 1 && argv[1][0] != '-') {
    if (const std::string problem = unknown_command(app, argv[1]); !problem.empty()) {
      report_usage_error("", problem);
      return kExitUsage;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {  // one line, naming the help of the command it is in
    report_usage_error(parsed_command(app), e.what());
    return kExitUsage;
  }
  if (convert_app->parsed()) return run_convert(convert);
  if (preview_app->parsed()) return run_preview(preview);
  if (bake_app->parsed()) return run_bake(bake);
  if (irradiance_app->parsed()) return run_irradiance(irradiance);
  if (merge_app->parsed()) return run_merge(merge);
  return eval_app->parsed() ? run_eval(eval) : run_bench(bench);
}
