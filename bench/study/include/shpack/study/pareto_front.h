// pareto_front.h - which method to pick for a time budget: the specs that no faster spec
// beats in error (a Pareto front over time and error).
#pragma once

#include <string>
#include <vector>

namespace shpack::study {

struct FrontPoint {
  std::string spec;
  double time_ms = 0;
  double err_pct = 0;
  std::string kind;  // of err_pct (expected_error.h)
  double samples = 0;  // what the point spends: samples per projection, probe or texel
};

// The front, fastest first: each point has less error than every point at most as fast
// (ties in time: the lower error). Points with a NaN time or error are left out. For a budget
// of T ms, the last point with time_ms <= T is the least error T buys.
std::vector<FrontPoint> pareto_front(std::vector<FrontPoint> points);

}  // namespace shpack::study
