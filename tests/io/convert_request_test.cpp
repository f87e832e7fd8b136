// to_convert_options (convert_request.h): the user-level options into the pipeline's, and
// the lines that name what is wrong.
#include "shpack/convert_request.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace shpack {
namespace {

TEST(ConvertRequest, DefaultsAreTheCommandLinesDefaults) {
  ConvertOptions out;
  out.threads = 7;
  ASSERT_EQ(to_convert_options(ConvertRequest{}, out), "");
  EXPECT_EQ(out.method, MethodSpec{});
  EXPECT_EQ(out.nonfinite, NonFinite::Error);
  EXPECT_EQ(out.negative, Negative::Keep);
  EXPECT_EQ(out.threads, 0u);
  EXPECT_EQ(out.finish.intensity, 1.0);
  EXPECT_EQ(out.finish.rotate_deg, 0.0);
  EXPECT_EQ(out.finish.window.kind, WindowKind::None);
  EXPECT_FALSE(out.finish.l1);
  EXPECT_FALSE(out.extract_sun);
  EXPECT_EQ(out.extract_lights, 0u);
}

TEST(ConvertRequest, EveryFieldReachesItsStage) {
  ConvertRequest request;
  request.method = "mc:512";
  request.seed = 9;
  request.nonfinite = NonFinite::Zero;
  request.negative = Negative::Clamp;
  request.intensity = 3;
  request.exposure = -2;
  request.rotate_deg = 45;
  request.window = "hanning:4";
  request.l1 = true;
  request.extract_lights = 3;
  request.threads = 2;
  ConvertOptions out;
  ASSERT_EQ(to_convert_options(request, out), "");
  EXPECT_EQ(out.method.method, SamplingMethod::MonteCarlo);
  EXPECT_EQ(out.method.param, 512u);
  EXPECT_EQ(out.method.seed, 9u);
  EXPECT_EQ(out.nonfinite, NonFinite::Zero);
  EXPECT_EQ(out.negative, Negative::Clamp);
  EXPECT_EQ(out.finish.intensity, 0.75);  // 3 * 2^-2: one factor, as the document records it
  EXPECT_EQ(out.finish.rotate_deg, 45.0);
  Window hanning;
  ASSERT_TRUE(parse_window("hanning:4", hanning).ok());
  EXPECT_EQ(out.finish.window.kind, hanning.kind);
  EXPECT_EQ(out.finish.window.width, hanning.width);
  EXPECT_TRUE(out.finish.l1);
  EXPECT_EQ(out.extract_lights, 3u);
  EXPECT_EQ(out.threads, 2u);
}

TEST(ConvertRequest, ProblemsNameTheOptionAndLeaveTheOutputAlone) {
  const auto problem = [](ConvertRequest request) {
    ConvertOptions out;
    out.threads = 42;
    const std::string line = to_convert_options(request, out);
    EXPECT_EQ(out.threads, 42u) << line;  // untouched
    return line;
  };
  ConvertRequest r;
  r.method = "fast";
  EXPECT_EQ(problem(r), "--method: 'fast': unknown method name");
  r = {};
  r.method = "mc:64:5";
  r.seed = 5;
  EXPECT_EQ(problem(r), "give the seed once, in --method or with --seed");
  r = {};
  r.intensity = -1;
  EXPECT_EQ(problem(r), "--intensity: '-1' is not a finite number >= 0");
  r = {};
  r.exposure = std::numeric_limits<double>::infinity();
  EXPECT_EQ(problem(r), "--exposure: 'inf' is not a finite number");
  r = {};
  r.rotate_deg = std::nan("");
  EXPECT_EQ(problem(r), "--rotate: 'nan' is not a finite number");
  r = {};
  r.window = "blur";
  EXPECT_EQ(problem(r).rfind("--window: ", 0), 0u);
  r = {};
  r.extract_lights = 9;
  EXPECT_EQ(problem(r), "--extract-lights: '9' is not an integer from 0 to 8");
  r = {};
  r.intensity = 1e300;
  r.exposure = 100;
  EXPECT_EQ(problem(r), "--intensity times 2^--exposure is not a finite number");
}

}  // namespace
}  // namespace shpack
