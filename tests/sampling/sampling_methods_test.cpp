// sampling_methods_test.cpp - the methods of sampling_methods.h against SamplingMethod::Exact.
//
// Every method reads the piecewise-constant image that `exact` integrates, so `exact` of
// the same image is the reference throughout. Errors are the Euclidean norm of the
// difference over all 27 radiance coefficients (3 channels x 9). Inputs are synthetic (fast
// under ASan): a smooth map, and a stand-in for a real HDRI with a small bright sun and a
// sharp horizon. Random methods use fixed seeds, so every assertion is deterministic; where
// a bound is statistical, the comment derives the probability that a correct implementation
// would have failed it with other seeds.
#include "shpack/sampling_methods.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

namespace shpack {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2u, u = 2^-53

using Rgb = std::array<double, 3>;

// ---- Test inputs -------------------------------------------------------------------------

// A tightly packed float RGB equirect image.
struct Map {
  std::uint32_t width = 0, height = 0;
  std::vector<float> rgb;

  ImageView view() const { return make_view(rgb.data(), width, height, 3); }
  Rgb texel(std::uint32_t x, std::uint32_t y) const {
    const float* p = &rgb[3 * (std::size_t{y} * width + x)];
    return {p[0], p[1], p[2]};
  }
};

// The image whose texel (i, j) holds f at the texel centre (conventions.h).
template <class F>
Map sample_map(std::uint32_t width, std::uint32_t height, F f) {
  Map map{width, height, std::vector<float>(std::size_t{3} * width * height)};
  for (std::uint32_t j = 0; j < height; ++j) {
    for (std::uint32_t i = 0; i < width; ++i) {
      const Rgb v = f(equirect_direction((i + 0.5) / width, (j + 0.5) / height));
      for (int c = 0; c < 3; ++c)
        map.rgb[3 * (std::size_t{j} * width + i) + c] = static_cast<float>(v[c]);
    }
  }
  return map;
}

double dot(const Dir3& a, const Dir3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Dir3 normalized(Dir3 d) {
  const double n = std::sqrt(dot(d, d));
  return {d.x / n, d.y / n, d.z / n};
}

// Smooth, positive and not band-limited: an exponential lobe, a product of sines, a
// Gaussian blob. Smooth at the poles too (a function of x, y, z).
Rgb smooth_radiance(const Dir3& d) {
  const double a = dot(d, normalized({0.3, 0.8, 0.52}));
  const double bx = d.x - 0.5, bz = d.z + 0.7;
  return {0.5 + 2.0 * std::exp(3.0 * (a - 1.0)),
          0.4 + 0.3 * d.x * d.z + 0.2 * std::sin(3.0 * d.x) * std::cos(2.0 * d.z),
          0.3 + 0.5 * std::exp(-4.0 * (bx * bx + d.y * d.y + bz * bz))};
}

// A stand-in for a real HDRI: the smooth sky, a darker ground below the horizon, and a
// sun of angular radius 5 degrees and radiance 500 (the sun carries most of the energy, a
// dynamic range of 1e3, and sharp edges, as in the maps of data/hdri).
Rgb sun_radiance(const Dir3& d) {
  if (dot(d, normalized({0.4, 0.5, -0.7})) > std::cos(5.0 * kPi / 180.0))
    return {500.0, 450.0, 400.0};
  Rgb v = smooth_radiance(d);
  if (d.y < 0.0) v = {0.3 * v[0], 0.25 * v[1], 0.2 * v[2]};
  return v;
}

Map smooth_map(std::uint32_t width, std::uint32_t height) {
  return sample_map(width, height, smooth_radiance);
}
Map sun_map(std::uint32_t width, std::uint32_t height) {
  return sample_map(width, height, sun_radiance);
}

// ---- Helpers -----------------------------------------------------------------------------

MethodSpec spec_of(std::string_view text, std::uint64_t seed = kDefaultMethodSeed) {
  MethodSpec spec;
  const Status st = parse_method(text, spec);
  EXPECT_TRUE(st.ok()) << "parse_method(\"" << text << "\"): " << st.what;
  spec.seed = seed;
  return spec;
}

std::string with_param(std::string_view method, std::uint32_t param) {
  return std::string(method) + ":" + std::to_string(param);
}

ShL2 project(const Map& map, const MethodSpec& spec, const ProjectOptions& options = {}) {
  ShL2 out;
  const Status st = project_with_method(map.view(), spec, options, out);
  EXPECT_TRUE(st.ok()) << method_name(spec).view() << " on " << map.width << "x" << map.height
                       << ": " << errc_name(st.code) << " " << st.what;
  return out;
}
ShL2 project(const Map& map, std::string_view spec, std::uint64_t seed = kDefaultMethodSeed) {
  return project(map, spec_of(spec, seed));
}

// Euclidean norm of the difference over the 27 coefficients.
double distance(const ShL2& a, const ShL2& b) {
  double sum = 0.0;
  for (int c = 0; c < kChannelCount; ++c)
    for (int i = 0; i < kShCount; ++i) sum += (a.c[c][i] - b.c[c][i]) * (a.c[c][i] - b.c[c][i]);
  return std::sqrt(sum);
}

double norm(const ShL2& a) { return distance(a, ShL2{}); }

// Observed order p of an error falling as N^-p between two parameters.
double order(double error_small, std::uint32_t n_small, double error_large, std::uint32_t n_large) {
  return std::log(error_small / error_large) / std::log(static_cast<double>(n_large) / n_small);
}

// RMS over seeds first_seed .. first_seed + seeds - 1 of the error of a seeded method.
double rms_error(const Map& map, std::string_view method, std::uint32_t n, std::uint64_t first_seed,
                 int seeds, const ShL2& exact) {
  double sum = 0.0;
  for (int s = 0; s < seeds; ++s) {
    const double e = distance(project(map, with_param(method, n), first_seed + s), exact);
    sum += e * e;
  }
  return std::sqrt(sum / seeds);
}

// Geometric mean of the errors of a deterministic method over several parameters.
double window_error(const Map& map, std::string_view method,
                    std::initializer_list<std::uint32_t> params, const ShL2& exact) {
  double log_sum = 0.0;
  for (const std::uint32_t n : params)
    log_sum += std::log(distance(project(map, with_param(method, n)), exact));
  return std::exp(log_sum / static_cast<double>(params.size()));
}

// Exact solid angle of a texel of row j (conventions.md), cancellation-free form.
double texel_solid_angle(std::uint32_t j, std::uint32_t width, std::uint32_t height) {
  const double a = kPi * j / height, b = kPi * (j + 1.0) / height;
  return (2.0 * kPi / width) * 2.0 * std::sin(0.5 * (a + b)) * std::sin(0.5 * (b - a));
}

// Sum over all 27 coefficients of the variance of ONE sample of an importance estimator
// that draws texel t with probability prob(t) and a direction uniform inside it:
// the term X = L_t Y_i(w) Omega_t / P_t has E[X^2] = sum_t L_t^2 Omega_t / P_t int_t Y_i^2,
// and sum_i Y_i^2 = 9 / (4 pi) everywhere (Unsold's theorem, l <= 2), so
//   sum_{c,i} Var X = sum_c sum_t L_ct^2 Omega_t^2 9 / (4 pi P_t) - sum_{c,i} L_ci^2.
// Uniform sampling (mc) is P_t = Omega_t / (4 pi): 9 int L^2 - |L|^2.
template <class Prob>
double one_sample_variance(const Map& map, const ShL2& exact, Prob prob) {
  double second_moment = 0.0;
  for (std::uint32_t y = 0; y < map.height; ++y) {
    const double omega = texel_solid_angle(y, map.width, map.height);
    for (std::uint32_t x = 0; x < map.width; ++x) {
      const Rgb v = map.texel(x, y);
      const double l2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
      second_moment += l2 * omega * omega * 9.0 / (4.0 * kPi * prob(x, y));
    }
  }
  const double mean2 = norm(exact) * norm(exact);
  return second_moment - mean2;
}

double mc_variance(const Map& map, const ShL2& exact) {
  return one_sample_variance(map, exact, [&](std::uint32_t, std::uint32_t y) {
    return texel_solid_angle(y, map.width, map.height) / (4.0 * kPi);
  });
}

// is:N's texel probabilities, recomputed from the header's definition.
double is_variance(const Map& map, const ShL2& exact) {
  auto lum = [&](std::uint32_t x, std::uint32_t y) {
    const Rgb v = map.texel(x, y);
    return std::max(0.0, 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2]);
  };
  double integral = 0.0;
  for (std::uint32_t y = 0; y < map.height; ++y)
    for (std::uint32_t x = 0; x < map.width; ++x)
      integral += lum(x, y) * texel_solid_angle(y, map.width, map.height);
  const double floor = kImportanceFloor * integral / (4.0 * kPi);
  const double total = integral + floor * 4.0 * kPi;  // sum of (lum + floor) Omega
  return one_sample_variance(map, exact, [&](std::uint32_t x, std::uint32_t y) {
    return (lum(x, y) + floor) * texel_solid_angle(y, map.width, map.height) / total;
  });
}

// Bounds for an RMS over S = 16 seeds. The squared error of one seed is a sum of squares of
// 27 (nearly) Gaussian estimates (CLT at N >= 256 for bounded terms); its mean over seeds,
// divided by its expectation, is distributed like chi^2_nu / nu with nu >= 16 (nu = 16 is
// the most spread case, one dominant direction of the covariance). chi^2_16/16 lies in
// [0.1734, 2.8703] except with probability 1e-4 per tail, so RMS / predicted lies in
// [0.4164, 1.6942]; the ratio of two independent RMS^2 is F(16, 16), whose 1e-4 tails are
// 1/7.6067 and 7.6067, so RMS(N) / RMS(16 N) lies in 4 [1/2.758, 2.758] = [1.450, 11.03].
constexpr int kSeeds = 16;
constexpr double kRmsLow = 0.4164, kRmsHigh = 1.6942;
constexpr double kRatioLow = 1.450, kRatioHigh = 11.03;

// ---- The direction -> texel lookup -------------------------------------------------------

TEST(EquirectTexel, RoundTripsEveryTexelCentre) {
  for (const auto [w, h] :
       {std::array<std::uint32_t, 2>{7, 5}, std::array<std::uint32_t, 2>{64, 32}}) {
    for (std::uint32_t j = 0; j < h; ++j) {
      for (std::uint32_t i = 0; i < w; ++i) {
        const EquirectTexel t =
            equirect_texel(equirect_direction((i + 0.5) / w, (j + 0.5) / h), w, h);
        EXPECT_EQ(t, (EquirectTexel{i, j})) << w << "x" << h << " texel (" << i << ", " << j
                                            << ") came back as (" << t.x << ", " << t.y << ")";
      }
    }
  }
}

TEST(EquirectTexel, AxesSeamPolesAndBadDirections) {
  // 7 x 5: columns are 1/7 wide, so u = 0.5 (+X), 0.25 (+Z), 0.75 (-Z) are inside columns
  // 3, 1 and 5 (conventions.md: centre column +X, u = 0.25 +Z, u = 0.75 -Z).
  struct Case {
    Dir3 d;
    EquirectTexel want;
    const char* what;
  };
  const Case cases[] = {
      {{1, 0, 0}, {3, 2}, "+X"},
      {{0, 0, 1}, {1, 2}, "+Z"},
      {{0, 0, -1}, {5, 2}, "-Z"},
      {{0, 1, 0}, {3, 0}, "+Y (top row)"},
      {{0, -1, 0}, {3, 4}, "-Y (bottom row)"},
      {{-1, 0, 0.0}, {0, 2}, "-X, z = +0: lon = pi, u = 0"},
      {{-1, 0, -0.0}, {6, 2}, "-X, z = -0: lon = -pi, u = 1, clamped"},
      {{2, 0, 0}, {3, 2}, "+X, not unit length"},
      {{0, 0, 0}, {3, 0}, "zero: lon = 0, theta = 0"},
      {{std::nan(""), 0, 0}, {0, 0}, "NaN"},
  };
  for (const Case& c : cases) {
    const EquirectTexel t = equirect_texel(c.d, 7, 5);
    EXPECT_EQ(t, c.want) << c.what << ": got (" << t.x << ", " << t.y << ")";
  }
}

// ---- Names -------------------------------------------------------------------------------

TEST(ParseMethod, AcceptsEveryMethodAndPrintsItBack) {
  struct Case {
    const char* text;
    SamplingMethod method;
    std::uint32_t param;
    std::uint64_t seed;
  };
  const Case cases[] = {
      {"exact", SamplingMethod::Exact, 0, kDefaultMethodSeed},
      {"center", SamplingMethod::Center, 0, kDefaultMethodSeed},
      {"mip:3", SamplingMethod::Mip, 3, kDefaultMethodSeed},
      {"mip:0", SamplingMethod::Mip, 0, kDefaultMethodSeed},
      {"mc:4096", SamplingMethod::MonteCarlo, 4096, kDefaultMethodSeed},
      {"mc:4096:7", SamplingMethod::MonteCarlo, 4096, 7},
      {"qmc:1024", SamplingMethod::QuasiMonteCarlo, 1024, kDefaultMethodSeed},
      {"qmc:1:18446744073709551615", SamplingMethod::QuasiMonteCarlo, 1, UINT64_MAX},
      {"fib:100", SamplingMethod::Fibonacci, 100, kDefaultMethodSeed},
      {"is:64:0", SamplingMethod::Importance, 64, 0},
      {"riemann:32", SamplingMethod::Riemann, 32, kDefaultMethodSeed},
      {"cube:16", SamplingMethod::CubeThreeJs, 16, kDefaultMethodSeed},
      {"cube-exact:1073741824", SamplingMethod::CubeExact, kMaxGridParam, kDefaultMethodSeed},
      {"fib:4294967295", SamplingMethod::Fibonacci, UINT32_MAX, kDefaultMethodSeed},
      {"lsq:9", SamplingMethod::LeastSquares, 9, kDefaultMethodSeed},
  };
  for (const Case& c : cases) {
    MethodSpec spec;
    const Status st = parse_method(c.text, spec);
    ASSERT_TRUE(st.ok()) << c.text << ": " << st.what;
    EXPECT_EQ(spec, (MethodSpec{c.method, c.param, c.seed})) << c.text;
    EXPECT_EQ(method_name(spec).view(), c.text) << "printed back";
  }
}

TEST(ParseMethod, RejectsMalformedNamesAndLeavesTheSpecAlone) {
  const char* bad[] = {"",
                       "exact:1",
                       "center:",
                       "mc",
                       "mc:",
                       "mc:-1",
                       "mc:+5",
                       "mc: 5",
                       "mc:5 ",
                       "mc:0",
                       "mc:4294967296",
                       "mc:5:",
                       "mc:5:x",
                       "fib:5:1",
                       "mip:32",
                       "lsq:8",
                       "cube-exact",
                       "Exact",
                       "mc:5:1:2",
                       "riemann:1e3",
                       "is:18446744073709551616",
                       "cube:1073741825",
                       "riemann:1073741825"};
  for (const char* text : bad) {
    MethodSpec spec{SamplingMethod::Riemann, 77, 99};
    const Status st = parse_method(text, spec);
    EXPECT_EQ(st.code, Errc::InvalidArgument) << "\"" << text << "\" was accepted";
    EXPECT_EQ(spec, (MethodSpec{SamplingMethod::Riemann, 77, 99}))
        << "\"" << text << "\" changed the spec";
  }
}

TEST(ProjectWithMethod, ValidatesTheSpecAndTheView) {
  const Map map = smooth_map(8, 4);
  ShL2 out;
  EXPECT_EQ(project_with_method(map.view(), {SamplingMethod::LeastSquares, 8, 0}, {}, out).code,
            Errc::InvalidArgument)
      << "lsq:8";
  EXPECT_EQ(project_with_method(map.view(), {SamplingMethod::MonteCarlo, 0, 0}, {}, out).code,
            Errc::InvalidArgument)
      << "mc:0";
  EXPECT_EQ(project_with_method(map.view(), {static_cast<SamplingMethod>(200), 1, 0}, {}, out).code,
            Errc::InvalidArgument)
      << "unknown enumerator";
  ImageView empty = map.view();
  empty.data = nullptr;
  EXPECT_EQ(project_with_method(empty, spec_of("mc:16"), {}, out).code, Errc::BadView)
      << "null data";
}

TEST(ProjectWithMethod, ExactAndCenterAreProjectEquirect) {
  const Map map = sun_map(64, 32);
  for (const SamplingMethod m : {SamplingMethod::Exact, SamplingMethod::Center}) {
    ProjectOptions options;
    options.method = m;
    ShL2 want;
    ASSERT_TRUE(project_equirect(map.view(), options, want).ok());
    // options.method is ignored: the spec decides.
    options.method = m == SamplingMethod::Exact ? SamplingMethod::Center : SamplingMethod::Exact;
    const ShL2 got = project(map, spec_of(m == SamplingMethod::Exact ? "exact" : "center"), options);
    EXPECT_EQ(got, want) << (m == SamplingMethod::Exact ? "exact" : "center");
  }
}

// ---- Uniform radiance, value policies ----------------------------------------------------

TEST(SamplingAllMethods, UniformRadianceGivesL00Only) {
  // L = 1: L00 = int Y0 = 4 pi k0 = 2 sqrt(pi), every other coefficient 0 (orthogonality).
  // Equal-weight rules sum N times Y0 (4 pi / N): rounding of a Neumaier sum, ~4u relative.
  // cube renormalises its weights to 4 pi exactly; cube-exact's weights sum to 4 pi within
  // 6 N^2 x 4 ulp(pi/2) (see CubeWeights) = 1.4e-13 at N = 5; is divides by CDF steps of
  // a 35-texel CDF: relative 35 u. So 1e-12 relative covers them all. riemann's weights sum
  // to 2 pi^2 / (N sin(pi / 2N)) (sum_j sin((j + 1/2) pi / N) = 1 / sin(pi / 2N)), not 4 pi.
  // The L1, L2 of the point methods are sums of Y_i over their points: zero only by symmetry
  // of the point set, so they are not checked here.
  const Map one = sample_map(7, 5, [](const Dir3&) { return Rgb{1.0, 1.0, 1.0}; });
  const double l00 = 2.0 * std::sqrt(kPi);
  const char* methods[] = {"exact",   "center",  "mip:1",  "mip:2",  "mip:31",       "mc:100",
                           "qmc:100", "fib:100", "is:100", "cube:5", "cube-exact:5", "lsq:50"};
  for (const char* m : methods) {
    const ShL2 sh = project(one, m);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sh.c[c][0], l00, 1e-12 * l00) << m << " channel " << c;
  }
  const ShL2 r = project(one, "riemann:6");
  const double riemann_sum = 2.0 * kPi * kPi / (6.0 * std::sin(kPi / 12.0));
  EXPECT_NEAR(r.c[0][0], riemann_sum * kY0, 1e-13) << "riemann:6, L00 = k0 sum of weights";
  // exact-weight methods also have exactly zero higher coefficients up to rounding:
  for (const char* m : {"exact", "mip:1", "lsq:50"}) {
    const ShL2 sh = project(one, m);
    for (int i = 1; i < kShCount; ++i) EXPECT_NEAR(sh.c[1][i], 0.0, 1e-13) << m << " i=" << i;
  }
}

