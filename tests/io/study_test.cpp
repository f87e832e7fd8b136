// The study behind `shpack bench` (bench/study): its error metrics on cases with a known
// answer, its sweeps and inputs, its fits and reports. No timing is asserted.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "io_test_files.h"
#include "shpack/convolution.h"
#include "shpack/sh_minimum.h"
#include "shpack/study/accuracy.h"
#include "shpack/study/draws.h"
#include "shpack/study/gnuplot.h"
#include "shpack/study/expected_error.h"
#include "shpack/sampling_variance.h"
#include "shpack/sampling_methods.h"
#include "shpack/study/load_average.h"
#include "shpack/study/pareto_front.h"
#include "shpack/study/method_sweep.h"
#include "shpack/study/plot.h"
#include "shpack/study/scene_study.h"
#include "shpack/study/study.h"
#include "shpack/study/study_inputs.h"
#include "shpack/study/study_report.h"

namespace shpack::study {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A positive map's radiance: L00 = 2 sqrt(pi) * mean per channel, and small other terms.
ShL2 reference_radiance() {
  ShL2 sh;
  const double means[3] = {1.0, 2.0, 0.5};
  for (int c = 0; c < kChannelCount; ++c) {
    sh.c[c][0] = 2 * std::sqrt(std::numbers::pi) * means[c];
    for (int i = 1; i < kShCount; ++i) sh.c[c][i] = 0.05 * (i % 3 - 1) * (c + 1);
  }
  return sh;
}

TEST(StudyAccuracy, FibonacciNormalsAreUnitAndCoverBothPoles) {
  const std::vector<Dir3> normals = fibonacci_normals(kAccuracyNormals);
  ASSERT_EQ(normals.size(), static_cast<std::size_t>(kAccuracyNormals));
  for (const Dir3& n : normals) EXPECT_NEAR(n.x * n.x + n.y * n.y + n.z * n.z, 1.0, 4 * kEps);
  EXPECT_DOUBLE_EQ(normals.front().y, 1.0 - 1.0 / kAccuracyNormals);
  EXPECT_DOUBLE_EQ(normals.back().y, -(1.0 - 1.0 / kAccuracyNormals));
}

TEST(StudyAccuracy, ExactAgainstItselfHasNoError) {
  const ShL2 reference = reference_radiance();
  const AccuracyMetrics m = AccuracyMeter(reference).measure(reference);
  EXPECT_EQ(m.err_max_pct, 0.0);
  EXPECT_EQ(m.err_rms_pct, 0.0);
  EXPECT_EQ(m.coef_err_max, 0.0);
  const ShL2 unity_form = radiance_to_unity_form(reference);
  double want_min = std::numeric_limits<double>::infinity();
  for (int c = 0; c < kChannelCount; ++c) want_min = std::min(want_min, minimum_on_sphere(unity_form, c).value);
  EXPECT_EQ(m.min_e_over_pi, want_min);
}

TEST(StudyAccuracy, ConstantOffsetGivesItsShareOfTheMean) {
  // Adding d to L00 of channel 2 adds C0 d to E/pi everywhere; the channel's mean is C0 L00,
  // so both errors are d / L00 exactly, and so is the coefficient error.
  const ShL2 reference = reference_radiance();
  ShL2 estimate = reference;
  const double d = 0.01;
  estimate.c[2][0] += d;
  const AccuracyMetrics m = AccuracyMeter(reference).measure(estimate);
  const double want = d / reference.c[2][0];
  EXPECT_NEAR(m.err_max_pct, 100 * want, 100 * want * 64 * kEps);
  EXPECT_NEAR(m.err_rms_pct, 100 * want, 100 * want * 64 * kEps);
  EXPECT_NEAR(m.coef_err_max, want, want * 8 * kEps);
}

TEST(StudyAccuracy, LinearOffsetFollowsTheFibonacciNormals) {
  // Adding d to L_1 (P_1 = y) of channel 0 adds C1 d y to E/pi. Over the n Fibonacci
  // normals, max |y| = 1 - 1/n and mean y^2 = (1/n) sum_k (1 - (2k+1)/n)^2 = 1/3 - 1/(3 n^2).
  const ShL2 reference = reference_radiance();
  ShL2 estimate = reference;
  const double d = 0.02;
  estimate.c[0][1] += d;
  const int n = 256;
  const AccuracyMetrics m = AccuracyMeter(reference, n).measure(estimate);
  const double mean = kC0 * reference.c[0][0];
  const double want_max = 100 * kC1 * d * (1 - 1.0 / n) / mean;
  const double want_rms = 100 * kC1 * d * std::sqrt(1.0 / 3 - 1.0 / (3.0 * n * n)) / mean;
  EXPECT_NEAR(m.err_max_pct, want_max, want_max * 1e-12);
  EXPECT_NEAR(m.err_rms_pct, want_rms, want_rms * 1e-12);
  EXPECT_NEAR(m.coef_err_max, d / reference.c[0][0], 1e-15);
}

TEST(StudyAccuracy, WorstChannelCountsAndBlackChannelsAreSkipped) {
  ShL2 reference = reference_radiance();
  reference.c[1] = {};  // a black channel has no relative error
  ShL2 estimate = reference;
  estimate.c[1][0] = 5.0;  // ignored: channel 1 has no mean
  estimate.c[0][0] += 0.01;
  estimate.c[2][0] += 0.01;  // channel 2's mean is half of channel 0's: twice the error
  const AccuracyMetrics m = AccuracyMeter(reference).measure(estimate);
  EXPECT_NEAR(m.err_max_pct, 100 * 0.01 / reference.c[2][0], 1e-12);

  const AccuracyMetrics black = AccuracyMeter(ShL2{}).measure(estimate);
  EXPECT_TRUE(std::isnan(black.err_max_pct));
  EXPECT_TRUE(std::isnan(black.err_rms_pct));
  EXPECT_TRUE(std::isnan(black.coef_err_max));
}

TEST(StudySweep, MethodListsExpandNamesAndKeepSpecs) {
  std::vector<MethodSpec> specs;
  ASSERT_TRUE(parse_method_list("exact,mc,mip:2,qmc:100:9", /*quick=*/true, 7, specs).ok());
  ASSERT_EQ(specs.size(), 1u + 3u + 1u + 1u);
  EXPECT_EQ(specs[0], (MethodSpec{SamplingMethod::Exact, 0, 7}));  // the seed is carried, unused
  EXPECT_EQ(specs[1], (MethodSpec{SamplingMethod::MonteCarlo, 64, 7}));
  EXPECT_EQ(specs[3], (MethodSpec{SamplingMethod::MonteCarlo, 16384, 7}));
  EXPECT_EQ(specs[4].method, SamplingMethod::Mip);
  EXPECT_EQ(specs[4].param, 2u);
  EXPECT_EQ(specs[5], (MethodSpec{SamplingMethod::QuasiMonteCarlo, 100, 9}));  // its own seed wins

  const std::vector<MethodSpec> before = specs;
  for (const char* bad : {"", "mc,", ",mc", "fast", "mc:0", "exact:1"})
    EXPECT_FALSE(parse_method_list(bad, false, 7, specs).ok()) << bad;
  EXPECT_EQ(specs, before);  // unchanged on failure
}

TEST(StudySweep, EveryMethodSpansDecadesOfCost) {
  for (const bool quick : {false, true}) {
    const std::vector<MethodSpec> specs = full_sweep(quick, kDefaultMethodSeed);
    for (const MethodSpec& spec : specs) EXPECT_TRUE(validate_method(spec).ok()) << method_name(spec).c_str();
    for (const SamplingMethod m : {SamplingMethod::MonteCarlo, SamplingMethod::Riemann, SamplingMethod::Mip}) {
      const std::vector<MethodSpec> sweep = method_sweep(m, quick, kDefaultMethodSeed);
      const double cheapest = sample_count(sweep.front(), 1024, 512);
      const double dearest = sample_count(sweep.back(), 1024, 512);
      EXPECT_GE(dearest / cheapest, quick ? 100 : 1000) << family_name(m);
    }
  }
  EXPECT_EQ(sample_count({SamplingMethod::CubeExact, 8}, 1024, 512), 6 * 64);
  EXPECT_EQ(sample_count({SamplingMethod::Mip, 3}, 1024, 512), 128 * 64);
  EXPECT_EQ(family_name(SamplingMethod::CubeExact), "cube-exact");
}

TEST(StudyInputs, SyntheticMapsAreEquirectAndPositive) {
  for (const std::string& name : synthetic_map_names()) {
    StudyImage image;
    ASSERT_TRUE(load_study_input(name, image).ok()) << name;
    EXPECT_EQ(image.name, name);
    EXPECT_EQ(image.width, kSyntheticWidth);
    EXPECT_EQ(image.height, kSyntheticWidth / 2);
    ASSERT_EQ(image.pixels.size(), std::size_t{3} * image.width * image.height);
    for (const float v : image.pixels) ASSERT_GT(v, 0.0f) << name;
  }
  StudyImage image;
  ASSERT_TRUE(load_study_input("synthetic:texel", image).ok());
  EXPECT_EQ(*std::max_element(image.pixels.begin(), image.pixels.end()), 1e6f);
  ASSERT_TRUE(load_study_input("synthetic:sun", image).ok());
  // The disc (6.7e-5 sr) over texels of (2 pi / 1024)^2 sin(55 deg) = 3.1e-5 sr: its
  // coverage sums to about two texels' worth.
  double sun_texels = 0;
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) sun_texels += image.pixels[i] > 1 ? image.pixels[i] / 1e5 : 0;
  EXPECT_GT(sun_texels, 1.0);
  EXPECT_LT(sun_texels, 3.0);
  EXPECT_EQ(load_study_input("synthetic:nothing", image).code, io::IoErrc::InvalidArgument);
}

