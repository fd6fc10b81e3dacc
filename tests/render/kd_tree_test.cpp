// The photon kd-tree's k-nearest answers against a brute-force scan of the same points.
#include "snell/render/photons/kd_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "snell/math/pcg32.hpp"

namespace snell::render::photons {
namespace {

std::vector<Neighbour> brute_force(const std::vector<math::Vec3>& points, const math::Vec3& c, size_t k,
                                   double radius) {
  std::vector<Neighbour> all;
  for (size_t i = 0; i < points.size(); ++i) {
    const math::Vec3 d = points[i] - c;
    if (dot(d, d) <= radius * radius) all.push_back({static_cast<uint32_t>(i), dot(d, d)});
  }
  std::sort(all.begin(), all.end(), [](const Neighbour& a, const Neighbour& b) {
    return a.distance_squared != b.distance_squared ? a.distance_squared < b.distance_squared
                                                    : a.index < b.index;
  });
  if (all.size() > k) all.resize(k);
  return all;
}

TEST(KdTreeTest, NearestMatchesBruteForce) {
  math::Pcg32 rng(7, 3);
  std::vector<math::Vec3> points;
  for (int i = 0; i < 3000; ++i)
    points.push_back({rng.next_double(), rng.next_double(), 0.1 * rng.next_double()});
  // Duplicates and points on a grid make ties that the index order must break the same way.
  for (int i = 0; i < 200; ++i) points.push_back({0.1 * (i % 10), 0.1 * (i / 10 % 10), 0.0});
  for (int i = 0; i < 50; ++i) points.push_back(points[static_cast<size_t>(i)]);
  const KdTree tree(points);
  ASSERT_EQ(tree.size(), points.size());
  std::vector<Neighbour> reused;
  for (int q = 0; q < 300; ++q) {
    const math::Vec3 c{rng.next_double(), rng.next_double(), 0.05};
    const size_t k = 1 + static_cast<size_t>(q % 40);
    const double radius = q % 3 == 0 ? 0.03 : 0.2;
    const auto expected = brute_force(points, c, k, radius);
    const auto got = tree.nearest(c, k, radius);
    ASSERT_EQ(got.size(), expected.size()) << "query " << q;
    // The same answer into a buffer kept from the previous query (larger k then, so stale entries).
    tree.nearest(c, k, radius, reused);
    ASSERT_EQ(reused.size(), got.size()) << "query " << q;
    for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(reused[i].index, got[i].index);
    for (size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].index, expected[i].index) << "query " << q << " rank " << i;
      EXPECT_DOUBLE_EQ(got[i].distance_squared, expected[i].distance_squared);
    }
    // Unsorted: the same points, and the farthest of them reported.
    const double farthest = tree.nearest_in_any_order(c, k, radius, reused);
    std::vector<uint32_t> in_any_order, in_order;
    for (const Neighbour& n : reused) in_any_order.push_back(n.index);
    for (const Neighbour& n : expected) in_order.push_back(n.index);
    std::sort(in_any_order.begin(), in_any_order.end());
    std::sort(in_order.begin(), in_order.end());
    EXPECT_EQ(in_any_order, in_order) << "query " << q;
    EXPECT_EQ(farthest, expected.empty() ? 0.0 : expected.back().distance_squared) << "query " << q;
  }
}

TEST(KdTreeTest, PointsExactlyAtTheRadiusAreKept) {
  // A grid of spacing 0.125 (exact in binary): from a grid point, its neighbours lie at exactly the radius
  // 0.125 or 0.125 * sqrt 2, where the cell-distance pruning must not drop them.
  std::vector<math::Vec3> points;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      for (int l = 0; l < 4; ++l) points.push_back({0.125 * i, 0.125 * j, 0.125 * l});
  const KdTree tree(points);
  for (const double radius : {0.125, 0.125 * std::sqrt(2.0), 0.25})
    for (size_t q = 0; q < points.size(); q += 37) {
      const auto expected = brute_force(points, points[q], 1000, radius);
      const auto got = tree.nearest(points[q], 1000, radius);
      ASSERT_EQ(got.size(), expected.size()) << "point " << q << " radius " << radius;
      for (size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].index, expected[i].index);
    }
}

TEST(KdTreeTest, EmptyTreeAndZeroKFindNothing) {
  EXPECT_TRUE(KdTree({}).nearest({0, 0, 0}, 5, 1).empty());
  EXPECT_TRUE(KdTree({{0, 0, 0}}).nearest({0, 0, 0}, 0, 1).empty());
  EXPECT_EQ(KdTree({{0, 0, 0}}).nearest({0.5, 0, 0}, 3, 1).size(), 1u);
}

}  // namespace
}  // namespace snell::render::photons