// Every method once, at a small parameter: for the texel-policy tests, which read a 1 x 1 image.
constexpr const char* kEveryMethodOnce[] = {"exact", "center", "mip:1",        "mc:16",  "qmc:16", "fib:16",
                                            "is:16", "riemann:2", "cube:2", "cube-exact:2", "lsq:16"};

TEST(SamplingAllMethods, NonFiniteTexelsFollowThePolicy) {
  // A 1 x 1 NaN image: every direction falls in the one texel, so every method reads it.
  const float nan_rgb[3] = {std::nanf(""), 1.0f, 1.0f};
  const ImageView nan_view = make_view(nan_rgb, 1, 1, 3);
  for (const char* m : kEveryMethodOnce) {
    ShL2 out;
    ProjectOptions options;
    const Status st = project_with_method(nan_view, spec_of(m), options, out);
    EXPECT_EQ(st.code, Errc::NonFiniteTexel) << m << " under NonFinite::Error";
    options.nonfinite = NonFinite::Zero;
    ProjectStats stats;
    ASSERT_TRUE(project_with_method(nan_view, spec_of(m), options, out, &stats).ok()) << m;
    EXPECT_GE(stats.nonfinite_texels, 1u) << m << " counts the NaN texel";
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < kShCount; ++i)
        EXPECT_TRUE(std::isfinite(out.c[c][i])) << m << " c=" << c << " i=" << i;
    EXPECT_EQ(out.c[0][0], 0.0) << m << ": the NaN channel reads as 0";
  }
  // Methods that read every texel report the first non-finite texel in row-major order,
  // as project_equirect does: a 4 x 2 image with NaN at (2, 1) and (1, 1).
  Map map = smooth_map(4, 2);
  map.rgb[3 * (1 * 4 + 2) + 1] = std::numeric_limits<float>::infinity();
  map.rgb[3 * (1 * 4 + 1) + 2] = std::nanf("");
  for (const char* m : {"exact", "mip:1", "is:8"}) {
    ShL2 out;
    const Status st = project_with_method(map.view(), spec_of(m), {}, out);
    EXPECT_EQ(st.code, Errc::NonFiniteTexel) << m;
    EXPECT_EQ(st.x, 1u) << m;
    EXPECT_EQ(st.y, 1u) << m;
    ProjectOptions zero;
    zero.nonfinite = NonFinite::Zero;
    ProjectStats stats;
    ASSERT_TRUE(project_with_method(map.view(), spec_of(m), zero, out, &stats).ok()) << m;
    EXPECT_EQ(stats.nonfinite_texels, 2u) << m << " sees each texel once";
  }
}