TEST(StudyInputs, BundledMapsAreTheDataVariableOrTheInstalledFolder) {
  namespace fs = std::filesystem;
  const shpack_io_test::ScratchDir dir;
  const fs::path exe = dir / "bin" / "shpack";  // need not exist: only its folder counts
  EXPECT_EQ(find_bundled_maps(nullptr, exe), fs::path());  // nothing installed, no variable
  EXPECT_EQ(find_bundled_maps(nullptr, {}), fs::path());
  const fs::path installed = dir / "share" / "shpack" / "hdri";
  fs::create_directories(installed);
  EXPECT_EQ(find_bundled_maps(nullptr, exe), installed);
  EXPECT_EQ(find_bundled_maps("", exe), installed);
  EXPECT_EQ(find_bundled_maps((dir / "missing").c_str(), exe), installed);  // not a folder
  const fs::path own = dir / "maps";
  fs::create_directories(own);
  EXPECT_EQ(find_bundled_maps(own.c_str(), exe), own);  // the variable wins
  EXPECT_EQ(find_bundled_maps(own.c_str(), {}), own);

  // default_inputs: the folder's *.exr sorted by name, then the synthetic maps; a missing or
  // empty folder gives the synthetic maps alone.
  for (const char* name : {"b.exr", "a.exr", "notes.txt"}) std::ofstream(own / name) << "x";
  std::vector<std::string> expected = {(own / "a.exr").string(), (own / "b.exr").string()};
  for (const std::string& name : synthetic_map_names()) expected.push_back(name);
  EXPECT_EQ(default_inputs(own), expected);
  EXPECT_EQ(default_inputs(installed), synthetic_map_names());
  EXPECT_EQ(default_inputs(fs::path()), synthetic_map_names());
}

