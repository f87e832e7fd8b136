#include "shpack/srgb.h"

#include <gtest/gtest.h>

#include <cmath>

namespace shpack::io {
namespace {

TEST(Srgb, EndpointsAreFixed) {
  EXPECT_EQ(srgb_to_linear(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgb_to_linear(1.0), 1.0);
}

TEST(Srgb, LinearSegmentBelowThreshold) {
  EXPECT_DOUBLE_EQ(srgb_to_linear(0.04), 0.04 / 12.92);
  EXPECT_DOUBLE_EQ(srgb_to_linear(0.04045), 0.04045 / 12.92);
}

TEST(Srgb, PowerSegmentAboveThreshold) {
  EXPECT_DOUBLE_EQ(srgb_to_linear(0.5), std::pow(0.555 / 1.055, 2.4));
  // 128/255, the 8-bit middle grey: 0.2158605 (IEC 61966-2-1 tables).
  EXPECT_NEAR(srgb_to_linear(128.0 / 255.0), 0.21586050011389926, 1e-15);
}

TEST(Srgb, PiecesMeetAtTheThreshold) {
  // The two pieces of IEC 61966-2-1 differ by ~2e-9 at c = 0.04045 (the standard's
  // rounded constants); the function must not jump by more than that.
  const double below = 0.04045 / 12.92;
  const double above = std::pow((0.04045 + 0.055) / 1.055, 2.4);
  EXPECT_NEAR(below, above, 1e-7);
  EXPECT_LE(srgb_to_linear(0.04045), srgb_to_linear(std::nextafter(0.04045, 1.0)));
}

TEST(Srgb, IsNotTheGammaApproximation) {
  // c^2.2 is what a careless decoder uses; in the darks it is far from the EOTF.
  const double c = 20.0 / 255.0;
  EXPECT_GT(std::abs(srgb_to_linear(c) - std::pow(c, 2.2)) / srgb_to_linear(c), 0.1);
}

}  // namespace
}  // namespace shpack::io
