#include "eval_command.h"

#include <array>
#include <charconv>
#include <cmath>
#include <iostream>

#include "report.h"
#include "shpack/io/json_reader.h"
#include "shpack/unity_pack.h"
#include "validators.h"

namespace shpack::cli {
namespace {

std::string shortest(float value) {
  std::array<char, 32> buffer;
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return error == std::errc() ? std::string(buffer.data(), end) : std::string("?");
}

}  // namespace

CLI::App* add_eval_command(CLI::App& app, EvalOptions& options) {
  CLI::App* cmd = app.add_subcommand("eval", "Print what Unity's shader returns for a normal");
  cmd->add_option("document", options.document, "A JSON file written by shpack convert; - for stdin")
      ->type_name("FILE")
      ->required();
  cmd->add_option("--dir", options.direction, "The normal X,Y,Z in Unity's frame (+Y up)")
      ->required()
      ->delimiter(',')
      ->expected(3)
      ->option_text("X,Y,Z REQUIRED")  // not CLI11's "NUMBER x 3"
      ->check(finite_number());
  return cmd;
}

int run_eval(const EvalOptions& options) {
  const std::vector<double>& d = options.direction;
  const double length = std::hypot(d[0], d[1], d[2]);  // no overflow for huge components
  if (!(length > 0) || !std::isfinite(length)) {
    report_usage_error("eval", "eval: --dir must be a non-zero direction");
    return kExitUsage;
  }
  io::ShJsonContent content;
  if (io::IoStatus st = io::read_sh_json(options.document, content); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  const auto x = static_cast<float>(d[0] / length), y = static_cast<float>(d[1] / length),
             z = static_cast<float>(d[2] / length);
  std::cout << shortest(shade_sh9(content.shader, 0, x, y, z)) << ' '
            << shortest(shade_sh9(content.shader, 1, x, y, z)) << ' '
            << shortest(shade_sh9(content.shader, 2, x, y, z)) << '\n';
  return kExitOk;
}

}  // namespace shpack::cli
