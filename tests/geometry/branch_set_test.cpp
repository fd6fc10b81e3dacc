// Round cones (geometry/branch_set.hpp) against analytic crossings of cylinders, cones and spheres.
#include <gtest/gtest.h>

#include <cmath>

#include "snell/geometry/branch_set.hpp"
#include "snell/math/constants.hpp"

namespace snell::geometry {
namespace {

TEST(BranchSet, CylinderSideAndSphereCaps) {
  const BranchInput b[] = {{Vec3(0, 0, 0), Vec3(0, 2, 0), 0.5, 0.5}};
  const BranchSet set(b);
  LocalHit hit;
  ASSERT_TRUE(set.intersect({Vec3(-5, 1, 0), Vec3(1, 0, 0), 0}, 0, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4.5, 1e-6);
  EXPECT_NEAR(normalize(hit.normal).x, -1, 1e-6);
  // Along the axis: the cap sphere at the top reaches y = 2.5, the bottom one y = -0.5.
  ASSERT_TRUE(set.intersect({Vec3(0, 5, 0), Vec3(0, -2, 0), 0}, 0, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 1.25, 1e-6);  // direction not unit: t = 2.5 / 2
  HitList hits;
  set.all_hits({Vec3(0, 5, 0), Vec3(0, -1, 0), 0}, 0, math::kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);  // the inner crossings (cylinder ends inside the spheres) are dropped
  EXPECT_NEAR(hits[1].t, 5.5, 1e-6);
  EXPECT_TRUE(set.inside(Vec3(0.4, 1, 0)));
  EXPECT_TRUE(set.inside(Vec3(0, 2.4, 0)));
  EXPECT_FALSE(set.inside(Vec3(0.6, 1, 0)));
  EXPECT_FALSE(set.intersect({Vec3(-5, 3, 0), Vec3(1, 0, 0), 0}, 0, math::kInfinity, hit));
}

TEST(BranchSet, ConeSideMatchesTheLinearRadius) {
  // Radius 1 at y = 0 to 0.5 at y = 2: at y = 1 the radius is 0.75.
  const BranchInput b[] = {{Vec3(0, 0, 0), Vec3(0, 2, 0), 1.0, 0.5}};
  const BranchSet set(b);
  LocalHit hit;
  ASSERT_TRUE(set.intersect({Vec3(-5, 1, 0), Vec3(1, 0, 0), 0}, 0, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 5 - 0.75, 1e-6);
  // The side's normal tilts up by atan(0.25) (the slope of the radius).
  const Vec3 n = normalize(hit.normal);
  EXPECT_NEAR(n.y / -n.x, 0.25, 1e-6);
}

TEST(BranchSet, ManyBranchesStayCompact) {
  // 2^16 branches along a zigzag: the shape (branches and BVH) stays under 64 bytes per branch.
  std::vector<BranchInput> branches;
  for (int i = 0; i < (1 << 16); ++i)
    branches.push_back({Vec3(i % 512, i / 512, 0), Vec3(i % 512 + 1, i / 512, 0.5), 0.1, 0.1});
  const BranchSet set(branches);
  EXPECT_EQ(set.size(), branches.size());
  EXPECT_LT(static_cast<double>(set.bytes()) / static_cast<double>(set.size()), 64.0);
  LocalHit hit;
  ASSERT_TRUE(set.intersect({Vec3(100.5, 100, -5), Vec3(0, 0, 1), 0}, 0, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 5 + 0.25 - 0.1 * std::sqrt(1.25), 1e-3);
}

}  // namespace
}  // namespace snell::geometry
