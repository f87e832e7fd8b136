// nearest_probes.h (private) - the k nearest of a fixed set of probes to a point, for
// dilation (probe_validity.h).
//
// A k-d tree (Bentley, "Multidimensional binary search trees used for associative
// searching", CACM 1975) split at the median of the widest axis, searched for the k nearest
// as Friedman, Bentley and Finkel (ACM TOMS 1977) do: the near side first, the far side only
// if the splitting plane is closer than the k-th best so far. The answer is exact and ties in
// distance go to the lower id, so it does not depend on the tree's shape.
#pragma once

#include <cstddef>
#include <vector>

#include "shpack/vec3.h"

namespace shpack::bake {

struct NearProbe {
  double distance2 = 0;  // squared distance to the query
  std::size_t id = 0;
};

class NearestProbes {
 public:
  // points[j] has id ids[j]; both the same size.
  NearestProbes(std::vector<Vec3> points, std::vector<std::size_t> ids);
  // The min(k, size) nearest to q, nearest first, ties by id.
  std::vector<NearProbe> nearest(const Vec3& q, std::size_t k) const;

 private:
  struct Node {
    Vec3 point;
    std::size_t id;
    int axis;  // 0, 1, 2: x, y, z; the split of the subtree this node is the median of
  };
  void build(std::size_t begin, std::size_t end);
  void search(std::size_t begin, std::size_t end, const Vec3& q, std::size_t k, std::vector<NearProbe>& best) const;
  std::vector<Node> nodes_;  // each subtree [begin, end) has its median at (begin + end) / 2
};

}  // namespace shpack::bake