TEST(StudyRun, ExactIsTheReferenceAndEveryRecordIsFilled) {
  StudyImage image{"tiny", 16, 8, 3, std::vector<float>(16 * 8 * 3, 1.0f)};
  image.pixels[3 * (3 * 16 + 5)] = 50.0f;
  const std::vector<MethodSpec> specs = {MethodSpec{}, {SamplingMethod::Center}, {SamplingMethod::Fibonacci, 64}};
  std::vector<StudyRecord> records;
  std::size_t calls = 0;
  ASSERT_TRUE(run_study(image, specs, {3, 1}, records,
                        [&](const StudyRecord&, std::size_t done, std::size_t total) {
                          EXPECT_EQ(done, ++calls);
                          EXPECT_EQ(total, specs.size());
                        })
                  .ok());
  ASSERT_EQ(records.size(), specs.size());
  EXPECT_EQ(calls, specs.size());
  EXPECT_EQ(records[0].accuracy.err_max_pct, 0.0);
  EXPECT_GT(records[2].accuracy.err_max_pct, 0.0);
  for (const StudyRecord& r : records) {
    EXPECT_EQ(r.input, "tiny");
    EXPECT_EQ(r.repeats, 3u);
    EXPECT_EQ(r.threads, 1u);
    EXPECT_LE(r.time_ms_min, r.time_ms_median);
    EXPECT_LE(r.time_ms_median, r.time_ms_max);
  }
  EXPECT_EQ(run_study(image, specs, {0, 1}, records).code, io::IoErrc::InvalidArgument);
}

TEST(StudyDraws, RmsAndQuantilesOfKnownValues) {
  // rms{3, 4} = sqrt((9 + 16) / 2); type-7 quantiles of 1..10: rank h = 9 p, so
  // p = 0.1 -> 1 + 0.9 (2 - 1) = 1.9 and p = 0.9 -> 9 + 0.1 (10 - 9) = 9.1.
  EXPECT_NEAR(rms({3, 4}), std::sqrt(12.5), 2 * kEps * std::sqrt(12.5));
  const std::vector<double> ten = {10, 9, 8, 7, 6, 5, 4, 3, 2, 1};
  EXPECT_NEAR(quantile(ten, 0.1), 1.9, 4 * kEps);
  EXPECT_NEAR(quantile(ten, 0.9), 9.1, 16 * kEps);
  EXPECT_EQ(quantile(ten, 0.0), 1.0);
  EXPECT_EQ(quantile(ten, 1.0), 10.0);
  EXPECT_EQ(quantile({5}, 0.1), 5.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(rms({1, nan})));
  EXPECT_TRUE(std::isnan(quantile({1, nan}, 0.5)));
  EXPECT_TRUE(std::isnan(rms({})));

  // One draw is its own summary; several: RMS errors, the lowest minimum, the spread.
  const AccuracyMetrics a{2, 1, 0.5, -0.25}, b{4, 3, 1.5, 0.75};
  const DrawSummary one = summarize_draws({a});
  EXPECT_EQ(one.accuracy.err_max_pct, 2.0);
  EXPECT_EQ(one.accuracy.min_e_over_pi, -0.25);
  EXPECT_EQ(one.err_max.p10, 2.0);
  EXPECT_EQ(one.err_max.p90, 2.0);
  const DrawSummary two = summarize_draws({a, b});
  EXPECT_NEAR(two.accuracy.err_max_pct, std::sqrt(10.0), 4 * kEps * std::sqrt(10.0));
  EXPECT_NEAR(two.accuracy.err_rms_pct, std::sqrt(5.0), 4 * kEps * std::sqrt(5.0));
  EXPECT_NEAR(two.accuracy.coef_err_max, std::sqrt(1.25), 4 * kEps * std::sqrt(1.25));
  EXPECT_EQ(two.accuracy.min_e_over_pi, -0.25);
  EXPECT_NEAR(two.err_max.p10, 2.2, 8 * kEps);  // h = 0.1: 2 + 0.1 (4 - 2)
  EXPECT_NEAR(two.err_rms.p90, 2.8, 8 * kEps);  // h = 0.9: 1 + 0.9 (3 - 1)
}

