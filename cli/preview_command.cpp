#include "preview_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "enum_option.h"
#include "output_check.h"
#include "report.h"
#include "shpack/option_choices.h"
#include "validators.h"
#include "shpack/io/atomic_write.h"
#include "shpack/io/image_file.h"
#include "shpack/io/json_reader.h"
#include "shpack/io/lightmap_preview.h"
#include "shpack/io/preview.h"
#include "shpack/io/sha256.h"
#include "shpack/io/stdin_spool.h"

namespace shpack::cli {
namespace {

std::string percent(double part, double whole) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g%%", whole > 0 ? 100.0 * part / whole : 0.0);
  return text;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

}  // namespace

CLI::App* add_preview_command(CLI::App& app, PreviewOptions& options) {
  CLI::App* cmd = app.add_subcommand("preview", "Pictures of the lighting: lit spheres, E/pi, error map (PNG)");
  cmd->add_option("document", options.document, "A JSON file written by shpack convert")->type_name("FILE")->required();
  cmd->add_option("-o,--output", options.output, "The image to write (.png); - for stdout (the report then goes to stderr)")
      ->type_name("FILE")
      ->required();
  cmd->add_option("--input", options.input,
                  "The map the document came from (- for stdin): adds its exact E/pi and the error map")
      ->type_name("FILE");
  add_enum_option(*cmd, "--input-layout", options.input_layout, kLayoutChoices,
                  "How --input holds the sphere, as convert's --layout (default auto)");
  cmd->add_option_function<std::size_t>(
         "--probe", [&options](std::size_t n) { options.probe = n; },
         "For a bake document: the probe to show, from 0")
      ->type_name("N")
      ->check(unsigned_integer());
  cmd->add_option("--size", options.size, "Sphere diameter in pixels, 32 to 1024 (default 128)")
      ->type_name("PIXELS")
      ->check(unsigned_in(32, 1024));
  return cmd;
}

int run_preview(const PreviewOptions& options) {
  const std::filesystem::path output = options.output;
  const bool to_stdout = io::output_descriptor(output) == 1;  // "-", /dev/stdout: the PNG bytes
  if (io::output_descriptor(output) < 0 && output.extension() != ".png" && output.extension() != ".PNG") {
    report_usage_error("preview", "preview: " + options.output + ": the image is written as PNG; name it .png");
    return kExitUsage;
  }
  std::vector<std::filesystem::path> inputs = {options.document};
  if (!options.input.empty()) inputs.emplace_back(options.input);
  if (const std::string problem = check_output_not_input(options.output, inputs); !problem.empty()) {
    report_usage_error("preview", problem);
    return kExitUsage;
  }
  if (options.document == "-" && options.input == "-") {
    report_usage_error("preview", "preview: the document and --input cannot both be stdin");
    return kExitUsage;
  }
  // A lightmap's sidecar (docs/lightmaps.md): its texels as pictures.
  if (options.document.size() > 14 && options.document.ends_with(".lightmap.json")) {
    io::Rgb8Image image;
    if (io::IoStatus st = io::render_lightmap_preview(options.document, options.size, image); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
    if (io::IoStatus st = io::write_png(output, image); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
    return kExitOk;
  }
  io::ShJsonContent content;
  if (io::IoStatus st = io::read_sh_json(options.document, content, options.probe); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  io::PreviewSettings settings;
  settings.size = options.size;
  settings.reference = options.input;
  settings.reference_layout = options.input_layout;
  settings.reference_label = std::filesystem::path(options.input).filename().string();
  io::StdinSpool spool;  // --input -: the map on stdin (stdin_spool.h)
  const bool from_stdin = options.input == "-";
  if (from_stdin) {
    if (io::IoStatus st = spool.fill(io::stdin_budget(io::kDefaultMaxTexels)); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
    settings.reference = spool.path();
    settings.reference_label = io::kStdinName;
  }
  io::Rgb8Image image;
  io::PreviewReport report;
  if (io::IoStatus st = io::render_preview(content, settings, image, report); !st.ok()) {
    const std::string path = settings.reference.string();
    report_error(from_stdin && st.message.rfind(path, 0) == 0 ? std::string(io::kStdinName).append(st.message, path.size())
                                                              : st.message);
    return kExitFailure;
  }
  if (!options.input.empty() && !content.sha256.empty()) {  // the reference should be the document's source
    std::string digest;
    if (io::sha256_file(settings.reference, digest).ok() &&
        std::find(content.sha256.begin(), content.sha256.end(), digest) == content.sha256.end())
      std::fprintf(stderr, "shpack: warning: %s is not the file the document was made from (its SHA-256 is not in "
                   "source.sha256); the error map compares different lighting\n", options.input.c_str());
  }
  if (io::IoStatus st = io::write_png(output, image); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  std::ostream& text = to_stdout ? std::cerr : std::cout;  // stdout holds the PNG
  text << "tone mapping: Reinhard x/(1+x) per channel, then sRGB; mean E/pi luminance "
            << number(report.mean_luminance) << " shown at 0.5\n"
            << "negative E/pi (striped): " << percent(report.negative_fraction, 1.0) << " of the sphere\n";
  if (report.has_reference) {
    const double bound = report.reference_bound_luminance;
    text << "reference: exact E/pi of the map's texels, error <= " << number(bound) << " ("
              << percent(bound, report.mean_luminance)
              << " of the mean)\n"
              << "sh - reference (luminance): max |error| " << number(report.max_abs_error) << " ("
              << percent(report.max_abs_error, report.mean_luminance) << " of the mean), rms "
              << number(report.rms_error) << " (" << percent(report.rms_error, report.mean_luminance) << ")\n";
  }
  return kExitOk;
}

}  // namespace shpack::cli
