#include "shpack/study/pareto_front.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shpack::study {

std::vector<FrontPoint> pareto_front(std::vector<FrontPoint> points) {
  std::erase_if(points, [](const FrontPoint& p) { return std::isnan(p.time_ms) || std::isnan(p.err_pct); });
  std::stable_sort(points.begin(), points.end(), [](const FrontPoint& a, const FrontPoint& b) {
    return a.time_ms < b.time_ms || (a.time_ms == b.time_ms && a.err_pct < b.err_pct);
  });
  std::vector<FrontPoint> front;
  double best = std::numeric_limits<double>::infinity();
  for (const FrontPoint& p : points) {
    if (p.err_pct < best) {
      best = p.err_pct;
      front.push_back(p);
    }
  }
  return front;
}

}  // namespace shpack::study