TEST(SamplingAllMethods, NegativeTexelsFollowThePolicy) {
  const float neg_rgb[3] = {-1.0f, -2.0f, -3.0f};
  const ImageView view = make_view(neg_rgb, 1, 1, 3);
  for (const char* m : kEveryMethodOnce) {
    ShL2 out;
    ProjectOptions options;
    ProjectStats stats;
    ASSERT_TRUE(project_with_method(view, spec_of(m), options, out, &stats).ok()) << m;
    EXPECT_LT(out.c[2][0], 0.0) << m << " keeps negative radiance (Negative::Keep)";
    EXPECT_GE(stats.negative_texels, 1u) << m;
    options.negative = Negative::Clamp;
    ASSERT_TRUE(project_with_method(view, spec_of(m), options, out, &stats).ok()) << m;
    EXPECT_EQ(out, ShL2{}) << m << " reads clamped texels as 0";
    EXPECT_GE(stats.negative_texels, 1u) << m << " still counts them";
  }
}

// ---- Determinism -------------------------------------------------------------------------

TEST(SamplingAllMethods, SameSeedIsBitIdenticalAndSeedsMatterOnlyWhereUsed) {
  const Map map = sun_map(64, 32);
  for (const char* m : {"mc:500", "qmc:500", "is:500"}) {
    EXPECT_EQ(project(map, m, 7), project(map, m, 7)) << m << ": same seed, same bits";
    EXPECT_NE(project(map, m, 7), project(map, m, 8)) << m << ": seeds 7 and 8 agree";
  }
  for (const char* m : {"mip:2", "fib:500", "riemann:20", "cube:10", "cube-exact:10", "lsq:500"}) {
    EXPECT_EQ(project(map, m, 7), project(map, m, 8)) << m << " does not use the seed";
  }
}

