// The greedy choice among light candidates (light_choice.h), with error measures made by hand:
// a table of the error of each set of candidates. It picks the candidate that lowers the error
// most at each step, never one that does not lower it, stops at max_lights, breaks ties by the
// lower index, calls the measure 1 + sum_s (K - s) times, and gives the same choice twice;
// a settling step after each choice lowers its error and may never raise it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <vector>

#include "shpack/light_candidates.h"
#include "shpack/light_choice.h"
#include "support/test_util.h"

namespace shpack {
namespace {

// The error of a set of candidates (bit k: candidate k chosen), as a table; it records what it
// was asked. A set missing from the table is a test error.
struct TableMeasure {
  std::map<unsigned, double> error;
  std::vector<std::vector<std::size_t>> asked;

  Status operator()(std::span<const std::size_t> chosen, double& out) {
    asked.emplace_back(chosen.begin(), chosen.end());
    unsigned set = 0;
    for (std::size_t k : chosen) set |= 1u << k;
    const auto it = error.find(set);
    EXPECT_NE(it, error.end()) << "set " << set;
    out = it == error.end() ? 0 : it->second;
    return Status::success();
  }
};

// Four candidates: alone, 1 lowers the error most (20 -> 12); after it, 2 (-> 8); after both,
// 0 only matches 8 and 3 raises it, so the choice stops at two lights.
TableMeasure four_candidates() {
  return {{{0b0000, 20},  {0b0001, 15},  {0b0010, 12},  {0b0100, 18},  {0b1000, 25},
           {0b0011, 9},   {0b0110, 8},   {0b1010, 13},  {0b0111, 8},   {0b1110, 11}},
          {}};
}

const std::vector<LightCandidate> kFour(4);

TEST(LightChoice, PicksWhatLowersTheErrorMostAndStopsWhenNothingLowersIt) {
  TableMeasure measure = four_candidates();
  LightChoice choice;
  ASSERT_TRUE(choose_lights(kFour, 8, measure, choice).ok());
  EXPECT_EQ(choice.error_without, 20);
  ASSERT_EQ(choice.lights.size(), 2u);
  EXPECT_EQ(choice.lights[0], (ChosenLight{1, 20, 12}));
  EXPECT_EQ(choice.lights[1], (ChosenLight{2, 12, 8}));
  // 1 + 4 + 3 + 2 calls: none, each of four, each of three after 1, each of two after 1 and 2;
  // each set asked in the order chosen, the one tried last.
  EXPECT_EQ(choice.evaluations, 10u);
  ASSERT_EQ(measure.asked.size(), 10u);
  EXPECT_TRUE(measure.asked[0].empty());
  EXPECT_EQ(measure.asked[5], (std::vector<std::size_t>{1, 0}));
  EXPECT_EQ(measure.asked[9], (std::vector<std::size_t>{1, 2, 3}));
}

TEST(LightChoice, StopsAtMaxLights) {
  TableMeasure measure = four_candidates();
  LightChoice choice;
  ASSERT_TRUE(choose_lights(kFour, 1, measure, choice).ok());
  ASSERT_EQ(choice.lights.size(), 1u);
  EXPECT_EQ(choice.lights[0].candidate, 1u);
  EXPECT_EQ(choice.evaluations, 5u);  // 1 + K, the bound 1 + K N for N = 1
  ASSERT_TRUE(choose_lights(kFour, 0, measure, choice).ok());
  EXPECT_TRUE(choice.lights.empty());
  EXPECT_EQ(choice.evaluations, 1u);
  EXPECT_EQ(choice.error_without, 20);
}

TEST(LightChoice, NeverAddsALightThatDoesNotLowerTheError) {
  // Every candidate raises the error or leaves it.
  TableMeasure measure{{{0b00, 5}, {0b01, 5}, {0b10, 7}}, {}};
  LightChoice choice;
  ASSERT_TRUE(choose_lights(std::vector<LightCandidate>(2), 8, measure, choice).ok());
  EXPECT_TRUE(choice.lights.empty());
  EXPECT_EQ(choice.evaluations, 3u);
  // No candidate at all: only the error without lights.
  ASSERT_TRUE(choose_lights({}, 8, measure, choice).ok());
  EXPECT_TRUE(choice.lights.empty());
  EXPECT_EQ(choice.evaluations, 1u);
}

TEST(LightChoice, BreaksTiesByTheLowerIndexAndChoosesTheSameTwice) {
  TableMeasure measure{{{0b000, 10}, {0b001, 6}, {0b010, 4}, {0b100, 4}, {0b110, 3}, {0b011, 3}, {0b111, 3}}, {}};
  LightChoice first, second;
  ASSERT_TRUE(choose_lights(std::vector<LightCandidate>(3), 3, measure, first).ok());
  ASSERT_EQ(first.lights.size(), 2u);
  EXPECT_EQ(first.lights[0].candidate, 1u);  // 1 and 2 both give 4
  EXPECT_EQ(first.lights[1].candidate, 0u);  // 0 and 2 both give 3
  ASSERT_TRUE(choose_lights(std::vector<LightCandidate>(3), 3, measure, second).ok());
  EXPECT_EQ(second, first);
}

TEST(LightChoice, SettlingLowersEachStepsErrorAndIsCalledOncePerStep) {
  // The settling step lowers the chosen set's error by 1 (a measure that then sees the
  // settled lights would give that): each step's error_after is the settled one, and the
  // next step starts from it.
  TableMeasure measure = four_candidates();
  std::vector<std::vector<std::size_t>> settled;
  auto settle = [&](std::span<const std::size_t> chosen, double& error) {
    settled.emplace_back(chosen.begin(), chosen.end());
    error -= 1;
    return Status::success();
  };
  LightChoice choice;
  ASSERT_TRUE(choose_lights(kFour, 8, measure, choice, settle).ok());
  ASSERT_EQ(choice.lights.size(), 2u);
  EXPECT_EQ(choice.lights[0], (ChosenLight{1, 20, 11}));
  EXPECT_EQ(choice.lights[1], (ChosenLight{2, 11, 7}));
  EXPECT_EQ(settled, (std::vector<std::vector<std::size_t>>{{1}, {1, 2}}));
}

TEST(LightChoice, RefusesASettlingThatRaisesTheError) {
  TableMeasure measure = four_candidates();
  auto raising = [](std::span<const std::size_t>, double& error) {
    error += 1;
    return Status::success();
  };
  LightChoice choice;
  EXPECT_EQ(choose_lights(kFour, 8, measure, choice, raising).code, Errc::InvalidArgument);
}

TEST(LightChoice, PassesOnTheMeasuresFailureAndRefusesANonFiniteError) {
  LightChoice choice;
  int calls = 0;
  auto failing = [&](std::span<const std::size_t>, double& error) {
    error = 1;
    return ++calls == 3 ? Status::error(Errc::OutOfRange, "test") : Status::success();
  };
  EXPECT_EQ(choose_lights(kFour, 4, failing, choice).code, Errc::OutOfRange);
  EXPECT_EQ(choice.evaluations, 3u);
  auto not_finite = [](std::span<const std::size_t> chosen, double& error) {
    error = chosen.empty() ? 10 : std::numeric_limits<double>::quiet_NaN();
    return Status::success();
  };
  EXPECT_EQ(choose_lights(kFour, 4, not_finite, choice).code, Errc::InvalidArgument);
}

}  // namespace
}  // namespace shpack
