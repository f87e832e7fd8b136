// preview_command.h - `shpack preview OUT.json -o IMG.png [--input MAP]`: pictures of the
// lighting (lib/io's preview.h says what each panel shows).
//
// Prints what the image shows in numbers, one fact per line: the tone mapping, the share of
// the sphere where E/pi is negative, and with --input the reference's error bound and the
// error of the SH against it.
#pragma once

#include <CLI/CLI.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "shpack/layout.h"

namespace shpack::cli {

struct PreviewOptions {
  std::string document;  // a JSON document of shpack convert
  std::string output;    // -o, a .png file
  std::string input;     // --input: the map the document came from, or empty
  Layout input_layout = Layout::Auto;  // --input-layout
  std::uint32_t size = 128;  // --size: sphere diameter in pixels
  std::optional<std::size_t> probe;  // --probe N: the probe of a bake document
};

CLI::App* add_preview_command(CLI::App& app, PreviewOptions& options);

// Exit code: kExitOk, kExitFailure if a file cannot be read or written, kExitUsage for a
// bad command line.
int run_preview(const PreviewOptions& options);

}  // namespace shpack::cli