// rms_interval: mean of v^2 +- 1.96 sd(v^2)/sqrt(n), then square roots. For v = 1, 3:
// v^2 = 1, 9, mean 5, sd sqrt(32), half-width 1.96 sqrt(32)/sqrt(2) = 7.84.
TEST(StudyDraws, RmsIntervalIsTheMeanSquaresNormalInterval) {
  const Interval i = rms_interval({1, 3});
  EXPECT_EQ(i.low, 0.0);  // 5 - 7.84 < 0, clamped
  EXPECT_NEAR(i.high, std::sqrt(12.84), 1e-14);
  EXPECT_NEAR(relative_half_width(i, std::sqrt(5.0)), std::sqrt(12.84) / (2 * std::sqrt(5.0)), 1e-14);
  EXPECT_TRUE(std::isnan(rms_interval({2}).low));
}

// The closed-form expected RMS error of mc (expected_error.h) against the RMS over draws of
// the meter's err_rms_pct on a grey map (channels equal, so the worst channel is any one):
// E[err_rms_pct^2] is the expected mean square, up to the 1024 normals standing for the
// sphere (a degree-4 polynomial, quadrature error well under 1%). Over M draws the mean of
// e^2 has standard error sd(e^2)/sqrt(M), estimated from the draws: within 5 of them plus 1%.
TEST(StudyExpectedError, ClosedFormMatchesTheDrawsOfMc) {
  std::vector<float> pixels(64 * 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) pixels[y * 64 + x] = 0.5f + 0.02f * float(x % 7 + y);
  pixels[10 * 64 + 20] = 40.0f;
  const ImageView view = make_view(pixels.data(), 64, 32, 1);
  ProjectOptions options;
  ShL2 reference, variance;
  ASSERT_TRUE(project_with_method(view, MethodSpec{}, options, reference).ok());
  ASSERT_TRUE(sample_variance(view, SamplingMethod::MonteCarlo, options, variance).ok());
  constexpr std::uint32_t kN = 256;
  constexpr int kDraws = 600;
  const AccuracyMeter meter(reference);
  double sum = 0, sum_sq = 0;
  for (int k = 0; k < kDraws; ++k) {
    ShL2 radiance;
    ASSERT_TRUE(project_with_method(view, {SamplingMethod::MonteCarlo, kN, 100u + k}, options, radiance).ok());
    const double e2 = std::pow(meter.measure(radiance).err_rms_pct, 2);
    sum += e2;
    sum_sq += e2 * e2;
  }
  const double mean = sum / kDraws, sd = std::sqrt((sum_sq / kDraws - mean * mean) * kDraws / (kDraws - 1));
  const double expected = std::pow(expected_rms_pct(variance, kN, reference), 2);
  EXPECT_NEAR(mean, expected, 5 * sd / std::sqrt(double(kDraws)) + 0.01 * expected);
  EXPECT_LT(5 * sd / std::sqrt(double(kDraws)), 0.25 * expected);  // a factor 4/3 off fails
}

TEST(StudyDraws, LoadAverageIsTheFirstThreeNumbers) {
  const std::array<double, 3> load = parse_load_average("0.25 1.07 11.5 1/81 5810\n");
  EXPECT_EQ(load[0], 0.25);
  EXPECT_EQ(load[1], 1.07);
  EXPECT_EQ(load[2], 11.5);
  const std::array<double, 3> part = parse_load_average("2.5 x");
  EXPECT_EQ(part[0], 2.5);
  EXPECT_TRUE(std::isnan(part[1]));
  EXPECT_TRUE(std::isnan(part[2]));
  EXPECT_TRUE(std::isnan(parse_load_average("")[0]));
}

// A smooth 64 x 32 map: cheap to sample under ASan, and every method converges on it.
StudyImage smooth_map() {
  StudyImage image{"smooth", 64, 32, 3, std::vector<float>(64 * 32 * 3)};
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = 1.0f + 0.5f * float(i % 7) / 7;
  return image;
}

