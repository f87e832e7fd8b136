#include "shpack/io/json_writer.h"

#include <nlohmann/json.hpp>

#include <string>

#include "shpack/engine_frame.h"
#include "shpack/io/sh_record_json.h"
#include "shpack/io/version.h"

namespace shpack::io {
namespace {

using OrderedJson = nlohmann::ordered_json;  // keeps keys in insertion order

// The sun of --extract-sun (light_extraction.h), or a light of --extract-lights: what was removed, and the Unity light that
// replaces it (unity_light.h).
OrderedJson sun_json(const FinishedLight& sun) {
  const SunLight& light = sun.light;
  const UnitySunLight& unity = sun.unity;
  return {{"direction", dir_json<OrderedJson>(light.direction)},
          {"irradiance", light.irradiance},
          {"sky_level", light.sky},
          {"angular_radius_deg", light.radius_deg},
          {"solid_angle_sr", light.solid_angle},
          {"texels", light.texels},
          {"unity_light",
           {{"forward", dir_json<OrderedJson>(unity.forward)},
            {"euler_deg", unity.euler_deg},
            {"quaternion", unity.quaternion},
            {"color", unity.colour},
            {"color_srgb", unity.colour_srgb},
            {"intensity", unity.intensity}}}};
}

const char* cube_frame_name(CubeFrame frame) {
  return frame == CubeFrame::Gl ? "gl" : frame == CubeFrame::ThreeJs ? "threejs" : "unity";
}

// "layer" when one was chosen, "cube_frame" for cube layouts, "colorspace" always, and the
// colour matrix when one was applied.
void add_reading(const ShDocument& doc, OrderedJson& source) {
  if (!doc.reading.layer.empty()) source["layer"] = doc.reading.layer;
  if (is_cube_layout(doc.source.layout)) source["cube_frame"] = cube_frame_name(doc.reading.cube_frame);
  source["colorspace"] = doc.reading.colorspace;
  if (doc.colour_matrix) source["rgb_to_rec709"] = *doc.colour_matrix;
}

}  // namespace

std::string to_json(const ShDocument& doc) {
  OrderedJson j;
  j["schema_version"] = kSchemaVersion;
  j["generator"] = std::string("shpack ") + shpack_version();
  j["source"] = {{"files", doc.source.files},
                 {"sha256", doc.source.sha256},
                 {"layout", layout_name(doc.source.layout)},
                 {"width", doc.source.width},
                 {"height", doc.source.height}};
  add_reading(doc, j["source"]);
  j["options"] = {{"method", std::string(method_name(doc.method).view())},
                  {"window", window_name(doc.window).text},
                  {"rotate_deg", doc.rotate_deg},
                  {"intensity", doc.intensity}};
  if (doc.l1) j["options"]["l1"] = true;  // --l1 (document.h): only when given
  j["frame"] = engine_frame_spec(EngineFrame::Unity).description;
  // --frame (engine_frame.h): radiance_sh alone in another engine's frame and basis signs;
  // the Unity forms and every direction stay in Unity's frame.
  const bool other_frame = doc.radiance_frame != EngineFrame::Unity;
  if (other_frame) j["radiance_sh_frame"] = engine_frame_spec(doc.radiance_frame).description;
  put_sh_values(doc.sh, j);
  if (other_frame) {
    OrderedJson radiance = OrderedJson::array();
    for (const auto& channel : sh_to_engine_frame(doc.radiance_frame, doc.sh.radiance).c) radiance.push_back(channel);
    j["radiance_sh"] = std::move(radiance);
  }
  OrderedJson diagnostics = {{"nonfinite_texels", doc.texels.nonfinite_texels},
                      {"negative_texels", doc.texels.negative_texels},
                      {"ignored_channels", doc.reading.ignored_channels}};
  put_sh_diagnostics(doc.sh, diagnostics);
  diagnostics["window_impossible"] = doc.sh.window.impossible;
  if (!scales_bands(doc.window.kind)) {  // optimal: no factors (null), what it changed instead
    diagnostics["window_rms_change"] = doc.sh.window.rms_change;
    diagnostics["window_planes"] = doc.sh.window.planes;
  }
  if (doc.view_error) {
    diagnostics["unity_view_error_max_pct"] = doc.view_error->max_pct;
    diagnostics["unity_view_error_rms_pct"] = doc.view_error->rms_pct;
    diagnostics["unity_view_error_bound_pct"] = doc.view_error->bound_pct;
    diagnostics["unity_view_error_directions"] = kViewErrorDirections;
  }
  j["diagnostics"] = std::move(diagnostics);
  if (doc.sun_extraction) j["sun"] = doc.sun ? sun_json(*doc.sun) : OrderedJson(nullptr);  // null: no sun found
  if (doc.light_extraction > 0) {  // --extract-lights: every light chosen, each a sun record
    j["light_candidates"] = doc.light_candidates;
    OrderedJson lights = OrderedJson::array();
    for (const ExtractedLight& light : doc.lights) {
      OrderedJson record = sun_json(light.light);
      record["offset_deg"] = light.light.light.offset_deg;
      record["unity_view_error_before_pct"] = light.error_before_pct;
      record["unity_view_error_after_pct"] = light.error_after_pct;
      lights.push_back(std::move(record));
    }
    j["lights"] = std::move(lights);
  }
  // A file name need not be UTF-8 on Linux: replace bad bytes rather than fail.
  return j.dump(2, ' ', false, OrderedJson::error_handler_t::replace) + "\n";
}

}  // namespace shpack::io
