// shpack: HDR environment maps to Unity L2 spherical harmonics. Each subcommand lives in
// its own file; main only wires them to CLI11 and maps parse errors to exit code 2.
#include <CLI/CLI.hpp>

#include <string>

#include "bake_command.h"
#include "bench_command.h"
#include "convert_command.h"
#include "eval_command.h"
#include "preview_command.h"
#include "report.h"
#include "shpack/io/version.h"

int main(int argc, char** argv) {
  using namespace shpack::cli;
  CLI::App app{"shpack: HDR environment maps to Unity L2 spherical harmonics", "shpack"};
  app.set_version_flag("--version", std::string("shpack ") + shpack::io::shpack_version());
  // Set before the subcommands are added, which copy it: every usage error is one line.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("shpack: ") + e.what() + " (see shpack --help)\n";
  });
  app.require_subcommand(1);

  ConvertOptions convert;
  EvalOptions eval;
  BenchOptions bench;
  PreviewOptions preview;
  BakeCommandOptions bake;
  const CLI::App* convert_app = add_convert_command(app, convert);
  const CLI::App* eval_app = add_eval_command(app, eval);
  add_bench_command(app, bench);
  const CLI::App* preview_app = add_preview_command(app, preview);
  const CLI::App* bake_app = add_bake_command(app, bake);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  }
  if (convert_app->parsed()) return run_convert(convert);
  if (preview_app->parsed()) return run_preview(preview);
  if (bake_app->parsed()) return run_bake(bake);
  return eval_app->parsed() ? run_eval(eval) : run_bench(bench);
}
