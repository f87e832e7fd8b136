// window_test.cpp - deringing windows (window.h): the factors of hanning, lanczos and unity
// against their formulas, parse_window's accepted and rejected texts, L00 kept by every
// per-band window, and sloan: non-negative E/pi after it, as little windowing as its
// bisection allows (a slightly wider window of its family rings again), no change to a
// channel that does not ring, "impossible" exactly when L00 < 0. Optimal, which is no
// per-band window: window_optimal_test.cpp.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "shpack/convolution.h"
#include "shpack/sh_basis.h"
#include "shpack/sh_minimum.h"
#include "shpack/window.h"
#include "support/sh_oracle.h"
#include "support/sphere_points.h"
#include "support/test_util.h"

namespace shpack_test {
namespace {

using shpack::ShL2;
using shpack::Window;
using shpack::WindowKind;
constexpr double kPi = std::numbers::pi;

TEST(Window, FactorsMatchTheirFormulas) {
  // Hanning w_l = (1 + cos(pi l / W)) / 2 and Lanczos w_l = sin(pi l / W) / (pi l / W) for
  // l < W, else 0 ([2] in window.h). Evaluated here from std::numbers; shpack's factors go
  // through the same few correctly rounded operations (x = pi l / W: 2 roundings, cos/sin
  // < 1 ulp, then 2 more), so they agree to 8u absolute.
  for (double w : {0.25, 0.5, 1.0, 1.5, 2.0, 2.000001, 2.5, 3.0, 7.25, 1e6}) {
    for (WindowKind kind : {WindowKind::Hanning, WindowKind::Lanczos}) {
      std::array<double, 3> f{};
      ASSERT_TRUE(shpack::window_factors({kind, w}, f).ok()) << "W=" << w;
      EXPECT_EQ(f[0], 1.0) << "w_0 = 1 keeps the mean";
      for (int l = 1; l < 3; ++l) {
        const double x = kPi * l / w;
        const double want = l >= w ? 0.0 : kind == WindowKind::Hanning ? (1 + std::cos(x)) / 2 : std::sin(x) / x;
        EXPECT_NEAR(f[l], want, 8 * kU) << "W=" << w << " l=" << l << " kind=" << static_cast<int>(kind);
      }
    }
  }
  // Both vanish continuously at l = W: (1 + cos pi)/2 = 0 and sin(pi)/pi = 0.
  std::array<double, 3> f{};
  ASSERT_TRUE(shpack::window_factors({WindowKind::Hanning, 2.0}, f).ok());
  EXPECT_EQ(f[1], 0.5);
  EXPECT_EQ(f[2], 0.0);
  ASSERT_TRUE(shpack::window_factors({WindowKind::Lanczos, 2.0}, f).ok());
  EXPECT_NEAR(f[1], 2 / kPi, 4 * kU);
  ASSERT_TRUE(shpack::window_factors({WindowKind::Unity, 0}, f).ok());
  EXPECT_EQ(f, (std::array<double, 3>{1.0, 0.922066, 0.731864})) << "Unity's ProbePostProcessing constants";
  ASSERT_TRUE(shpack::window_factors({WindowKind::None, 0}, f).ok());
  EXPECT_EQ(f, (std::array<double, 3>{1.0, 1.0, 1.0}));
  EXPECT_EQ(shpack::window_factors({WindowKind::Sloan, 0}, f).code, shpack::Errc::InvalidArgument)
      << "sloan depends on the data";
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(shpack::window_factors({WindowKind::Hanning, bad}, f).code, shpack::Errc::InvalidArgument) << bad;
    EXPECT_EQ(shpack::window_factors({WindowKind::Lanczos, bad}, f).code, shpack::Errc::InvalidArgument) << bad;
  }
}

TEST(Window, ParseAcceptsExactlyTheDocumentedForms) {
  struct Good {
    std::string text;
    WindowKind kind;
    double width;
  };
  const Good good[] = {{"none", WindowKind::None, 0},          {"unity", WindowKind::Unity, 0},
                       {"sloan", WindowKind::Sloan, 0},        {"optimal", WindowKind::Optimal, 0},
                       {"hanning:3", WindowKind::Hanning, 3},
                       {"hanning:2.5", WindowKind::Hanning, 2.5}, {"lanczos:0.5", WindowKind::Lanczos, 0.5},
                       {"lanczos:1e3", WindowKind::Lanczos, 1e3}, {"hanning:1e-300", WindowKind::Hanning, 1e-300}};
  for (const Good& g : good) {
    Window w;
    const shpack::Status st = shpack::parse_window(g.text, w);
    ASSERT_TRUE(st.ok()) << g.text << ": " << st.what;
    EXPECT_EQ(w.kind, g.kind) << g.text;
    EXPECT_EQ(w.width, g.width) << g.text;
    // window_name prints what parses back to the same window.
    Window again;
    ASSERT_TRUE(shpack::parse_window(shpack::window_name(w).text, again).ok()) << shpack::window_name(w).text;
    EXPECT_EQ(again.kind, w.kind);
    EXPECT_EQ(again.width, w.width);
  }
  const std::string bad[] = {"",           "Hanning:3",  "HANNING:3",  "hanning",    "hanning:",    "hanning:0",
                             "hanning:-1", "hanning:nan", "hanning:inf", "hanning:1e999", "hanning:3x", "hanning: 3",
                             " hanning:3", "hanning:3 ", "hanning:3:4", "hanning:0x10", "lanczos",    "unity:1",
                             "sloan:2",    "none:",      "hann:3",     "gauss:2",    std::string("none\0", 5), "none,",
                             "optimal:1",  "Optimal",    "optimal "};
  for (const std::string& text : bad) {
    Window w{WindowKind::Lanczos, 7};
    EXPECT_EQ(shpack::parse_window(text, w).code, shpack::Errc::InvalidArgument) << "'" << text << "'";
    EXPECT_EQ(w.kind, WindowKind::Lanczos) << "'" << text << "': a rejected text leaves the window alone";
    EXPECT_EQ(w.width, 7.0) << "'" << text << "'";
  }
}

// Random Unity-form coefficients whose L2 function rings (a bright lobe on a dim mean),
// with L00 > 0.
ShL2 random_ringing(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // Directional lights of irradiance >= 0.5 ring to <= -0.0063 (-19E/(480 pi)); the added
  // mean (0.005 k0 = 0.0014) and noise (<= 0.002 sum_i C_i |P_i| < 0.002) do not undo it.
  const std::array<double, 3> e = {1.5 + 0.5 * u(rng), 2.0 + u(rng), 1.0 + 0.5 * u(rng)};
  const shpack::Dir3 d = random_direction(rng);
  const std::array<double, 9> y = unity_basis_slow(d.x, d.y, d.z);
  ShL2 radiance;
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 9; ++i) radiance.c[c][i] = e[c] * y[i] + (i == 0 ? 0.005 : 0.002 * u(rng));
  return shpack::radiance_to_unity_form(radiance);
}

