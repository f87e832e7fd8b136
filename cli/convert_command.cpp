#include "convert_command.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

#include "batch.h"
#include "enum_option.h"
#include "face_pattern.h"
#include "output_check.h"
#include "replace_all.h"
#include "report.h"
#include "shpack/convert_request.h"
#include "shpack/io/atomic_write.h"
#include "shpack/io/convert.h"
#include "shpack/io/error_remedy.h"
#include "shpack/io/json_writer.h"
#include "shpack/io/output_format.h"
#include "shpack/io/stdin_spool.h"
#include "shpack/option_choices.h"
#include "validators.h"

namespace shpack::cli {
namespace {

namespace fs = std::filesystem;

// Converts one input (or the six `faces`, when there are any); writes `output`, or stdout
// when it is empty. Returns the error line to report, or "" on success; runs on any thread.
// `spooled`: the temporary file holding stdin (stdin_spool.h) when `input` is it; the
// document and the messages then name it "stdin".
std::string convert_one(const fs::path& input, const std::vector<std::string>& face_files, const fs::path& output,
                        const io::ConvertSettings& settings, const ConvertOptions& options, io::OutputFormat format,
                        bool spooled) {
  ShDocument doc;
  std::array<fs::path, kFaceNames.size()> faces;
  std::copy(face_files.begin(), face_files.end(), faces.begin());
  if (io::IoStatus st = face_files.empty() ? io::convert_env_map(input, settings, doc)
                                           : io::convert_cube_faces(faces, settings, doc);
      !st.ok()) {
    const std::string message = io::with_remedy(st, options.layout);
    return spooled ? replace_all(message, input.string(), io::kStdinName) : message;
  }
  if (spooled) doc.source.files = {io::kStdinName};
  doc.radiance_frame = options.frame;
  const std::string json = io::format_document(doc, format);
  if (output.empty()) {
    std::cout << json << std::flush;
    return std::cout ? std::string() : std::string("stdout: cannot write the JSON");
  }
  if (io::IoStatus st = io::write_file_atomically(output, json); !st.ok()) return st.message;
  return {};
}

// Input -> output pairs, or a usage problem. One output per input, never an input.
struct Plan {
  std::vector<std::pair<fs::path, fs::path>> jobs;
  std::vector<std::string> faces;  // the six --faces files, patterns expanded; empty without --faces
  std::string problem;
};

// The six face files of --faces: the six values as given, or one pattern expanded in Unity's
// face order. Returns the usage problem, or "".
std::string resolve_faces(const std::vector<std::string>& values, std::vector<std::string>& faces) {
  if (values.size() == kFaceNames.size()) {
    faces = values;
    return {};
  }
  if (values.size() != 1 || values[0].find(kFacePlaceholder) == std::string::npos) {
    return "convert: --faces takes six files, or one pattern containing {face}";
  }
  faces.clear();
  for (std::string_view name : kFaceNames) faces.push_back(expand_face_pattern(values[0], name));
  return {};
}

Plan plan_outputs(const ConvertOptions& options, io::OutputFormat format) {
  Plan plan;
  if (!options.faces.empty()) {  // one document from six files
    plan.problem = resolve_faces(options.faces, plan.faces);
    if (!plan.problem.empty()) return plan;
    if (!options.inputs.empty() || !options.out_dir.empty()) {
      plan.problem = "convert: --faces makes one document from six files: no other inputs, no --out-dir";
      return plan;
    }
    plan.problem = check_output_not_input(options.output, {plan.faces.begin(), plan.faces.end()});
    if (!plan.problem.empty()) return plan;
    plan.jobs.emplace_back(plan.faces[0], options.output);
    return plan;
  }
  if (options.inputs.empty()) {
    plan.problem = "convert: give the environment map files, or --faces with six files";
    return plan;
  }
  if (options.out_dir.empty() && options.inputs.size() > 1) {
    plan.problem = "convert: several inputs need --out-dir DIR";
    return plan;
  }
  if (std::count(options.inputs.begin(), options.inputs.end(), "-") > 0 &&
      (options.inputs.size() > 1 || !options.out_dir.empty())) {
    plan.problem = "convert: - (the image on stdin) is the only input, without --out-dir";
    return plan;
  }
  std::map<fs::path, fs::path> input_of_output;
  const std::vector<fs::path> all_inputs(options.inputs.begin(), options.inputs.end());
  for (const std::string& input : options.inputs) {
    const fs::path output = options.out_dir.empty()
                                ? fs::path(options.output)
                                : fs::path(options.out_dir) /
                                      fs::path(input).stem().concat(io::format_extension(format));
    if (!output.empty()) {
      if (const auto [it, fresh] = input_of_output.emplace(output, input); !fresh) {
        plan.problem = "convert: " + it->second.string() + " and " + input + " would both write " +
                       output.string();
        return plan;
      }
      plan.problem = check_output_not_input(output.string(), all_inputs);  // no output is any input
      if (!plan.problem.empty()) return plan;
    }
    plan.jobs.emplace_back(input, output);
  }
  return plan;
}

// The format of the outputs: --format; else the one -o's extension names (.json, .cs, .hlsl,
// .yaml, .gltf); else json. An explicit --format whose file the extension says is another
// format is a usage problem naming both (threejs writes .json and filament .txt: a .json
// file is a three.js one when --format says so). --frame is the JSON document's only.
std::string resolve_format(const ConvertOptions& options, io::OutputFormat& format) {
  const std::string extension = options.output.empty() || options.output == "-"
                                    ? std::string()
                                    : fs::path(options.output).extension().string();
  const std::optional<io::OutputFormat> named = io::format_of_extension(extension);
  format = options.format.value_or(named.value_or(io::OutputFormat::Json));
  if (options.format && named && *named != *options.format && extension != io::format_extension(*options.format)) {
    return std::string("convert: --format ") + io::format_name(*options.format) + " contradicts -o " +
           options.output + ", whose extension " + extension + " is --format " + io::format_name(*named);
  }
  if (options.frame != EngineFrame::Unity && format != io::OutputFormat::Json) {
    return std::string("convert: --frame sets the JSON document's radiance_sh; --format ") + io::format_name(format) +
           " has its engine's frame already";
  }
  return {};
}

}  // namespace

CLI::App* add_convert_command(CLI::App& app, ConvertOptions& options) {
  CLI::App* cmd = app.add_subcommand("convert", "Environment maps to Unity L2 SH (JSON)");
  CLI::Option* inputs =
      cmd->add_option("inputs", options.inputs, "Environment map files (EXR, HDR, PFM, PNG, ...); - for one on stdin")
          ->type_name("FILE");
  // 1 to 6 values for CLI11; plan_outputs refuses any count but six files or one pattern.
  cmd->add_option("--faces", options.faces,
                  "Six cube face files in Unity's order: +X -X +Y -Y +Z -Z (instead of inputs); "
                  "or one pattern with {face}, which becomes px nx py ny pz nz in that order")
      ->expected(1, static_cast<int>(kFaceNames.size()))
      ->type_name("FILE")
      ->excludes(inputs);
  CLI::Option* output = cmd->add_option("-o,--output", options.output,
                                        "Output file; - for stdout (default: stdout). Its extension sets the "
                                        "format unless --format does: .json, .cs, .hlsl, .yaml, .gltf")
                              ->type_name("FILE");
  cmd->add_option("--out-dir", options.out_dir, "Write DIR/<stem>.json (or the format's extension) for each input")
      ->type_name("DIR")
      ->excludes(output);
  add_enum_option(*cmd, "--layout", options.layout, kLayoutChoices,
                  "Image layout; auto: 2:1 equirect, 4:3/3:4 crosses, 6:1/1:6 strips, 1x1 uniform "
                  "(default auto; a square image needs octahedral, angular or mirrorball)");
  add_enum_option(*cmd, "--cube-frame", options.cube_frame, kCubeFrameChoices,
                  "World the cube faces were made in: unity, gl (z mirrored), threejs (default unity)");
  cmd->add_option("--layer", options.layer, "EXR part or channel layer to read (e.g. diffuse for diffuse.R/G/B)")
      ->type_name("NAME");
  add_enum_option(*cmd, "--colorspace", options.colorspace, kColorSpaceChoices,
                  "Primaries of the input's linear RGB (default auto: the EXR's chromaticities, else Rec. 709)");
  cmd->add_option("--method", options.method,
                  "exact, center, mip:K, mc:N, qmc:N, fib:N, is:N, riemann:N, cube:N, "
                  "cube-exact:N or lsq:N (default exact)")
      ->type_name("METHOD")
      ->check([](const std::string& text) {
        MethodSpec spec;
        const Status st = parse_method(text, spec);
        return st.ok() ? std::string() : "'" + text + "': " + st.what;
      });
  cmd->add_option_function<std::uint64_t>(
      "--seed", [&options](std::uint64_t seed) { options.seed = seed; },
      "Seed of the random methods mc, qmc and is; the others ignore it (default " +
          std::to_string(kDefaultMethodSeed) + ")")
      ->type_name("N")
      ->check(unsigned_integer());
  add_enum_option(*cmd, "--nonfinite", options.nonfinite, kNonFiniteChoices,
                  "NaN/Inf texels: fail, or count them as 0 (default error)");
  add_enum_option(*cmd, "--negative", options.negative, kNegativeChoices,
                  "Negative texels: keep them, or count them as 0 (default keep)");
  cmd->add_option("--intensity", options.intensity, "Multiply the radiance by K, a number >= 0 (default 1)")
      ->type_name("K")
      ->check(non_negative_finite_number());
  cmd->add_option("--exposure", options.exposure, "Multiply the radiance by 2^EV (default 0)")
      ->type_name("EV")
      ->check(finite_number());
  cmd->add_option("--rotate", options.rotate_deg,
                  "Yaw about +Y in degrees, as Skybox/Panoramic's _Rotation (default 0)")
      ->type_name("DEG")
      ->check(finite_number());
  cmd->add_option("--window", options.window,
                  "Deringing: none, hanning:W, lanczos:W, unity, sloan or optimal (default none)")
      ->type_name("W")
      ->check(window_text());
  cmd->add_option("--max-texels", options.max_texels,
                  "Refuse a map whose header declares more than N texels (display or data window; "
                  "six faces together), before reading it; N >= 1 (default " + std::to_string(io::kDefaultMaxTexels) + ")")
      ->type_name("N")
      ->check(unsigned_in(1, std::numeric_limits<std::uint64_t>::max()));
  cmd->add_option("--threads", options.threads, "Worker threads (default 0: all cores)")
      ->type_name("N")
      ->check(unsigned_integer());
  add_enum_option(*cmd, "--format", options.format,
                  {{"json", io::OutputFormat::Json}, {"csharp", io::OutputFormat::CSharp},
                   {"hlsl", io::OutputFormat::Hlsl}, {"unity-yaml", io::OutputFormat::UnityYaml},
                   {"threejs", io::OutputFormat::ThreeJs}, {"filament", io::OutputFormat::Filament},
                   {"gltf", io::OutputFormat::Gltf}},
                  "Output: JSON, a C# SphericalHarmonicsL2, an HLSL include, Unity YAML, a three.js LightProbe "
                  "(.json), cmgen's --sh-shader text for Filament (.txt), a glTF EXT_lights_image_based light "
                  "(.gltf) (default: from -o's extension, else json)");
  add_enum_option(*cmd, "--frame", options.frame, kEngineFrameChoices,
                  "Frame of the JSON's radiance_sh: unity, threejs (z mirrored), gltf (x mirrored), unreal "
                  "(Z up, Condon-Shortley signs), blender (Z up), filament (default unity; docs/conventions.md)");
  cmd->add_flag("--l1", options.l1, "L1 only (band 2 removed), for Light Probe Proxy Volumes");
  CLI::Option* sun = cmd->add_flag("--extract-sun", options.extract_sun,
                                   "Take the sun out of the map and write it as a Unity directional light (JSON \"sun\")");
  cmd->add_option("--extract-lights", options.extract_lights,
                  "Take up to N (0 to 8) compact bright sources out of the map as Unity directional lights, "
                  "each only if it lowers the max error of what Unity shows (JSON \"lights\"; default 0)")
      ->type_name("N")
      ->check(unsigned_in(0, kMaxExtractedLights))
      ->excludes(sun);
  return cmd;
}

namespace {

// The user-level options of the conversion, as the core translates them (convert_request.h).
ConvertRequest request_of(const ConvertOptions& options) {
  ConvertRequest request;
  request.method = options.method;
  request.seed = options.seed;
  request.nonfinite = options.nonfinite;
  request.negative = options.negative;
  request.intensity = options.intensity;
  request.exposure = options.exposure;
  request.rotate_deg = options.rotate_deg;
  request.window = options.window;
  request.l1 = options.l1;
  request.extract_sun = options.extract_sun;
  request.extract_lights = options.extract_lights;
  request.threads = options.threads;
  return request;
}

}  // namespace

int run_convert(const ConvertOptions& options) {
  io::ConvertSettings settings;
  // The values CLI11 checked are right by now: what is left is the factor and the seed.
  if (const std::string problem = to_convert_options(request_of(options), settings.convert); !problem.empty()) {
    report_usage_error("convert", std::string("convert: ").append(problem));
    return kExitUsage;
  }
  io::OutputFormat format = io::OutputFormat::Json;
  if (const std::string problem = resolve_format(options, format); !problem.empty()) {
    report_usage_error("convert", problem);
    return kExitUsage;
  }
  Plan plan = plan_outputs(options, format);
  if (!plan.problem.empty()) {
    report_usage_error("convert", plan.problem);
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

  settings.source = {options.layout, options.layer, options.colorspace, options.cube_frame, options.max_texels};
  shpack::ConvertOptions& convert = settings.convert;
  if (!plan.faces.empty()) {  // the layout is known before anything is read
    if (Status st = check_convert_options(convert, Layout::Faces, options.cube_frame); !st.ok()) {
      report_usage_error("convert", std::string("convert: --faces: ") + st.what);
      return kExitUsage;
    }
  }
  // Files in parallel: up to `threads` files at a time, each projected with its share of the
  // threads (the output is bit-identical for any thread count); errors reported in input order.
  const unsigned threads = options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  const auto files = static_cast<unsigned>(std::min<std::size_t>(plan.jobs.size(), threads));
  convert.threads = std::max(1u, threads / files);
  // `-`: the image on stdin, copied into a temporary file first (stdin_spool.h).
  io::StdinSpool spool;
  const bool from_stdin = plan.faces.empty() && plan.jobs.size() == 1 && plan.jobs[0].first == "-";
  if (from_stdin) {
    if (io::IoStatus st = spool.fill(io::stdin_budget(options.max_texels)); !st.ok()) {
      report_error(st.message);
      return kExitFailure;
    }
    plan.jobs[0].first = spool.path();
  }
  bool all_ok = true;
  run_in_order<std::string>(
      plan.jobs.size(), files,
      [&](std::size_t k) {
        return convert_one(plan.jobs[k].first, plan.faces, plan.jobs[k].second, settings, options, format,
                           from_stdin);
      },
      [&](std::size_t, std::string& error) {
        if (!error.empty()) report_error(error);
        all_ok = all_ok && error.empty();
      });
  return all_ok ? kExitOk : kExitFailure;
}

}  // namespace shpack::cli