// ---- mip:K -------------------------------------------------------------------------------

TEST(SamplingMip, LevelZeroIsExactBitForBit) {
  // Level 0 averages one texel with weight W H / (W H): the double result rounds back to the
  // same float, so the small map is the image itself.
  const Map map = sun_map(96, 48);
  EXPECT_EQ(project(map, "mip:0"), project(map, "exact"));
}

TEST(SamplingMip, ErrorGrowsWithLevelLikeTheBlockAreaOnSmoothInput) {
  // A block average over a 2^K block of a smooth function differs from the function's
  // integral by O(h_K^2), h_K = 2^K h: each level should multiply the error by ~4. The ratio
  // settles from K = 3 (K = 1, 2 still carry the O(h^2) of the base image): [3, 5].
  const Map map = smooth_map(256, 128);
  const ShL2 exact = project(map, "exact");
  double previous = 0.0;
  for (std::uint32_t k = 1; k <= 5; ++k) {
    const double e = distance(project(map, with_param("mip", k)), exact);
    EXPECT_GT(e, previous) << "mip:" << k << " is not worse than mip:" << k - 1;
    if (k >= 3) {
      EXPECT_GT(e / previous, 3.0) << "mip:" << k << " error ratio";
      EXPECT_LT(e / previous, 5.0) << "mip:" << k << " error ratio";
    }
    previous = e;
  }
  // The real-map stand-in: coarser levels are worse overall (not always level by level: a
  // sun's block can straddle texels more or less favourably).
  const Map sun = sun_map(256, 128);
  const ShL2 sun_exact = project(sun, "exact");
  EXPECT_LT(distance(project(sun, "mip:1"), sun_exact), distance(project(sun, "mip:4"), sun_exact));
}