std::vector<Window> every_window() {
  std::vector<Window> out;
  for (const char* text : {"none", "hanning:0.5", "hanning:1", "hanning:2", "hanning:3.5", "lanczos:1.5", "lanczos:4",
                           "lanczos:1e6", "unity", "sloan"}) {
    Window w;
    EXPECT_TRUE(shpack::parse_window(text, w).ok()) << text;
    out.push_back(w);
  }
  return out;
}

TEST(Window, EveryWindowKeepsL00AndAppliesItsFactorsPerBand) {
  std::mt19937_64 rng(0x5eed);
  for (int trial = 0; trial < 20; ++trial) {
    const ShL2 in = random_ringing(rng);
    for (const Window& w : every_window()) {
      ShL2 out;
      shpack::WindowResult result;
      ASSERT_TRUE(shpack::apply_window(in, w, out, &result).ok());
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(out.c[c][0], in.c[c][0]) << shpack::window_name(w).text << " c=" << c;
        EXPECT_EQ(result.factors[c][0], 1.0);
        for (int i = 0; i < 9; ++i)
          EXPECT_EQ(out.c[c][i], result.factors[c][shpack::kBand[i]] * in.c[c][i]) << shpack::window_name(w).text;
      }
    }
  }
}

// Sloan's family, written out: w_l = sinc(pi l / W)^4 for l < W, else 0 (window.h).
std::array<double, 3> sloan_family(long double width) {
  std::array<double, 3> f = {1, 0, 0};
  for (int l = 1; l < 3; ++l)
    if (l < width) {
      const long double x = std::numbers::pi_v<long double> * l / width;
      f[l] = static_cast<double>(std::pow(std::sin(x) / x, 4));
    }
  return f;
}

// The width W > 1 with sinc(pi / W)^4 = w_1, by bisection in long double (sinc is
// decreasing on (0, pi)).
long double width_of(double w1) {
  long double lo = 0, hi = std::numbers::pi_v<long double>;  // x = pi / W
  const long double target = std::pow(static_cast<long double>(w1), 0.25L);
  for (int it = 0; it < 200; ++it) {
    const long double mid = (lo + hi) / 2;
    (std::sin(mid) / mid > target ? lo : hi) = mid;
  }
  return std::numbers::pi_v<long double> / ((lo + hi) / 2);
}

double minimum_with(const ShL2& in, int c, const std::array<double, 3>& f) {
  ShL2 w;
  for (int i = 0; i < 9; ++i) w.c[c][i] = f[shpack::kBand[i]] * in.c[c][i];
  return shpack::minimum_on_sphere(w, c).value;
}

