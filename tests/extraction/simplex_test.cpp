// The linear-program solver of the light fit (lib/src/common/simplex.h, private; the light fit
// is its only user): against a brute force over every vertex of small random problems, on a
// degenerate problem (many constraints through one vertex, where a careless pivot rule can
// cycle), and an unbounded one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "common/simplex.h"

namespace shpack {
namespace {

// The largest c . x over the vertices of {A x <= b, x >= 0}: every choice of n of the m + n
// constraints taken as equalities, solved by Gaussian elimination with partial pivoting, kept
// when the solution is feasible. The optimum of a bounded feasible LP is at a vertex.
double brute_force_max(const LinearProgram& lp) {
  const std::size_t n = lp.cols, total = lp.rows + lp.cols;
  double best = -std::numeric_limits<double>::infinity();
  std::vector<std::size_t> pick(n);
  for (std::size_t i = 0; i < n; ++i) pick[i] = i;
  for (;;) {
    std::vector<double> m(n * (n + 1), 0.0);  // [row | rhs]
    for (std::size_t r = 0; r < n; ++r) {
      const std::size_t k = pick[r];
      if (k < lp.rows) {
        for (std::size_t j = 0; j < n; ++j) m[r * (n + 1) + j] = lp.a[k * n + j];
        m[r * (n + 1) + n] = lp.b[k];
      } else {
        m[r * (n + 1) + (k - lp.rows)] = 1.0;  // x_j = 0
      }
    }
    bool singular = false;
    for (std::size_t col = 0; col < n && !singular; ++col) {
      std::size_t p = col;
      for (std::size_t r = col + 1; r < n; ++r)
        if (std::abs(m[r * (n + 1) + col]) > std::abs(m[p * (n + 1) + col])) p = r;
      if (std::abs(m[p * (n + 1) + col]) < 1e-12) {
        singular = true;
        break;
      }
      for (std::size_t j = 0; j <= n; ++j) std::swap(m[col * (n + 1) + j], m[p * (n + 1) + j]);
      for (std::size_t r = 0; r < n; ++r) {
        if (r == col) continue;
        const double f = m[r * (n + 1) + col] / m[col * (n + 1) + col];
        for (std::size_t j = 0; j <= n; ++j) m[r * (n + 1) + j] -= f * m[col * (n + 1) + j];
      }
    }
    if (!singular) {
      std::vector<double> x(n);
      for (std::size_t j = 0; j < n; ++j) x[j] = m[j * (n + 1) + n] / m[j * (n + 1) + j];
      bool feasible = true;
      for (double v : x) feasible = feasible && v >= -1e-9;
      for (std::size_t r = 0; r < lp.rows && feasible; ++r) {
        double lhs = 0;
        for (std::size_t j = 0; j < n; ++j) lhs += lp.a[r * n + j] * x[j];
        feasible = lhs <= lp.b[r] + 1e-9;
      }
      if (feasible) {
        double value = 0;
        for (std::size_t j = 0; j < n; ++j) value += lp.c[j] * x[j];
        best = std::max(best, value);
      }
    }
    // Next combination of n out of total.
    std::size_t i = n;
    while (i > 0 && pick[i - 1] == total - n + i - 1) --i;
    if (i == 0) return best;
    ++pick[i - 1];
    for (std::size_t j = i; j < n; ++j) pick[j] = pick[j - 1] + 1;
  }
}

TEST(Simplex, MatchesTheBestVertexOfRandomProblems) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coef(-1.0, 1.0), rhs(0.0, 2.0);
  for (int trial = 0; trial < 300; ++trial) {
    LinearProgram lp;
    lp.cols = 1 + trial % 4;
    lp.rows = lp.cols + 2 + trial % 7;
    for (std::size_t r = 0; r < lp.rows; ++r) {
      for (std::size_t j = 0; j < lp.cols; ++j) lp.a.push_back(coef(rng));
      lp.b.push_back(r == 0 ? 0.0 : rhs(rng));  // b_0 = 0: a degenerate start
    }
    // A box row keeps it bounded: sum_j x_j <= 3.
    lp.a.insert(lp.a.end(), lp.cols, 1.0);
    lp.b.push_back(3.0);
    ++lp.rows;
    for (std::size_t j = 0; j < lp.cols; ++j) lp.c.push_back(coef(rng));
    const LpSolution solution = maximize(lp);
    ASSERT_EQ(solution.outcome, LpOutcome::Optimal) << trial;
    // Rounding: a few pivots on O(1) data, each losing a few ulps: 1e-9 leaves room.
    EXPECT_NEAR(solution.value, brute_force_max(lp), 1e-9) << trial;
    for (std::size_t r = 0; r < lp.rows; ++r) {
      double lhs = 0;
      for (std::size_t j = 0; j < lp.cols; ++j) lhs += lp.a[r * lp.cols + j] * solution.x[j];
      EXPECT_LE(lhs, lp.b[r] + 1e-9) << trial << " row " << r;
    }
    for (double v : solution.x) EXPECT_GE(v, 0.0);
  }
}

TEST(Simplex, EndsOnADegenerateVertex) {
  // Beale's cycling example (Chvatal, ch. 3): Dantzig's largest-coefficient rule cycles on it;
  // Bland's rule must reach the optimum 1/20 at x = (1/25, 0, 1, 0).
  LinearProgram lp;
  lp.rows = 3;
  lp.cols = 4;
  lp.a = {0.25, -60, -1.0 / 25, 9, 0.5, -90, -1.0 / 50, 3, 0, 0, 1, 0};
  lp.b = {0, 0, 1};
  lp.c = {0.75, -150, 1.0 / 50, -6};
  const LpSolution solution = maximize(lp);
  ASSERT_EQ(solution.outcome, LpOutcome::Optimal);
  EXPECT_NEAR(solution.value, 0.05, 1e-12);
  EXPECT_NEAR(solution.x[0], 0.04, 1e-12);
  EXPECT_NEAR(solution.x[2], 1.0, 1e-12);
}

TEST(Simplex, FindsAnUnboundedProblem) {
  LinearProgram lp;  // max x0 + x1 with x0 - x1 <= 1: x1 grows without bound
  lp.rows = 1;
  lp.cols = 2;
  lp.a = {1, -1};
  lp.b = {1};
  lp.c = {1, 1};
  EXPECT_EQ(maximize(lp).outcome, LpOutcome::Unbounded);
}

}  // namespace
}  // namespace shpack
