// One map to one document: what convert_env_map puts in it.
#include "shpack/io/convert.h"

#include <gtest/gtest.h>

#include <limits>

#include "io_test_files.h"
#include "shpack/convolution.h"
#include "shpack/io/sha256.h"
#include "shpack/sh_minimum.h"

namespace shpack::io {
namespace {

using shpack_io_test::hdri;

ShDocument convert(const std::filesystem::path& path, const ConvertSettings& settings = {}) {
  ShDocument doc;
  const IoStatus st = convert_env_map(path, settings, doc);
  EXPECT_TRUE(st.ok()) << st.message;
  return doc;
}

TEST(Convert, DocumentDescribesTheSource) {
  const std::filesystem::path path = hdri("courtyard.exr");
  const ShDocument doc = convert(path);
  std::string digest;
  ASSERT_TRUE(sha256_file(path, digest).ok());
  EXPECT_EQ(doc.source.files, std::vector<std::string>{"courtyard.exr"});  // no folders
  EXPECT_EQ(doc.source.sha256, std::vector<std::string>{digest});
  EXPECT_EQ(doc.source.layout, Layout::Equirect);
  EXPECT_EQ(doc.source.width, 1024u);
  EXPECT_EQ(doc.source.height, 512u);
  EXPECT_EQ(doc.method, MethodSpec{});  // exact
  EXPECT_EQ(doc.intensity, 1.0);
  // data/hdri/README.md: courtyard has small negative texels from lossy compression.
  EXPECT_GT(doc.texels.negative_texels, 0u);
  EXPECT_EQ(doc.texels.nonfinite_texels, 0u);
  EXPECT_EQ(doc.reading.ignored_channels, 0u);
}

TEST(Convert, UnityFormAndMinimumFollowFromTheRadiance) {
  const ShDocument doc = convert(hdri("courtyard.exr"));
  EXPECT_EQ(doc.sh.unity_form, radiance_to_unity_form(doc.sh.radiance));
  for (int c = 0; c < kChannelCount; ++c) {
    const SphereMinimum want = minimum_on_sphere(doc.sh.unity_form, c);
    EXPECT_EQ(doc.sh.min_e_over_pi[c].value, want.value) << "c=" << c;
    EXPECT_EQ(doc.sh.min_e_over_pi[c].direction, want.direction) << "c=" << c;
  }
}

TEST(Convert, IntensityScalesTheRadiance) {
  const std::filesystem::path path = hdri("studio.exr");
  const ShDocument plain = convert(path);
  ConvertSettings doubled;
  doubled.convert.finish.intensity = 2.0;  // a power of two: every coefficient doubles exactly
  const ShDocument twice = convert(path, doubled);
  EXPECT_EQ(twice.intensity, 2.0);
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i)
      EXPECT_EQ(twice.sh.radiance.c[c][i], 2.0 * plain.sh.radiance.c[c][i]) << "c=" << c << " i=" << i;
}

TEST(Convert, BadIntensityIsRefused) {
  for (const double bad : {-1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    ConvertSettings settings;
    settings.convert.finish.intensity = bad;
    ShDocument doc;
    EXPECT_EQ(convert_env_map(hdri("studio.exr"), settings, doc).code, IoErrc::InvalidArgument) << bad;
  }
}

TEST(Convert, TooBrightForFloatIsRefused) {
  ConvertSettings settings;
  settings.convert.finish.intensity = 1e300;  // far beyond float32 (3.4e38) for any map that is not black
  ShDocument doc;
  const IoStatus st = convert_env_map(hdri("studio.exr"), settings, doc);
  EXPECT_EQ(st.code, IoErrc::Unsupported) << st.message;
}

}  // namespace
}  // namespace shpack::io