TEST(Window, SloanIsTheSmallestWindowThatRemovesTheRinging) {
  // For a directional light (every channel rings: minimum -19E/(480 pi)) and random ringing
  // lobes: after sloan the exact minimum is >= 0 (the bisection keeps that invariant with the
  // same arithmetic), a dense brute force agrees to rounding, and the window is minimal: its
  // width W, recovered from w_1, reproduces w_2 (so the family is sinc^4), and the window
  // of width W (1 + 1e-9) - wider than the bisection's last ringing width, which is within
  // 1e-12 W - rings again. Printed: the minimum after sloan, in units of E.
  std::mt19937_64 rng(0x5eed);
  const std::vector<shpack::Dir3> points = fibonacci_sphere(4000);
  Window sloan;
  ASSERT_TRUE(shpack::parse_window("sloan", sloan).ok());
  double worst_min = 0;
  for (int trial = 0; trial < 24; ++trial) {
    ShL2 in;
    if (trial < 8) {  // a directional light, E = 1, 1e6, 1e-6 per channel
      const shpack::Dir3 d = random_direction(rng);
      const std::array<double, 9> y = unity_basis_slow(d.x, d.y, d.z);
      ShL2 radiance;
      const double e[3] = {1.0, 1e6, 1e-6};
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 9; ++i) radiance.c[c][i] = e[c] * y[i];
      in = shpack::radiance_to_unity_form(radiance);
    } else {
      in = random_ringing(rng);
    }
    ShL2 out;
    shpack::WindowResult result;
    ASSERT_TRUE(shpack::apply_window(in, sloan, out, &result).ok());
    for (int c = 0; c < 3; ++c) {
      ASSERT_LT(shpack::minimum_on_sphere(in, c).value, 0.0) << "trial " << trial << " c=" << c << " must ring";
      EXPECT_FALSE(result.impossible[c]);
      const double after = shpack::minimum_on_sphere(out, c).value;
      EXPECT_GE(after, 0.0) << "trial " << trial << " c=" << c;
      double brute = INFINITY, scale = 0;
      for (const shpack::Dir3& p : points) brute = std::min(brute, shpack::eval_unity_form(out, c, p.x, p.y, p.z));
      for (double s : out.c[c]) scale += std::fabs(s);
      EXPECT_GE(brute, -32 * kU * 2 * scale) << "trial " << trial << " c=" << c;
      const std::array<double, 3>& f = result.factors[c];
      EXPECT_LT(f[1], 1.0);
      EXPECT_LT(f[2], 1.0);
      const long double width = width_of(f[1]);
      ASSERT_GT(width, 1.0L);
      const std::array<double, 3> again = sloan_family(width);
      EXPECT_NEAR(again[1], f[1], 1e-15) << "trial " << trial;
      // W from the double w_1 is good to ~1e-16 relative (long-double inversion), times
      // the conditioning of sinc^4 away from its zero: 1e-12 is ample.
      EXPECT_NEAR(again[2], f[2], 1e-12) << "trial " << trial << ": w_2 = sinc(2 pi / W)^4 of the same W";
      EXPECT_LT(minimum_with(in, c, sloan_family(width * (1 + 1e-9L))), 0.0)
          << "trial " << trial << " c=" << c << ": a slightly wider window must still ring (W = " << static_cast<double>(width) << ")";
      worst_min = std::max(worst_min, after / std::fabs(in.c[c][0]));
    }
  }
  std::cout << "[ measure  ] sloan: max minimum of E/pi after the window = " << worst_min
            << " x L00 (>= 0 required; 0 = the ringing just removed)\n";
}

TEST(Window, SloanLeavesNonRingingChannelsAndReportsImpossibleChannels) {
  // Channel 0 does not ring (a mild gradient): unchanged. Channel 1 has L00 < 0: its mean is
  // negative, so no window of the family (all keep L00) can make it non-negative: reported,
  // left unwindowed. Channel 2 has L00 = 0 and rings: possible, at the limit W -> 1, which
  // leaves only L00 = 0: minimum exactly 0.
  ShL2 in;
  in.c[0] = {1.0, 0.1, -0.05, 0.2, 0.01, 0, 0.02, 0, -0.01};
  in.c[1] = {-0.5, 0.3, 0, 0, 0, 0, 0, 0, 0};
  in.c[2] = {0.0, 0.3, 0.1, 0, 0, 0.05, 0, 0, 0};
  ASSERT_GE(shpack::minimum_on_sphere(in, 0).value, 0.0);
  Window sloan;
  ASSERT_TRUE(shpack::parse_window("sloan", sloan).ok());
  ShL2 out;
  shpack::WindowResult result;
  ASSERT_TRUE(shpack::apply_window(in, sloan, out, &result).ok());
  EXPECT_EQ(out.c[0], in.c[0]);
  EXPECT_EQ(result.factors[0], (std::array<double, 3>{1, 1, 1}));
  EXPECT_FALSE(result.impossible[0]);
  EXPECT_TRUE(result.impossible[1]);
  EXPECT_EQ(out.c[1], in.c[1]) << "an impossible channel is left unwindowed";
  EXPECT_EQ(result.factors[1], (std::array<double, 3>{1, 1, 1}));
  EXPECT_FALSE(result.impossible[2]);
  EXPECT_GE(shpack::minimum_on_sphere(out, 2).value, 0.0);
  EXPECT_EQ(out.c[2][0], 0.0);
}

}  // namespace
}  // namespace shpack_test