TEST(StudyRun, RandomMethodsAreMeasuredOverTheirSeedsAndTheOthersOnce) {
  const StudyImage image = smooth_map();
  const MethodSpec mc{SamplingMethod::MonteCarlo, 256, 40};
  std::vector<StudyRecord> records;
  ASSERT_TRUE(run_study(image, {mc, {SamplingMethod::Fibonacci, 256}}, {1, 1, 4}, records).ok());
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].seeds, 4u);
  EXPECT_EQ(records[1].seeds, 1u);
  EXPECT_EQ(records[0].spec, mc);  // the first seed names the record
  // The same four draws one at a time, seeds 40..43: their RMS and their extremes.
  std::vector<double> err_max;
  for (std::uint64_t k = 0; k < 4; ++k) {
    std::vector<StudyRecord> one;
    ASSERT_TRUE(run_study(image, {{SamplingMethod::MonteCarlo, 256, 40 + k}}, {1, 1, 1}, one).ok());
    err_max.push_back(one[0].accuracy.err_max_pct);
  }
  const double want = rms(err_max);
  EXPECT_NEAR(records[0].accuracy.err_max_pct, want, 4 * kEps * want);
  EXPECT_GE(records[0].err_max_spread.p10, *std::min_element(err_max.begin(), err_max.end()));
  EXPECT_LE(records[0].err_max_spread.p90, *std::max_element(err_max.begin(), err_max.end()));
  EXPECT_LT(records[0].err_max_spread.p10, records[0].err_max_spread.p90) << "four different draws";
  EXPECT_EQ(records[1].err_max_spread.p10, records[1].accuracy.err_max_pct);
  EXPECT_EQ(run_study(image, {mc}, {1, 1, 0}, records).code, io::IoErrc::InvalidArgument);
}

TEST(StudyRun, ExpectedErrorOfMonteCarloFallsAsNToTheMinusHalf) {
  // mc is unbiased, so its RMS error over seeds is sqrt(variance / N) exactly: slope -1/2.
  // Estimated from R = 16 draws, e^2 (a sum of squared Gaussian-like errors, at worst one
  // chi-square degree of freedom, relative sd sqrt 2) has relative sd <= sqrt(2 / 16), so the
  // RMS e has <= 0.18, i.e. sd 0.18 in log e. The least-squares slope over 4 points spaced
  // ln 4 apart has sd 0.18 / sqrt(sum (x - mean)^2) = 0.18 / (ln 4 sqrt 5) = 0.058; 4 sd: 0.23.
  const StudyImage image = smooth_map();
  std::vector<MethodSpec> specs;
  for (const std::uint32_t n : {64u, 256u, 1024u, 4096u}) specs.push_back({SamplingMethod::MonteCarlo, n, 1});
  std::vector<StudyRecord> records;
  ASSERT_TRUE(run_study(image, specs, {1, 1, 16}, records).ok());
  const std::vector<ConvergenceFit> fits = convergence_fits(records);
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_NEAR(fits[0].slope, -0.5, 0.23);
}

// Records whose error falls exactly as samples^-1/2 (Monte Carlo) and samples^-1 (a grid).
std::vector<StudyRecord> power_law_records() {
  std::vector<StudyRecord> records;
  for (const double n : {64.0, 256.0, 1024.0, 4096.0}) {
    StudyRecord mc;
    mc.input = "a";
    mc.spec = {SamplingMethod::MonteCarlo, static_cast<std::uint32_t>(n)};
    mc.samples = n;
    mc.time_ms_median = n * 1e-4;
    mc.accuracy.err_max_pct = 300 / std::sqrt(n);
    mc.accuracy.err_rms_pct = 100 / std::sqrt(n);
    mc.expected_err_rms_pct = 100 / std::sqrt(n);  // the fits read the expected error
    StudyRecord grid = mc;
    grid.spec = {SamplingMethod::Riemann, static_cast<std::uint32_t>(n)};
    grid.accuracy.err_max_pct = 3000 / n;
    grid.accuracy.err_rms_pct = 1000 / n;
    grid.expected_err_rms_pct = 1000 / n;
    records.push_back(mc);
    records.push_back(grid);
  }
  return records;
}

TEST(StudyReport, ConvergenceSlopesRecoverPowerLaws) {
  const std::vector<ConvergenceFit> fits = convergence_fits(power_law_records());
  ASSERT_EQ(fits.size(), 2u);
  EXPECT_EQ(fits[0].method, SamplingMethod::MonteCarlo);
  EXPECT_NEAR(fits[0].slope, -0.5, 1e-12);
  EXPECT_EQ(fits[0].points, 4);
  EXPECT_EQ(fits[1].method, SamplingMethod::Riemann);
  EXPECT_NEAR(fits[1].slope, -1.0, 1e-12);
}

// The front keeps a point only if it beats every faster one; NaN errors are left out.
TEST(StudyReport, ParetoFrontKeepsWhatNoFasterPointBeats) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<FrontPoint> front = pareto_front({{"slow-good", 10, 0.1, "exact"},
                                                      {"fast-bad", 1, 5, "exact"},
                                                      {"mid-worse", 5, 6, "sampled"},
                                                      {"mid-better", 5, 2, "exact"},
                                                      {"black", 0.5, nan, "exact"}});
  ASSERT_EQ(front.size(), 3u);
  EXPECT_EQ(front[0].spec, "fast-bad");
  EXPECT_EQ(front[1].spec, "mid-better");
  EXPECT_EQ(front[2].spec, "slow-good");
}

