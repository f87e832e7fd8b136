// The JSON output: the keys of docs/json-format.md in its order, exact numbers both ways, and a
// reader whose errors point at the offending value.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <random>
#include <string>
#include <vector>

#include "io_test_files.h"
#include "shpack/convolution.h"
#include "shpack/io/json_reader.h"
#include "shpack/io/json_writer.h"
#include "shpack/unity_pack.h"

namespace shpack::io {
namespace {

using OrderedJson = nlohmann::ordered_json;  // keeps the keys in the order written

// Coefficients with many significant digits and both signs, so that a writer that
// rounds anything shows it.
ShDocument sample_document() {
  std::mt19937_64 rng(0x5eed);
  std::uniform_real_distribution<double> coefficient(-3.0, 3.0);
  ShDocument doc;
  doc.source = {{"sky.exr"}, {std::string(64, 'a')}, Layout::Equirect, 1024, 512};
  doc.method = {SamplingMethod::MonteCarlo, 4096, 7};  // a seed other than the default
  doc.intensity = 0.1;
  for (auto& channel : doc.sh.radiance.c)
    for (double& v : channel) v = coefficient(rng);
  doc.sh.unity_form = radiance_to_unity_form(doc.sh.radiance);
  doc.sh.unity_sh = to_unity_sh(doc.sh.unity_form);  // the finish stage packs; the writer only copies
  doc.sh.shader = to_shader_vectors(doc.sh.unity_form);
  doc.texels.nonfinite_texels = 2;
  doc.texels.negative_texels = 12;
  doc.reading.ignored_channels = 1;
  for (int c = 0; c < kChannelCount; ++c) doc.sh.min_e_over_pi[c] = {-0.125 * c, {0.0, -1.0, 0.0}};
  return doc;
}

std::vector<std::string> keys(const OrderedJson& object) {
  std::vector<std::string> out;
  for (const auto& item : object.items()) out.push_back(item.key());
  return out;
}

TEST(JsonWriter, KeysAreThoseOfTheDesignInOrder) {
  const OrderedJson j = OrderedJson::parse(to_json(sample_document()));
  EXPECT_EQ(keys(j), (std::vector<std::string>{"schema_version", "generator", "source", "options", "frame",
                                               "radiance_sh", "sphericalHarmonicsL2", "shader",
                                               "diagnostics"}));
  EXPECT_EQ(keys(j["source"]), (std::vector<std::string>{"files", "sha256", "layout", "width", "height", "colorspace"}));
  EXPECT_EQ(keys(j["options"]), (std::vector<std::string>{"method", "window", "rotate_deg", "intensity"}));
  EXPECT_EQ(keys(j["shader"]), (std::vector<std::string>{"unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr",
                                                         "unity_SHBg", "unity_SHBb", "unity_SHC"}));
  EXPECT_EQ(keys(j["diagnostics"]),
            (std::vector<std::string>{"nonfinite_texels", "negative_texels", "ignored_channels",
                                      "min_e_over_pi", "min_e_over_pi_direction", "window_factors",
                                      "window_impossible"}));
}

TEST(JsonWriter, WritesTheViewErrorWhenTheDocumentHasOne) {
  ShDocument doc = sample_document();
  doc.view_error = shpack::ViewError{12.5, 4.25, 0.5, 2, {0, 1, 0}};
  const OrderedJson d = OrderedJson::parse(to_json(doc))["diagnostics"];
  EXPECT_EQ(d["unity_view_error_max_pct"], 12.5);
  EXPECT_EQ(d["unity_view_error_rms_pct"], 4.25);
  EXPECT_EQ(d["unity_view_error_bound_pct"], 0.5);
  EXPECT_EQ(d["unity_view_error_directions"], shpack::kViewErrorDirections);
}

TEST(JsonWriter, TheOptimalWindowWritesWhatItChangedInsteadOfFactors) {
  ShDocument doc = sample_document();
  EXPECT_FALSE(OrderedJson::parse(to_json(doc))["diagnostics"].contains("window_rms_change"));  // only with optimal
  doc.window.kind = shpack::WindowKind::Optimal;
  doc.sh.window.rms_change = {0.125, 0.0, 0.5};
  doc.sh.window.planes = {3, 0, 7};
  const OrderedJson j = OrderedJson::parse(to_json(doc));
  EXPECT_EQ(j["options"]["window"], "optimal");
  EXPECT_EQ(j["diagnostics"]["window_rms_change"], OrderedJson::array({0.125, 0.0, 0.5}));
  EXPECT_EQ(j["diagnostics"]["window_planes"], OrderedJson::array({3, 0, 7}));
}

TEST(JsonWriter, ValuesAreThoseOfTheDocument) {
  const ShDocument doc = sample_document();
  const OrderedJson j = OrderedJson::parse(to_json(doc));
  EXPECT_EQ(j["schema_version"], 1);
  EXPECT_EQ(j["generator"], "shpack 0.1.0");
  EXPECT_EQ(j["source"]["files"], OrderedJson::array({"sky.exr"}));
  EXPECT_EQ(j["source"]["sha256"], OrderedJson::array({std::string(64, 'a')}));
  EXPECT_EQ(j["source"]["layout"], "equirect");
  EXPECT_EQ(j["source"]["width"], 1024);
  EXPECT_EQ(j["source"]["height"], 512);
  EXPECT_EQ(j["options"]["method"], "mc:4096:7");  // method_name: parse_method reads it back
  EXPECT_EQ(j["options"]["window"], "none");
  EXPECT_EQ(j["options"]["rotate_deg"], 0);
  EXPECT_EQ(j["options"]["intensity"].get<double>(), 0.1);
  EXPECT_EQ(j["frame"], "unity: left-handed, +Y up, +Z forward");
  EXPECT_EQ(j["diagnostics"]["nonfinite_texels"], 2);
  EXPECT_EQ(j["diagnostics"]["negative_texels"], 12);
  EXPECT_EQ(j["diagnostics"]["ignored_channels"], 1);
  EXPECT_EQ(j["diagnostics"]["min_e_over_pi"], OrderedJson::array({0.0, -0.125, -0.25}));
  EXPECT_EQ(j["diagnostics"]["min_e_over_pi_direction"][2], OrderedJson::array({0.0, -1.0, 0.0}));
}

TEST(JsonWriter, NumbersReadBackExactly) {
  // Doubles in shortest round-trip form, floats as the double of equal value: parsing
  // the text gives the very same bits.
  const ShDocument doc = sample_document();
  const OrderedJson j = OrderedJson::parse(to_json(doc));
  const UnitySphericalHarmonicsL2 floats = to_unity_sh(doc.sh.unity_form);
  const UnityShaderVectors vectors = to_shader_vectors(doc.sh.unity_form);
  for (int c = 0; c < kChannelCount; ++c) {
    for (int i = 0; i < kShCount; ++i) {
      EXPECT_EQ(j["radiance_sh"][c][i].get<double>(), doc.sh.radiance.c[c][i]) << "c=" << c << " i=" << i;
      EXPECT_EQ(j["sphericalHarmonicsL2"][c][i].get<double>(), static_cast<double>(floats[c][i]))
          << "c=" << c << " i=" << i;
    }
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(j["shader"]["unity_SHAr"][k].get<double>(), static_cast<double>(vectors.SHAr[k])) << k;
    EXPECT_EQ(j["shader"]["unity_SHC"][k].get<double>(), static_cast<double>(vectors.SHC[k])) << k;
  }
}

TEST(JsonRoundTrip, ReaderReturnsWhatTheWriterWrote) {
  const shpack_io_test::ScratchDir dir;
  const ShDocument doc = sample_document();
  const std::string text = to_json(doc);
  shpack_io_test::write_bytes(dir / "out.json", {text.begin(), text.end()});
  ShJsonContent content;
  const IoStatus st = read_sh_json(dir / "out.json", content);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(content.radiance, doc.sh.radiance);
  EXPECT_EQ(content.unity_sh, to_unity_sh(doc.sh.unity_form));
  const UnityShaderVectors want = to_shader_vectors(doc.sh.unity_form);
  EXPECT_EQ(content.shader.SHAr, want.SHAr);
  EXPECT_EQ(content.shader.SHAg, want.SHAg);
  EXPECT_EQ(content.shader.SHAb, want.SHAb);
  EXPECT_EQ(content.shader.SHBr, want.SHBr);
  EXPECT_EQ(content.shader.SHBg, want.SHBg);
  EXPECT_EQ(content.shader.SHBb, want.SHBb);
  EXPECT_EQ(content.shader.SHC, want.SHC);
}

// Reads `doc` (as text) back and returns the error message, "" on success.
std::string read_error(const std::string& text, IoErrc want) {
  const shpack_io_test::ScratchDir dir;
  shpack_io_test::write_bytes(dir / "out.json", {text.begin(), text.end()});
  ShJsonContent content;
  const IoStatus st = read_sh_json(dir / "out.json", content);
  EXPECT_EQ(st.code, want) << st.message;
  EXPECT_EQ(st.message.find('\n'), std::string::npos) << st.message;
  const std::string prefix = (dir / "out.json").string() + ": ";
  EXPECT_EQ(st.message.rfind(prefix, 0), 0u) << st.message;
  return st.message.substr(std::min(prefix.size(), st.message.size()));
}

TEST(JsonReader, ErrorsPointAtTheValue) {
  const OrderedJson good = OrderedJson::parse(to_json(sample_document()));
  OrderedJson j = good;
  j["shader"]["unity_SHBg"][2] = "x";
  EXPECT_EQ(read_error(j.dump(), IoErrc::BadDocument), "/shader/unity_SHBg/2: expected a number");
  j = good;
  j["radiance_sh"][1].erase(8);
  EXPECT_EQ(read_error(j.dump(), IoErrc::BadDocument), "/radiance_sh/1: expected an array of 9 elements");
  j = good;
  j.erase("sphericalHarmonicsL2");
  EXPECT_EQ(read_error(j.dump(), IoErrc::BadDocument), "/: missing key \"sphericalHarmonicsL2\"");
  j = good;
  j["shader"].erase("unity_SHC");
  EXPECT_EQ(read_error(j.dump(), IoErrc::BadDocument), "/shader: missing key \"unity_SHC\"");
  j = good;
  j["sphericalHarmonicsL2"][0][0] = 1e39;  // beyond float32
  EXPECT_EQ(read_error(j.dump(), IoErrc::BadDocument), "/sphericalHarmonicsL2/0/0: out of float32 range");
  j = good;
  j["schema_version"] = 2;
  EXPECT_EQ(read_error(j.dump(), IoErrc::BadDocument),
            "/schema_version: unsupported schema version 2 (this shpack reads 1)");
  EXPECT_EQ(read_error("[1, 2]", IoErrc::BadDocument), "/: expected an object");
}

TEST(JsonReader, NotJsonIsUnreadable) {
  EXPECT_EQ(read_error("{\"schema_version\": ", IoErrc::Unreadable).rfind("not valid JSON: ", 0), 0u);
  EXPECT_EQ(read_error("", IoErrc::Unreadable).rfind("not valid JSON: ", 0), 0u);
}

TEST(JsonReader, MissingFileIsNamed) {
  ShJsonContent content;
  const IoStatus st = read_sh_json("no/such.json", content);
  EXPECT_EQ(st.code, IoErrc::NotFound);
  EXPECT_EQ(st.message, "no/such.json: no such file");
}

}  // namespace
}  // namespace shpack::io
