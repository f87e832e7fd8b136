// Tests of the scene loader's `settings`: the accuracy target and cap of the Monte Carlo
// effects, and probe validity's threshold, policy and reach (docs/scenes.md). Each bad value
// is a one-line error naming the file and the key.
#include <gtest/gtest.h>

#include <string>

#include "scene_files.h"
#include "shpack/scene/scene_loader.h"

namespace shpack::scene {
namespace {

std::filesystem::path with_settings(const std::string& name, const std::string& settings) {
  return shpack_test::write_scene(name + ".json",
                                  R"({"probes": [[0, 0, 0]], "effects": [], "settings": {)" + settings + "}}");
}

// The message after "<file>: ", checking that it starts with the file's path.
std::string error_of(const std::filesystem::path& path) {
  Scene scene;
  const io::IoStatus st = load_scene(path, scene);
  if (st.ok()) return "(loaded)";
  const std::string prefix = path.string() + ": ";
  EXPECT_EQ(st.message.rfind(prefix, 0), 0u) << st.message;
  EXPECT_EQ(st.message.find('\n'), std::string::npos) << "one line: " << st.message;
  return st.message.substr(prefix.size());
}

TEST(SceneSettings, DefaultsAreDocumented) {
  Scene scene;
  ASSERT_TRUE(load_scene(with_settings("defaults", ""), scene).ok());
  EXPECT_EQ(scene.settings.target_error_pct, 1.0);
  EXPECT_EQ(scene.settings.max_samples, 65536);
  EXPECT_EQ(scene.settings.validity_threshold, 0.25);
  EXPECT_EQ(scene.settings.invalid_probes, InvalidProbes::Dilate);
  EXPECT_EQ(scene.settings.max_offset, 0.2);
}

TEST(SceneSettings, ReadsEveryValue) {
  Scene scene;
  const io::IoStatus st = load_scene(with_settings("all", R"("target_error_pct": 0.5, "max_samples": 4096,
    "validity_threshold": 0.1, "invalid_probes": "offset", "max_offset": 0.75)"), scene);
  ASSERT_TRUE(st.ok()) << st.message;
  EXPECT_EQ(scene.settings.target_error_pct, 0.5);
  EXPECT_EQ(scene.settings.max_samples, 4096);
  EXPECT_EQ(scene.settings.validity_threshold, 0.1);
  EXPECT_EQ(scene.settings.invalid_probes, InvalidProbes::Offset);
  EXPECT_EQ(scene.settings.max_offset, 0.75);
  for (const auto& [text, policy] : {std::pair{"dilate", InvalidProbes::Dilate}, {"keep", InvalidProbes::Keep},
                                     {"error", InvalidProbes::Error}, {"offset", InvalidProbes::Offset}}) {
    ASSERT_TRUE(load_scene(with_settings("policy", std::string(R"("invalid_probes": ")") + text + "\""), scene).ok());
    EXPECT_EQ(scene.settings.invalid_probes, policy) << text;
  }
  // The ends of each range are allowed: 0 (fixed sample counts), 1 sample, thresholds 0 and 1,
  // no offset.
  ASSERT_TRUE(load_scene(with_settings("ends", R"("target_error_pct": 0, "max_samples": 1, "validity_threshold": 1,
    "max_offset": 0)"), scene).ok());
  EXPECT_EQ(scene.settings.target_error_pct, 0.0);
  EXPECT_EQ(scene.settings.max_samples, 1);
  EXPECT_EQ(scene.settings.validity_threshold, 1.0);
  EXPECT_EQ(scene.settings.max_offset, 0.0);
  ASSERT_TRUE(load_scene(with_settings("zero_threshold", R"("validity_threshold": 0)"), scene).ok());
  EXPECT_EQ(scene.settings.validity_threshold, 0.0);
}

TEST(SceneSettings, BadValuesNameTheFileAndTheKey) {
  const std::pair<const char*, const char*> cases[] = {
      {R"("target_error_pct": -0.5)", "settings.target_error_pct: must be >= 0"},
      {R"("target_error_pct": "1")", "settings.target_error_pct: has the wrong type"},
      {R"("max_samples": 0)", "settings.max_samples: must be >= 1"},
      {R"("max_samples": 2.5)", "settings.max_samples: has the wrong type"},
      {R"("max_samples": 16777217)", "settings.max_samples: must be <= 16777216"},
      {R"("validity_threshold": -0.1)", "settings.validity_threshold: must be >= 0"},
      {R"("validity_threshold": 1.5)", "settings.validity_threshold: must be <= 1"},
      {R"("validity_threshold": null)", "settings.validity_threshold: has the wrong type"},
      {R"("invalid_probes": "ignore")", "settings.invalid_probes: is not one of the allowed values"},
      {R"("invalid_probes": 1)", "settings.invalid_probes: is not one of the allowed values"},
      {R"("max_offset": -1)", "settings.max_offset: must be >= 0"},
      {R"("max_offset": [1])", "settings.max_offset: has the wrong type"},
  };
  for (const auto& [settings, want] : cases) EXPECT_EQ(error_of(with_settings("bad", settings)), want) << settings;
}

}  // namespace
}  // namespace shpack::scene
