// simplex.h (private) - a small linear program: the largest c . x over
//   { x in R^n : A x <= b, x >= 0 },  b >= 0 (so x = 0 is a feasible vertex to start from),
// by the simplex method on the dictionary [V. Chvatal, "Linear Programming", 1983, ch. 2]:
// the m slack (basic) variables are kept written in the n non-basic ones, an m x n array, so a
// pivot costs O(m n) where a full tableau would cost O(m (m + n)). Made for many rows and few
// columns (the light fit of light_fit.h: ~1500 rows, at most 9 columns).
//
// Pivoting: Bland's rule (of the improving non-basic variables the one of smallest index
// enters; of the rows tying in the ratio test the basic variable of smallest index leaves),
// which never cycles [Chvatal, thm 3.3], so the method ends at an optimal vertex or finds the
// problem unbounded after finitely many pivots; kMaxSimplexPivots bounds them all the same.
//
// Rounding: a coefficient counts as positive above kSimplexTolerance times the largest |A_ij|
// (an entering cost above that times the largest |c_j|): the data should be scaled to O(1)
// by the caller. The values of the basic variables are kept >= 0 (a rounding to -1e-17 is
// set to 0), so the result is feasible up to rounding.
#pragma once

#include <cstddef>
#include <vector>

namespace shpack {

inline constexpr std::size_t kMaxSimplexPivots = 10000;
inline constexpr double kSimplexTolerance = 1e-12;

struct LinearProgram {
  std::size_t rows = 0, cols = 0;
  std::vector<double> a;  // rows x cols, row-major
  std::vector<double> b;  // rows, each >= 0
  std::vector<double> c;  // cols
};

enum class LpOutcome { Optimal, Unbounded, PivotLimit };

struct LpSolution {
  LpOutcome outcome = LpOutcome::Optimal;
  std::vector<double> x;  // cols: the last vertex reached (optimal when outcome is Optimal)
  double value = 0;       // c . x there
  std::size_t pivots = 0;
};

// May throw std::bad_alloc. The caller guarantees the shapes and b >= 0.
LpSolution maximize(const LinearProgram& lp);

}  // namespace shpack
