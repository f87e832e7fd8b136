// Tests of the k-nearest search that dilation uses (lib/bake/src/nearest_probes.h): the same
// answer as a brute-force sort by (squared distance, id), ties and coincident points included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "nearest_probes.h"

namespace shpack::bake {
namespace {

std::vector<NearProbe> brute_force(const std::vector<Vec3>& points, const std::vector<std::size_t>& ids,
                                   const Vec3& q, std::size_t k) {
  std::vector<NearProbe> all;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const Vec3 d = q - points[j];
    all.push_back({dot(d, d), ids[j]});
  }
  std::sort(all.begin(), all.end(), [](const NearProbe& a, const NearProbe& b) {
    return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.id < b.id);
  });
  all.resize(std::min(all.size(), k));
  return all;
}

TEST(NearestProbes, MatchesBruteForceOnAGridWithTiesAndOnRandomPoints) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (const bool grid : {true, false}) {
    std::vector<Vec3> points;
    std::vector<std::size_t> ids;
    for (std::size_t j = 0; j < 1500; ++j) {
      // A grid of spacing 0.5 (many equal distances, some coincident points) or random.
      const Vec3 p = grid ? Vec3{0.5 * static_cast<double>(j % 11), 0.5 * static_cast<double>((j / 11) % 7),
                                 0.5 * static_cast<double>((j / 77) % 13)}
                          : Vec3{u(rng), u(rng), u(rng)};
      points.push_back(p);
      ids.push_back(3 * j + 1);  // ids need not be positions in the list
    }
    const NearestProbes tree(points, ids);
    for (int query = 0; query < 300; ++query) {
      const Vec3 q = grid && query % 2 ? points[static_cast<std::size_t>(query)] : Vec3{u(rng), u(rng), u(rng)};
      for (const std::size_t k : {std::size_t{1}, std::size_t{8}, std::size_t{40}}) {
        const std::vector<NearProbe> got = tree.nearest(q, k), want = brute_force(points, ids, q, k);
        ASSERT_EQ(got.size(), want.size());
        for (std::size_t n = 0; n < got.size(); ++n) {
          EXPECT_EQ(got[n].id, want[n].id) << "grid " << grid << " query " << query << " k " << k << " n " << n;
          EXPECT_EQ(got[n].distance2, want[n].distance2);
        }
      }
    }
  }
  EXPECT_TRUE(NearestProbes({}, {}).nearest({0, 0, 0}, 8).empty());
  EXPECT_EQ(NearestProbes({{1, 2, 3}}, {5}).nearest({0, 0, 0}, 8).size(), 1u) << "fewer than k";
}

}  // namespace
}  // namespace shpack::bake
