#include "bake_support.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "scene/scene_files.h"
#include "shpack/scene/scene_loader.h"

namespace shpack_test {

Baked bake_scene(const std::string& name, const std::string& json, unsigned threads) {
  Baked b;
  const shpack::io::IoStatus loaded = shpack::scene::load_scene(write_scene(name + ".json", json), b.scene);
  EXPECT_TRUE(loaded.ok()) << loaded.message;
  shpack::bake::BakeOptions options;
  options.threads = threads;
  options.keep_effects = true;
  b.status = shpack::bake::bake(b.scene, options, b.result);
  return b;
}

Baked bake_ok(const std::string& name, const std::string& json, unsigned threads) {
  Baked b = bake_scene(name, json, threads);
  EXPECT_TRUE(b.status.ok()) << b.status.message;
  return b;
}

int run_cli(const std::string& args, std::string& err) {
  const std::filesystem::path err_file = scene_scratch() / "stderr.txt";
  std::string command = SHPACK_CLI_PATH;  // built piece by piece: g++ 12 warns falsely on a + chain
  command += ' ';
  command += args;
  command += " 2> ";
  command += err_file.string();
  const int status = std::system(command.c_str());
  std::ifstream in(err_file);
  err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

double max_error_pct(const shpack::ShL2& got, const shpack::ShL2& want) {
  using shpack::kChannelCount;
  using shpack::kShCount;
  constexpr int n = 4096;
  double brightest = 0;
  for (int c = 0; c < kChannelCount; ++c) brightest = std::max(brightest, want.c[c][0] * shpack::kY0);
  double worst = 0;
  for (int k = 0; k < n; ++k) {
    const double y = 1.0 - (2.0 * k + 1.0) / n, s = std::sqrt(1.0 - y * y), phi = 2.399963229728653 * k;
    const auto basis = shpack::eval_basis(s * std::cos(phi), y, s * std::sin(phi));
    for (int c = 0; c < kChannelCount; ++c) {
      double e = 0;
      for (int i = 0; i < kShCount; ++i)
        e += (i == 0 ? 1.0 : i < 4 ? 2.0 / 3.0 : 0.25) * (got.c[c][i] - want.c[c][i]) * basis[i];
      worst = std::max(worst, 100.0 * std::fabs(e) / std::max(want.c[c][0] * shpack::kY0, 0.01 * brightest));
    }
  }
  return worst;
}

}  // namespace shpack_test
