#include "nearest_probes.h"

#include <algorithm>

namespace shpack::bake {
namespace {

double coordinate(const Vec3& p, int axis) noexcept { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

bool closer(const NearProbe& a, const NearProbe& b) noexcept {
  return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.id < b.id);
}

// Inserts `candidate` into `best` (sorted by closer, at most k long) if it belongs there.
void offer(std::vector<NearProbe>& best, std::size_t k, const NearProbe& candidate) {
  if (best.size() == k && !closer(candidate, best.back())) return;
  best.insert(std::upper_bound(best.begin(), best.end(), candidate, closer), candidate);
  if (best.size() > k) best.pop_back();
}

}  // namespace

NearestProbes::NearestProbes(std::vector<Vec3> points, std::vector<std::size_t> ids) {
  nodes_.reserve(points.size());
  for (std::size_t j = 0; j < points.size() && j < ids.size(); ++j) nodes_.push_back({points[j], ids[j], 0});
  build(0, nodes_.size());
}

void NearestProbes::build(std::size_t begin, std::size_t end) {
  if (end - begin < 2) return;
  // The widest axis of the subtree's bounding box, so that cells stay compact.
  Vec3 lo = nodes_[begin].point, hi = lo;
  for (std::size_t j = begin; j < end; ++j) {
    const Vec3& p = nodes_[j].point;
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const Vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const std::size_t mid = begin + (end - begin) / 2;
  const auto at = [this](std::size_t j) { return nodes_.begin() + static_cast<std::ptrdiff_t>(j); };
  std::nth_element(at(begin), at(mid), at(end), [axis](const Node& a, const Node& b) {
    return coordinate(a.point, axis) < coordinate(b.point, axis);
  });
  nodes_[mid].axis = axis;
  build(begin, mid);
  build(mid + 1, end);
}

void NearestProbes::search(std::size_t begin, std::size_t end, const Vec3& q, std::size_t k,
                           std::vector<NearProbe>& best) const {
  if (begin >= end) return;
  const std::size_t mid = begin + (end - begin) / 2;
  const Node& node = nodes_[mid];
  const Vec3 d = q - node.point;
  offer(best, k, {dot(d, d), node.id});
  if (end - begin == 1) return;
  // Left of the median: coordinates <= the split; right: >= (nth_element's partition).
  const double split = coordinate(q, node.axis) - coordinate(node.point, node.axis);
  const bool left_first = split < 0;
  if (left_first) search(begin, mid, q, k, best);
  else search(mid + 1, end, q, k, best);
  // The far side can hold a point at least |split| away: visit it unless k closer are known
  // (strictly closer, so that an equally distant point of lower id is still found).
  if (best.size() < k || split * split <= best.back().distance2) {
    if (left_first) search(mid + 1, end, q, k, best);
    else search(begin, mid, q, k, best);
  }
}

std::vector<NearProbe> NearestProbes::nearest(const Vec3& q, std::size_t k) const {
  std::vector<NearProbe> best;
  if (k == 0) return best;
  best.reserve(k + 1);
  search(0, nodes_.size(), q, k, best);
  return best;
}

}  // namespace shpack::bake