TEST(SamplingMip, SizesNotDivisibleByTheBlockSplitTexelsByOverlap) {
  // A map varying only in longitude, 7 x 5 -> 3 x 2 (K = 1) and 1 x 1 (K = 2..31). Each
  // source column overlaps the small columns with total weight one source column, so the
  // longitude mean is kept: L00 = k0 (4 pi / W) sum_i v_i for both maps (the rows' solid
  // angles sum to 4 pi / W per column either way). The small map is float32: relative
  // error <= 2^-24 per value, so 1e-7 relative.
  const Map map = sample_map(7, 5, [](const Dir3& d) {
    const double lon = std::atan2(d.z, d.x);
    return Rgb{2.0 + std::cos(lon), 1.0 + 0.5 * std::sin(2.0 * lon), 3.0};
  });
  const ShL2 exact = project(map, "exact");
  for (const char* m : {"mip:1", "mip:2", "mip:3", "mip:31"}) {
    const ShL2 sh = project(map, m);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(sh.c[c][0], exact.c[c][0], 1e-7 * std::fabs(exact.c[c][0])) << m << " c=" << c;
  }
  // 7 x 5, K = 1: small column 0 covers source columns 0, 1 and the first third of 2; a map
  // that is 1 in source column 2 only gives (1/3) / (7/3) = 1/7 in small column 0 and
  // (2/3) / (7/3) = 2/7 in small column 1, so L00 = k0 (4 pi / 3)(1/7 + 2/7) = k0 4 pi / 7,
  // the source's own L00.
  const Map column = sample_map(7, 5, [](const Dir3& d) {
    const double u = 0.5 - std::atan2(d.z, d.x) / (2.0 * kPi);
    return Rgb{u >= 2.0 / 7 && u < 3.0 / 7 ? 1.0 : 0.0, 0.0, 0.0};
  });
  EXPECT_NEAR(project(column, "mip:1").c[0][0], kY0 * 4.0 * kPi / 7.0, 1e-7)
      << "partial footprints";
  // The split itself: the small map is exactly {1/7, 2/7, 0} in both rows (5/35 and 10/35
  // in double, rounded to float like 1/7 and 2/7), so mip:1 is exact of that 3 x 2 map.
  const float third = static_cast<float>(1.0 / 7.0), two = static_cast<float>(2.0 / 7.0);
  const float small[18] = {third, 0, 0, two, 0, 0, 0, 0, 0, third, 0, 0, two, 0, 0, 0, 0, 0};
  ShL2 want;
  ASSERT_TRUE(project_equirect(make_view(small, 3, 2, 3), {}, want).ok());
  EXPECT_EQ(project(column, "mip:1"), want) << "source column 2 split 1/3 : 2/3";
}

TEST(SamplingMip, DivisibleSizesAverageBlocks) {
  // 8 x 4, K = 1: each small texel is (a + b + c + d) / 4 of its 2 x 2 block, summed in
  // row-major order. The code sums 8a + 8b + 8c + 8d and divides by 32: scaling by powers
  // of two is exact, so the floats are identical and so are the projections.
  const Map map = sun_map(8, 4);
  std::vector<float> small(3 * 4 * 2);
  for (std::uint32_t y = 0; y < 2; ++y) {
    for (std::uint32_t x = 0; x < 4; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double sum =
            (static_cast<double>(map.texel(2 * x, 2 * y)[c]) + map.texel(2 * x + 1, 2 * y)[c]) +
            map.texel(2 * x, 2 * y + 1)[c] + map.texel(2 * x + 1, 2 * y + 1)[c];
        small[3 * (y * 4 + x) + c] = static_cast<float>(sum / 4.0);
      }
    }
  }
  ShL2 want;
  ASSERT_TRUE(project_equirect(make_view(small.data(), 4, 2, 3), {}, want).ok());
  EXPECT_EQ(project(map, "mip:1"), want);
}

// ---- mc:N, is:N --------------------------------------------------------------------------

