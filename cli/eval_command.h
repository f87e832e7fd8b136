// eval_command.h - `shpack eval OUT.json --dir X,Y,Z`: what Unity's shader returns.
//
// Reads the shader vectors of an output document and prints ShadeSH9(n), evaluated in
// float from the packed vectors exactly as Unity's shader does (unity_pack.h), for the
// normalised direction n in Unity's frame: one line "R G B", each the shortest decimal
// that reads back to the same float.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shpack::cli {

struct EvalOptions {
  std::string document;
  std::vector<double> direction;  // X, Y, Z in Unity's frame; normalised before use
};

CLI::App* add_eval_command(CLI::App& app, EvalOptions& options);

// Exit code: kExitOk, kExitFailure if the document cannot be read, kExitUsage for a
// zero direction.
int run_eval(const EvalOptions& options);

}  // namespace shpack::cli