TEST(StudyReport, SummaryTakesTheWorstAndTheMedianInput) {
  std::vector<StudyRecord> records;
  for (const auto& [input, time, err] : {std::tuple{"a", 1.0, 2.0}, {"b", 3.0, 8.0}, {"c", 2.0, 4.0}}) {
    StudyRecord r;
    r.input = input;
    r.spec = {SamplingMethod::Fibonacci, 64};
    r.time_ms_median = time;
    r.accuracy.err_max_pct = err;
    r.accuracy.err_rms_pct = err / 2;
    records.push_back(r);
  }
  const std::vector<SpecSummary> summary = summarize(records);
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_EQ(summary[0].inputs, 3);
  EXPECT_EQ(summary[0].time_ms, 2.0);
  EXPECT_EQ(summary[0].err_max_pct, 8.0);
  EXPECT_EQ(summary[0].err_rms_pct, 2.0);
}

TEST(StudyReport, JsonWritesEveryKeyAndNaNAsNull) {
  std::vector<StudyRecord> records = power_law_records();
  records[0].accuracy.err_max_pct = std::numeric_limits<double>::quiet_NaN();
  const nlohmann::json j = nlohmann::json::parse(json_report(records));
  ASSERT_EQ(j.size(), records.size());
  EXPECT_TRUE(j[0]["err_max_pct"].is_null());
  EXPECT_EQ(j[0]["method"], "mc");
  EXPECT_EQ(j[0]["param"], 64);
  EXPECT_EQ(j[0]["seed"], kDefaultMethodSeed);
  EXPECT_TRUE(j[1]["seed"].is_null());  // riemann takes no seed
  for (const char* key : {"seeds", "err_max_pct_p10", "err_max_pct_p90", "err_rms_pct_p10", "err_rms_pct_p90"})
    EXPECT_TRUE(j[1].contains(key)) << key;
  EXPECT_EQ(j[1]["seeds"], 1);
  ASSERT_TRUE(j[1]["load_average"].is_array());
  EXPECT_EQ(j[1]["load_average"].size(), 3u);
}

TEST(StudyReport, PlotScriptDrawsEachMethodTheFrontAndExact) {
  std::vector<StudyRecord> records = power_law_records();
  StudyRecord exact;
  exact.input = "a";
  exact.time_ms_median = 0.2;
  records.push_back(exact);
  const std::string gp = plot_script(records, "it's.png", "out.svg");
  EXPECT_NE(gp.find("set output 'it''s.png'"), std::string::npos) << gp;  // gnuplot's quote escape
  EXPECT_NE(gp.find("set output 'out.svg'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set ylabel 'expected RMS error of E/pi"), std::string::npos) << gp;
  EXPECT_NE(gp.find("title 'mc (closed form)'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("title 'riemann'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("title 'Pareto front'"), std::string::npos) << gp;
  EXPECT_NE(gp.find("'exact (error 0)'"), std::string::npos) << gp;
  EXPECT_EQ(gp.find("filledcurves"), std::string::npos) << "no sampled method: no interval to draw";
  EXPECT_EQ(gp.find("using 1:5"), std::string::npos) << "one draw each: no draws to check against";
}

// The rows of the gnuplot data block NAME (between "NAME << EOD" and "EOD"), as numbers.
std::vector<std::vector<double>> data_rows(const std::string& gp, const std::string& name) {
  const std::string head = name + " << EOD\n";
  std::size_t at = gp.find(head);
  std::vector<std::vector<double>> rows;
  if (at == std::string::npos) return rows;
  at += head.size();
  const std::string block = gp.substr(at, gp.find("EOD\n", at) - at);
  std::istringstream lines(block);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    std::vector<double> row;
    for (double v; fields >> v;) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

std::string method_block(SamplingMethod method) { return "$m" + std::to_string(static_cast<int>(method)); }

// gnuplot_number writes 9 significant digits: a value read back is within half a unit of the
// 9th, 5e-9 relative.
constexpr double kPrinted = 5e-9;

// On a real study, mc's line is the closed form the record holds (not its draws, drawn as
// the open points), so consecutive 4x sample counts halve it: slope -0.5 up to the printing.
TEST(StudyReport, PlotOfMcIsItsClosedFormExpectedError) {
  const StudyImage image = smooth_map();
  std::vector<MethodSpec> specs;
  for (const std::uint32_t n : {64u, 256u, 1024u}) specs.push_back({SamplingMethod::MonteCarlo, n, 1});
  std::vector<StudyRecord> records;
  ASSERT_TRUE(run_study(image, specs, {1, 1, 4}, records).ok());
  const std::string gp = plot_script(records, "a.png", "a.svg");
  const std::vector<std::vector<double>> rows = data_rows(gp, method_block(SamplingMethod::MonteCarlo));
  ASSERT_EQ(rows.size(), records.size()) << gp;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 5u) << gp;
    ASSERT_EQ(records[k].err_rms_kind, ErrorKind::Exact);
    EXPECT_NEAR(rows[k][1], records[k].expected_err_rms_pct, kPrinted * records[k].expected_err_rms_pct);
    EXPECT_NEAR(rows[k][4], records[k].accuracy.err_rms_pct, kPrinted * records[k].accuracy.err_rms_pct);
    if (k > 0) {
      EXPECT_NEAR(rows[k - 1][1] / rows[k][1], 2.0, 2 * 2 * kPrinted);
    }
  }
  EXPECT_NE(gp.find(method_block(SamplingMethod::MonteCarlo) + " using 1:5 with points"), std::string::npos) << gp;
  EXPECT_EQ(gp.find("filledcurves"), std::string::npos) << "a closed form has no interval\n" << gp;
}