TEST(SamplingMonteCarlo, ErrorFallsAsOneOverRootNWithThePredictedVariance) {
  // mc is unbiased for exact: error^2 has expectation V / N, V = 9 int L^2 - |L|^2
  // (one_sample_variance). Bounds: kRmsLow..kRmsHigh and kRatioLow..kRatioHigh (above).
  // Independent seeds for the two N (1..16 and 101..116).
  const Map map = smooth_map(256, 128);
  const ShL2 exact = project(map, "exact");
  const double v = mc_variance(map, exact);
  const double rms256 = rms_error(map, "mc", 256, 1, kSeeds, exact);
  const double rms4096 = rms_error(map, "mc", 4096, 101, kSeeds, exact);
  const double predicted256 = std::sqrt(v / 256), predicted4096 = std::sqrt(v / 4096);
  EXPECT_GT(rms256 / predicted256, kRmsLow)
      << "mc:256 rms " << rms256 << " predicted " << predicted256;
  EXPECT_LT(rms256 / predicted256, kRmsHigh)
      << "mc:256 rms " << rms256 << " predicted " << predicted256;
  EXPECT_GT(rms4096 / predicted4096, kRmsLow)
      << "mc:4096 rms " << rms4096 << " predicted " << predicted4096;
  EXPECT_LT(rms4096 / predicted4096, kRmsHigh)
      << "mc:4096 rms " << rms4096 << " predicted " << predicted4096;
  EXPECT_GT(rms256 / rms4096, kRatioLow) << "rms(256)/rms(4096), 4 expected";
  EXPECT_LT(rms256 / rms4096, kRatioHigh) << "rms(256)/rms(4096), 4 expected";
}

TEST(SamplingImportance, IsUnbiasedWithThePredictedVariance) {
  // is:N is unbiased for exact with error^2 expectation V_is / N, V_is from the texel
  // probabilities of the header (is_variance); same statistical bounds as mc. On the sun
  // map the floor bounds the weights (Omega / P <= 4 pi (1 + eps) / eps), so the CLT holds.
  for (const bool sun : {false, true}) {
    const Map map = sun ? sun_map(256, 128) : smooth_map(256, 128);
    const char* name = sun ? "sun map" : "smooth map";
    const ShL2 exact = project(map, "exact");
    const double v = is_variance(map, exact);
    const double rms256 = rms_error(map, "is", 256, 1, kSeeds, exact);
    const double rms4096 = rms_error(map, "is", 4096, 101, kSeeds, exact);
    const double predicted256 = std::sqrt(v / 256), predicted4096 = std::sqrt(v / 4096);
    EXPECT_GT(rms256 / predicted256, kRmsLow)
        << name << " is:256 rms " << rms256 << " predicted " << predicted256;
    EXPECT_LT(rms256 / predicted256, kRmsHigh)
        << name << " is:256 rms " << rms256 << " predicted " << predicted256;
    EXPECT_GT(rms4096 / predicted4096, kRmsLow)
        << name << " is:4096 rms " << rms4096 << " predicted " << predicted4096;
    EXPECT_LT(rms4096 / predicted4096, kRmsHigh)
        << name << " is:4096 rms " << rms4096 << " predicted " << predicted4096;
    EXPECT_GT(rms256 / rms4096, kRatioLow) << name << " rms(256)/rms(4096)";
    EXPECT_LT(rms256 / rms4096, kRatioHigh) << name << " rms(256)/rms(4096)";
  }
}

TEST(SamplingImportance, NeedsFarFewerSamplesThanMonteCarloOnASun) {
  // The exact variances (no sampling involved): with a sun holding most of the energy in
  // 0.2% of the sphere, uniform sampling rarely hits it; is hits it with probability ~0.8.
  const Map map = sun_map(256, 128);
  const ShL2 exact = project(map, "exact");
  const double v_mc = mc_variance(map, exact), v_is = is_variance(map, exact);
  EXPECT_GT(v_mc / v_is, 100.0) << "variance mc " << v_mc << " is " << v_is;
  // The floor's guarantee: never more than (1 + eps)/eps = 5 times mc's second moment; on a
  // smooth map is is within that of mc.
  const Map smooth = smooth_map(256, 128);
  const ShL2 smooth_exact = project(smooth, "exact");
  const double second_mc =
      mc_variance(smooth, smooth_exact) + norm(smooth_exact) * norm(smooth_exact);
  const double second_is =
      is_variance(smooth, smooth_exact) + norm(smooth_exact) * norm(smooth_exact);
  EXPECT_LT(second_is, (1.0 + kImportanceFloor) / kImportanceFloor * second_mc);
}

// ---- qmc:N, fib:N, lsq:N -----------------------------------------------------------------

TEST(SamplingLowDiscrepancy, QmcErrorFallsFasterThanMonteCarlo) {
  // Randomised (digitally shifted) Sobol points: for a smooth integrand the RMS error falls
  // like ~N^-1 (observed 1.19 here), against N^-1/2 for mc. With 64 seeds the RMS is within
  // [0.687, 1.340] of its expectation except with probability 1e-4 per tail (chi^2_64/64:
  // [0.4715, 1.7943]), which moves an observed order over a factor 16 in N by at most
  // log(1.340 / 0.687) / log(16) = 0.24: an order-1 method passes > 0.75.
  const Map map = smooth_map(256, 128);
  const ShL2 exact = project(map, "exact");
  const double rms256 = rms_error(map, "qmc", 256, 1, 64, exact);
  const double rms4096 = rms_error(map, "qmc", 4096, 101, 64, exact);
  EXPECT_GT(order(rms256, 256, rms4096, 4096), 0.75) << "qmc rms " << rms256 << " -> " << rms4096;
}

TEST(SamplingLowDiscrepancy, FibonacciAndLeastSquaresFallFasterThanMonteCarlo) {
  // Deterministic rules: spherical Fibonacci points integrate smooth functions with error
  // ~N^-1 or better (observed 1.16 for fib, 1.04 for lsq here); > 0.75 separates them from
  // random points (0.5).
  const Map map = smooth_map(256, 128);
  const ShL2 exact = project(map, "exact");
  for (const char* m : {"fib", "lsq"}) {
    const double e256 = distance(project(map, with_param(m, 256)), exact);
    const double e4096 = distance(project(map, with_param(m, 4096)), exact);
    EXPECT_GT(order(e256, 256, e4096, 4096), 0.75) << m << " error " << e256 << " -> " << e4096;
  }
}

