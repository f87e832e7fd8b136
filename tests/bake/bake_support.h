// bake_support.h - baking a scene written by a test, and measuring a probe's error as a user
// reads it, for the tests of tests/bake.
#pragma once

#include <string>

#include "shpack/bake/bake.h"
#include "shpack/io/io_status.h"
#include "shpack/scene/scene.h"

namespace shpack_test {

struct Baked {
  shpack::scene::Scene scene;
  shpack::io::IoStatus status = shpack::io::IoStatus::success();
  shpack::bake::BakeResult result;
};

// Writes `json` as <scratch>/<name>.json, loads and bakes it (keeping each effect's part).
Baked bake_scene(const std::string& name, const std::string& json, unsigned threads = 2);
// The same, expecting the bake to succeed.
Baked bake_ok(const std::string& name, const std::string& json, unsigned threads = 2);

// Runs the built `shpack` with `args` through the shell (SHPACK_CLI_PATH); returns its exit
// code, its stderr in `err`.
int run_cli(const std::string& args, std::string& err);

// The largest |E/pi(got) - E/pi(want)| over 4096 nearly uniform directions, in % of the mean
// E/pi of `want`, the worst channel (a channel dimmer than 1 % of the brightest measured
// against 1 % of the brightest, as the bake's own estimate is): what error_estimate_pct
// promises to bound. E/pi = sum_l (A_l / pi) L_lm Y_lm, A_l / pi = 1, 2/3, 1/4.
double max_error_pct(const shpack::ShL2& got, const shpack::ShL2& want);

}  // namespace shpack_test