TEST(StudyReport, PlotDrawsASampledMethodDashedInItsInterval) {
  std::vector<StudyRecord> records = power_law_records();
  for (StudyRecord& r : records) {
    if (r.spec.method != SamplingMethod::MonteCarlo) continue;
    r.spec.method = SamplingMethod::QuasiMonteCarlo;
    r.seeds = 16;
    r.err_rms_kind = ErrorKind::Sampled;
    r.err_rms_interval = {0.5 * r.expected_err_rms_pct, 2 * r.expected_err_rms_pct};
  }
  const std::string gp = plot_script(records, "a.png", "a.svg");
  // qmc:64's row: time, expected error, its interval, the draws' RMS (here the same number).
  EXPECT_NE(gp.find("\n0.0064 12.5 6.25 25 12.5\n"), std::string::npos) << gp;
  const std::size_t band = gp.find("using 1:3:4 with filledcurves");
  ASSERT_NE(band, std::string::npos) << gp;
  const std::size_t line = gp.find("dt 2 lc rgb");
  ASSERT_NE(line, std::string::npos) << gp;
  EXPECT_LT(band, line) << "the band under the line\n" << gp;
  EXPECT_NE(gp.find("title 'qmc (sampled)'"), std::string::npos) << gp;
  EXPECT_EQ(gp.find("using 1:3:4", band + 1), std::string::npos) << "only qmc has a band\n" << gp;
  EXPECT_EQ(gp.find("dt 2 lc", line + 1), std::string::npos) << "only qmc is dashed\n" << gp;
}

// Two inputs: the plot's front is the report's (median time, median expected error), not one
// of its own: fib:64 has the least err_max but it does not count; fib:256 and fib:1024 tie in
// median time (4) and the lower expected error (3) stays; qmc:256 loses to the faster fib:1024;
// exact (error 0) ends the staircase at its time.
TEST(StudyReport, PlotFrontIsTheReportsFrontOverTheInputs) {
  std::vector<StudyRecord> records;
  const auto add = [&](const char* input, MethodSpec spec, double time, double expected, ErrorKind kind) {
    StudyRecord r;
    r.input = input;
    r.spec = spec;
    r.samples = spec.param;
    r.time_ms_median = time;
    r.expected_err_rms_pct = expected;
    r.accuracy.err_rms_pct = expected;
    r.accuracy.err_max_pct = spec.param == 64 ? 0.001 : 3 * expected;
    r.err_rms_kind = kind;
    records.push_back(r);
  };
  for (const auto& [input, i] : {std::pair{"a", 0}, {"b", 1}}) {
    add(input, {SamplingMethod::Fibonacci, 64}, 1 + 2 * i, 10 + 10 * i, ErrorKind::Exact);
    add(input, {SamplingMethod::Fibonacci, 256}, 4, 4 + 2 * i, ErrorKind::Exact);
    add(input, {SamplingMethod::Fibonacci, 1024}, 3 + 2 * i, 2 + 2 * i, ErrorKind::Exact);
    add(input, {SamplingMethod::QuasiMonteCarlo, 256}, 6, 3.5, ErrorKind::Sampled);
    add(input, {SamplingMethod::Exact, 0}, 10, 0, ErrorKind::Exact);
  }
  const std::vector<FrontPoint> front = expected_error_front(records);
  ASSERT_EQ(front.size(), 3u);
  EXPECT_EQ(front[0].spec, "fib:64");
  EXPECT_EQ(front[1].spec, "fib:1024");
  EXPECT_EQ(front[2].spec, "exact");
  const std::string gp = plot_script(records, "a.png", "a.svg");
  EXPECT_NE(gp.find("$front << EOD\n2 15\n4 3\n10 3\nEOD\n"), std::string::npos) << gp;
  EXPECT_NE(gp.find("$front << EOD\n" + gnuplot_front_rows(front) + "EOD\n"), std::string::npos) << gp;
  const std::string md = markdown_report(records);
  EXPECT_NE(md.find("All inputs (median time, median expected error):\n\n| at ms | method | expected err rms % | kind |\n"
                    "|---:|---|---:|---|\n| 2 | fib:64 | 15 | exact |\n| 4 | fib:1024 | 3 | exact |\n"
                    "| 10 | exact | 0 | exact |\n\n"),
            std::string::npos)
      << md;
  // The summary's row of qmc:256: the median expected error (3.5 on both) and its kind, then
  // the draws' worst max (3 x 3.5) and median RMS.
  EXPECT_NE(md.find("| qmc:256 | 256 | 1 | 6 | 3.5 | sampled | 10.5 | - | 3.5 |"), std::string::npos) << md;
}