TEST(SamplingLowDiscrepancy, ConvergeOnTheSunMap) {
  // A sun's edge makes the integrand discontinuous. The error of a deterministic rule then
  // swings by a factor of ~5 from one N to the next (how many points happen to fall in the
  // sun), around an envelope falling like ~N^-3/4 (cap discrepancy of spherical Fibonacci
  // points). So the geometric mean over a window of N is compared, at 64x the samples:
  // at least the order of random points, 0.5, i.e. a factor 8 (observed 18.7).
  // qmc: RMS over 16 seeds at 16x the samples, factor 4 = order 0.5 (observed 15).
  const Map map = sun_map(256, 128);
  const ShL2 exact = project(map, "exact");
  for (const char* m : {"fib", "lsq"}) {
    const double small = window_error(map, m, {512, 640, 768, 896, 1024}, exact);
    const double large = window_error(map, m, {32768, 40960, 49152, 57344, 65536}, exact);
    EXPECT_GT(small / large, 8.0) << m << " error " << small << " -> " << large << " (|exact| "
                                  << norm(exact) << ")";
  }
  const double r1 = rms_error(map, "qmc", 1024, 1, kSeeds, exact);
  const double r2 = rms_error(map, "qmc", 16384, 101, kSeeds, exact);
  EXPECT_GT(r1 / r2, 4.0) << "qmc rms " << r1 << " -> " << r2;
}

TEST(ShLeastSquares, ReproducesBandLimitedDataExactly) {
  // Values of an L2 function at >= 9 well-spread directions determine it: the residual is 0
  // and the fit returns the coefficients. QR by rotations is backward stable: error
  // <~ kappa(A) * 9 * sqrt(N) * u * |c|, kappa ~ 1-2 for Fibonacci points: 1e-12 |c| is
  // a wide margin.
  ShL2 want;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < kShCount; ++i)
      want.c[c][i] = std::sin(1.0 + 3.0 * c + 0.7 * i) * (i == 0 ? 3.0 : 1.0);
  for (const std::uint32_t n : {9u, 10u, 64u, 1000u}) {
    ShLeastSquares fit;
    for (std::uint32_t k = 0; k < n; ++k) {
      // The Fibonacci directions of lsq:N (sampling_methods.h).
      const double y = 1.0 - (2.0 * k + 1.0) / n;
      const double lon =
          2.0 * kPi *
          (k * (std::sqrt(5.0) - 1.0) / 2.0 - std::floor(k * (std::sqrt(5.0) - 1.0) / 2.0));
      const double r = std::sqrt((1.0 - y) * (1.0 + y));
      const Dir3 d = {r * std::cos(lon), y, r * std::sin(lon)};
      const std::array<double, kShCount> basis = eval_basis(d.x, d.y, d.z);
      Rgb v{};
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < kShCount; ++i) v[c] += want.c[c][i] * basis[i];
      fit.add(d, v);
    }
    ShL2 got;
    ASSERT_TRUE(fit.solve(got).ok()) << "N=" << n;
    EXPECT_EQ(fit.count(), n);
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < kShCount; ++i)
        EXPECT_NEAR(got.c[c][i], want.c[c][i], 1e-12 * norm(want))
            << "N=" << n << " c=" << c << " i=" << i;
  }
}

TEST(ShLeastSquares, RejectsTooFewOrDegenerateSamples) {
  ShLeastSquares fit;
  ShL2 out;
  for (int k = 0; k < 8; ++k) fit.add(normalized({1.0, 0.1 * k, 0.3}), {1, 1, 1});
  EXPECT_EQ(fit.solve(out).code, Errc::InvalidArgument) << "8 samples";
  // Directions on one great circle (y = 0) leave y, xy, yz undetermined.
  ShLeastSquares ring;
  for (int k = 0; k < 100; ++k) ring.add({std::cos(0.1 * k), 0.0, std::sin(0.1 * k)}, {1, 1, 1});
  EXPECT_EQ(ring.solve(out).code, Errc::InvalidArgument) << "100 samples on the equator";
}

// ---- riemann:N, center -------------------------------------------------------------------

TEST(SamplingRiemann, CenterAndRiemannAreSecondOrderOnSmoothInput) {
  // riemann:N on a 2N x N map of a smooth function samples every texel at its centre, with
  // the midpoint weight sin(theta) dtheta dlon; center uses the exact solid angle. Both are
  // midpoint rules: error C h^2 + O(h^4), so the observed order over a doubling is
  // 2 + O(h^2): within [1.8, 2.2] from N = 16 (observed 2.00 - 2.03).
  double previous_center = 0.0, previous_riemann = 0.0;
  for (const std::uint32_t n : {16u, 32u, 64u, 128u}) {
    const Map map = smooth_map(2 * n, n);
    const ShL2 exact = project(map, "exact");
    const double ec = distance(project(map, "center"), exact);
    const double er = distance(project(map, with_param("riemann", n)), exact);
    if (previous_center > 0.0) {
      const double pc = order(previous_center, n / 2, ec, n),
                   pr = order(previous_riemann, n / 2, er, n);
      EXPECT_GT(pc, 1.8) << "center order at N=" << n;
      EXPECT_LT(pc, 2.2) << "center order at N=" << n;
      EXPECT_GT(pr, 1.8) << "riemann order at N=" << n;
      EXPECT_LT(pr, 2.2) << "riemann order at N=" << n;
    }
    previous_center = ec;
    previous_riemann = er;
  }
}

TEST(SamplingRiemann, ConvergesOnAFixedMapOnceEveryTexelHoldsWholeCells) {
  // From N = H each texel holds (N/H)^2 whole cells, sampled at their midpoints: the
  // integral of the basis over each texel is a midpoint rule with cell size pi/N, error
  // O(N^-2): order in [1.8, 2.2] over each doubling, on smooth input and on the sun map
  // (whose texels are constant, so the sun's edges cost nothing once cells nest in texels).
  for (const bool sun : {false, true}) {
    const Map map = sun ? sun_map(128, 64) : smooth_map(128, 64);
    const ShL2 exact = project(map, "exact");
    const double e64 = distance(project(map, "riemann:64"), exact);
    const double e128 = distance(project(map, "riemann:128"), exact);
    const double e256 = distance(project(map, "riemann:256"), exact);
    for (const double p : {order(e64, 64, e128, 128), order(e128, 128, e256, 256)}) {
      EXPECT_GT(p, 1.8) << (sun ? "sun" : "smooth") << " errors " << e64 << " " << e128 << " "
                        << e256;
      EXPECT_LT(p, 2.2) << (sun ? "sun" : "smooth") << " errors " << e64 << " " << e128 << " "
                        << e256;
    }
  }
}

