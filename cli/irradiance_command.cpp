#include "irradiance_command.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string_view>
#include <vector>

#include "enum_option.h"
#include "face_pattern.h"
#include "report.h"
#include "shpack/option_choices.h"
#include "shpack/io/exr_writer.h"
#include "shpack/io/map_source.h"
#include "shpack/io/stdin_spool.h"
#include "validators.h"

namespace shpack::cli {

bool parse_irradiance_source(const std::string& text, IrradianceRequest& request) {
  if (text == "sh" || text == "exact") {
    request.source = text == "sh" ? IrradianceSource::Sh : IrradianceSource::Exact;
    request.samples = 0;
    return true;
  }
  const std::size_t colon = text.find(':');
  const std::string name = text.substr(0, colon);
  if (colon == std::string::npos || (name != "riemann" && name != "mc")) return false;
  std::uint32_t n = 0;
  const char* first = text.data() + colon + 1;
  const char* last = text.data() + text.size();
  const auto [end, error] = std::from_chars(first, last, n);
  if (error != std::errc() || end != last || first == last || n == 0) return false;
  request.source = name == "riemann" ? IrradianceSource::Riemann : IrradianceSource::MonteCarlo;
  request.samples = n;
  return true;
}

CLI::App* add_irradiance_command(CLI::App& app, IrradianceOptions& options) {
  CLI::App* cmd = app.add_subcommand("irradiance", "Write E/pi of a map as an image: what L2 keeps and loses");
  cmd->add_option("input", options.input, "The environment map (any format convert reads); - for one on stdin")
      ->type_name("FILE")
      ->required();
  cmd->add_option("-o,--output", options.output, "The OpenEXR file to write (float RGB); - for stdout")
      ->type_name("FILE")
      ->required();
  add_enum_option(*cmd, "--input-layout", options.input_layout, kLayoutChoices,
                  "How the input holds the sphere, as convert's --layout (default auto)");
  add_enum_option(*cmd, "--layout", options.layout,
                  {{"equirect", Layout::Equirect}, {"hcross", Layout::HorizontalCross},
                   {"vcross", Layout::VerticalCross}, {"hstrip", Layout::HorizontalStrip},
                   {"vstrip", Layout::VerticalStrip}, {"faces", Layout::Faces}},
                  "The output's layout; faces: six files, -o a pattern with {face} (px nx py ny pz nz) "
                  "(default equirect)");
  cmd->add_option("--size", options.size,
                  "Equirect: the height (the width is twice it); cubes: a face's side (default 128)")
      ->type_name("N")
      ->check(unsigned_in(1, 8192));
  cmd->add_option("--source", options.source,
                  "sh (what Unity shows from the L2 SH), exact (the map's cosine convolution, within a "
                  "stated bound), riemann:N or mc:N (the Riemann and Monte Carlo sums of N samples) "
                  "(default exact)")
      ->type_name("SOURCE")
      ->check([](const std::string& text) {
        IrradianceRequest request;
        return parse_irradiance_source(text, request) ? std::string()
                                                      : "'" + text + "': not sh, exact, riemann:N or mc:N (N >= 1)";
      });
  cmd->add_option("--seed", options.seed, "Seed of mc (default " + std::to_string(kDefaultMethodSeed) + ")")
      ->type_name("N")
      ->check(unsigned_integer());
  cmd->add_option("--threads", options.threads, "Worker threads (default 0: all cores); the image does not depend on it")
      ->type_name("N")
      ->check(unsigned_integer());
  return cmd;
}

namespace {

// One file, or for faces the six faces of the horizontal strip it was rendered as (+X -X
// +Y -Y +Z -Z left to right, none turned: cube_layout.h), each to the pattern with {face}
// replaced by px nx py ny pz nz. Each file is written whole or not at all (atomic_write.h).
io::IoStatus write_image(const IrradianceOptions& options, const IrradianceImage& image) {
  if (options.layout != Layout::Faces)
    return io::write_exr_rgb(options.output, image.width, image.height, image.rgb);
  const std::uint32_t n = image.height;
  for (std::uint32_t f = 0; f < 6; ++f) {
    std::vector<float> face(std::size_t{3} * n * n);
    for (std::uint32_t y = 0; y < n; ++y)
      std::copy_n(image.rgb.begin() + 3 * (std::size_t{y} * image.width + f * n), 3 * n, face.begin() + 3 * std::size_t{y} * n);
    const std::string path = expand_face_pattern(options.output, kFaceNames[f]);
    if (io::IoStatus st = io::write_exr_rgb(path, n, n, face); !st.ok()) return st;
  }
  return io::IoStatus::success();
}

}  // namespace

int run_irradiance(const IrradianceOptions& options) {
  if ((options.layout == Layout::Faces) != (options.output.find(kFacePlaceholder) != std::string::npos)) {
    report_usage_error("irradiance", options.layout == Layout::Faces
                                         ? "irradiance: --layout faces writes six files: give -o a pattern with {face}"
                                         : "irradiance: {face} in -o needs --layout faces");
    return kExitUsage;
  }
  IrradianceRequest request;
  if (!parse_irradiance_source(options.source, request)) return kExitUsage;  // checked by CLI11
  request.seed = options.seed;
  request.layout = options.layout == Layout::Faces ? Layout::HorizontalStrip : options.layout;
  request.size = options.size;
  request.threads = options.threads;

  io::MapSource source;
  io::SourceOptions source_options;
  source_options.layout = options.input_layout;
  io::StdinSpool spool;  // `-`: the image on stdin (stdin_spool.h)
  if (options.input == "-") {
    if (io::IoStatus st = spool.fill(io::stdin_budget(source_options.max_texels)); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
  }
  const std::string path = options.input == "-" ? spool.path().string() : options.input;
  // A message names the file first (io_status.h): the temporary copy is named as stdin.
  const auto shown = [&](const std::string& message) {
    if (options.input != "-" || message.rfind(path, 0) != 0) return message;
    return std::string(io::kStdinName).append(message, path.size());
  };
  if (io::IoStatus st = source.open(path, source_options); !st.ok()) {
    report_error(shown(st.message));
    return kExitFailure;
  }
  MapImage map;
  if (io::IoStatus st = source.read_whole(map, options.threads); !st.ok()) {
    report_error(shown(st.message));
    return kExitFailure;
  }
  shpack::ConvertOptions convert;
  convert.nonfinite = NonFinite::Zero;  // as the reference reads NaN/Inf texels: black
  convert.threads = options.threads;
  convert.finish.colour_matrix = source.info().colour.matrix;
  IrradianceImage image;
  if (Status st = render_irradiance(map, convert, request, image); !st.ok()) {
    report_error(shown(std::string(path).append(": ").append(st.what)));
    return st.code == Errc::InvalidArgument ? kExitUsage : kExitFailure;
  }
  if (io::IoStatus st = write_image(options, image); !st.ok()) {
    report_error(st.message);
    return kExitFailure;
  }
  if (request.source == IrradianceSource::Exact)
    std::fprintf(stderr, "irradiance: %ux%u, exact within %.6g (E/pi, the largest bound of a texel)\n", image.width,
                 image.height, image.bound);
  return kExitOk;
}

}  // namespace shpack::cli