// One scene panel by hand: (estimator, samples, CPU ms, error %, estimate %).
std::vector<SceneStudyRecord> scene_records() {
  std::vector<SceneStudyRecord> records;
  const std::tuple<const char*, double, double, double, double> rows[] = {
      {"next-events", 64, 2, 30, 40},  {"next-events", 256, 4, 10, 20}, {"directions", 64, 1.5, 35, 50},
      {"directions", 256, 4, 12, 20},  {"directions", 1024, 5, 11, 15}, {"settings", 3000, 8, 1, 2}};
  for (const auto& [estimator, samples, cpu, err, estimate] : rows) {
    SceneStudyRecord r;
    r.scene = "outdoor.json";
    r.receivers = "probes";
    r.count = 9;
    r.effect = "bounce";
    r.estimator = estimator;
    r.samples = samples;
    r.seeds = 4;
    r.cpu_ms = cpu;
    r.err_max_pct = err;
    r.err_worst_pct = 1.2 * err;
    r.estimate_pct = estimate;
    records.push_back(r);
  }
  SceneStudyRecord exact = records.front();  // an effect exact at every probe: error and estimate 0
  exact.effect = "shadows";
  exact.err_max_pct = exact.err_worst_pct = exact.estimate_pct = 0;
  records.push_back(exact);
  return records;
}

// The front: directions:64 (fastest), next-events:64, next-events:256 (ties directions:256
// in time with less error), settings; directions:1024 loses to the faster next-events:256.
TEST(SceneStudyReport, FrontRowsAreTheParetoOptimalRecords) {
  const std::string md = scene_markdown_report(scene_records());
  EXPECT_NE(md.find("| error estimate % | measured / estimate | reference's estimate % |"), std::string::npos) << md;
  EXPECT_NE(md.find("| outdoor.json | 9 probes | bounce | settings | 3000 | 8 | 1 | 1.2 | 2 | 0.5 | 0 | 4 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("outdoor.json, probes: bounce\n\n"
                    "| at CPU ms | estimator | samples/receiver | error % | kind | seeds | measured / estimate |\n"
                    "|---:|---|---:|---:|---|---:|---:|\n"
                    "| 1.5 | directions | 64 | 35 | sampled | 4 | 0.7 |\n"
                    "| 2 | next-events | 64 | 30 | sampled | 4 | 0.75 |\n"
                    "| 4 | next-events | 256 | 10 | sampled | 4 | 0.5 |\n"
                    "| 8 | settings | 3000 | 1 | sampled | 4 | 0.5 |\n\n"),
            std::string::npos)
      << md;
  // The exact effect: its fastest record alone, with no estimate to compare.
  EXPECT_NE(md.find("outdoor.json, probes: shadows\n\n"), std::string::npos) << md;
  EXPECT_NE(md.find("|\n| 2 | next-events | 64 | 0 | sampled | 4 | n/a |\n\n"), std::string::npos) << md;
}

TEST(SceneStudyReport, JsonMarksTheFrontAndKeepsEveryKey) {
  const std::vector<SceneStudyRecord> records = scene_records();
  const nlohmann::json j = nlohmann::json::parse(scene_json_report(records));
  ASSERT_EQ(j.size(), records.size());
  const bool want_front[] = {true, true, true, false, false, true, true};
  for (std::size_t k = 0; k < records.size(); ++k) {
    for (const char* key : {"scene", "receivers", "count", "effect", "estimator", "samples", "seeds", "cpu_ms",
                            "err_max_pct", "err_worst_pct", "error_estimate_pct", "reference_estimate_pct",
                            "receivers_per_s", "measured_over_estimate", "error_kind", "on_front"})
      EXPECT_TRUE(j[k].contains(key)) << k << " " << key;
    EXPECT_EQ(j[k]["on_front"], want_front[k]) << k;
    EXPECT_EQ(j[k]["error_kind"], "sampled");
  }
  EXPECT_DOUBLE_EQ(j[2]["measured_over_estimate"].get<double>(), 35.0 / 50.0);
  EXPECT_TRUE(j[6]["measured_over_estimate"].is_null()) << "no estimate to compare";
}

// Each panel draws its front first, the same points as the report's rows; the exact effect
// (error 0 on a log axis) has no panel.
TEST(SceneStudyReport, PlotDrawsEachPanelsFront) {
  const std::string gp = scene_plot_script(scene_records(), "a.png", "a.svg");
  const std::size_t plot = gp.find("plot '-' with steps lw 8 lc rgb '#c8c8c8' title 'Pareto front', ");
  ASSERT_NE(plot, std::string::npos) << gp;
  EXPECT_NE(gp.find("\n1.5 35\n2 30\n4 10\n8 1\ne\n", plot), std::string::npos) << gp;
  EXPECT_EQ(gp.find("shadows"), std::string::npos) << gp;
}

}  // namespace
}  // namespace shpack::study