// ---- cube:N, cube-exact:N ----------------------------------------------------------------

TEST(SamplingCubeWeights, ExactSolidAnglesSumToFourPi) {
  // Each texel is four atan2 values of magnitude <= pi/2 combined by three additions: error
  // <= ~4 ulp(pi/2) = 4 * 2^-52 * 2 = 1.8e-15 per texel, summed over 6 N^2 texels (plain
  // sum in the test, its rounding 6N^2 * u * 4 pi is smaller): 6 N^2 * 2.2e-15 bounds it;
  // 1e-12 for N <= 8, the derived bound beyond.
  for (const std::uint32_t n : {1u, 2u, 3u, 8u, 64u}) {
    double sum = 0.0, smallest = 1.0, largest = 0.0;
    for (std::uint32_t y = 0; y < n; ++y) {
      for (std::uint32_t x = 0; x < n; ++x) {
        const double w = cube_texel_solid_angle(n, x, y);
        sum += 6.0 * w;
        smallest = std::min(smallest, w);
        largest = std::max(largest, w);
      }
    }
    const double tol = std::max(1e-12, 6.0 * n * n * 2.2e-15);
    EXPECT_NEAR(sum, 4.0 * kPi, tol) << "N=" << n;
    EXPECT_GT(smallest, 0.0) << "N=" << n;
    // Corner texels are the smallest and centre texels the largest: a texel of area (2/N)^2
    // at (a, b) subtends ~(2/N)^2 / (1 + a^2 + b^2)^1.5 (relative error O(N^-2)), so the
    // ratio is ~((1 + 2 a1^2) / (1 + 2 a0^2))^1.5, a1 = 1 - 1/N, a0 = 1/N (5.03 at N = 64).
    if (n == 64) {
      const double a1 = 1.0 - 1.0 / n, a0 = 1.0 / n;
      const double want = std::pow((1.0 + 2.0 * a1 * a1) / (1.0 + 2.0 * a0 * a0), 1.5);
      EXPECT_NEAR(largest / smallest, want, 1e-2 * want) << "N=64 centre/corner";
    }
  }
  EXPECT_NEAR(cube_texel_solid_angle(1, 0, 0), 4.0 * kPi / 6.0, 4 * kEps) << "one texel per face";
}

TEST(SamplingCubeWeights, ThreeJsWeightsAreApproximateAndRenormalised) {
  // The centre-point weight is the midpoint rule for the face integral
  // int int (1 + a^2 + b^2)^-1.5 da db = 4 pi / 6: its sum misses 4 pi by O(N^-2) (ratio
  // ~4 per doubling), which is why three.js scales by 4 pi / sum. cube:N of a uniform map
  // then has L00 = 2 sqrt(pi) (UniformRadianceGivesL00Only).
  double previous = 0.0;
  for (const std::uint32_t n : {8u, 16u, 32u}) {
    double sum = 0.0;
    for (std::uint32_t y = 0; y < n; ++y)
      for (std::uint32_t x = 0; x < n; ++x) sum += 6.0 * cube_texel_weight_threejs(n, x, y);
    const double miss = std::fabs(sum - 4.0 * kPi);
    EXPECT_GT(miss, 1e-4 * 4.0 * kPi) << "N=" << n << ": the raw weights already sum to 4 pi?";
    if (previous > 0.0) {
      EXPECT_GT(previous / miss, 3.5) << "N=" << n;
      EXPECT_LT(previous / miss, 4.5) << "N=" << n;
    }
    previous = miss;
  }
  EXPECT_DOUBLE_EQ(cube_texel_weight_threejs(1, 0, 0), 4.0) << "(2/1)^2 / 1^1.5";
  // The two weightings agree to first order at the face centre: (2/N)^2 vs the exact
  // solid angle of the centre texel of an odd N, relative O(N^-2).
  EXPECT_NEAR(cube_texel_weight_threejs(101, 50, 50) / cube_texel_solid_angle(101, 50, 50), 1.0,
              1e-3);
}

TEST(SamplingCube, ConvergesToExactOnceCubeTexelsAreSmallerThanTheMap) {
  // Cube texels resample the equirect map by nearest texel. Once they are smaller than the
  // map's texels the rule integrates the piecewise-constant image, with error from the
  // cube texels that equirect texel edges cut: O(h_cube) per unit of edge length with
  // signs that partly cancel, so an order between 1 and 2 (observed 1.88 on the smooth map).
  // On the sun map the two grids alias along the sun's edge (jump 500), and the error swings
  // by up to 4x between neighbouring N (even N = 256 can be worse than 128): compare
  // geometric means over windows of N at 8x the resolution, asking for a factor 4, an order
  // of 2/3 in N (observed 12).
  const Map smooth = smooth_map(64, 32);
  const Map sun = sun_map(128, 64);
  const ShL2 smooth_exact = project(smooth, "exact");
  const ShL2 sun_exact = project(sun, "exact");
  for (const char* m : {"cube", "cube-exact"}) {
    const double e32 = distance(project(smooth, with_param(m, 32)), smooth_exact);
    const double e128 = distance(project(smooth, with_param(m, 128)), smooth_exact);
    EXPECT_GT(order(e32, 32, e128, 128), 1.0) << m << " smooth error " << e32 << " -> " << e128;
    const double small = window_error(sun, m, {12, 16, 20}, sun_exact);
    const double large = window_error(sun, m, {96, 128, 160}, sun_exact);
    EXPECT_GT(small / large, 4.0) << m << " sun error " << small << " -> " << large;
  }
}

}  // namespace
}  // namespace shpack
