#include "snell/geometry/sphere.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::math::kInfinity;

TEST(SphereTest, HitsAtCentreDistanceMinusRadiusAndFromInside) {
  const Sphere sphere({1, 2, 3}, 2);
  HitList hits;
  sphere.all_hits({{1, 2, -7}, {0, 0, 0.5}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 16, 1e-12);
  EXPECT_NEAR(hits[1].t, 24, 1e-12);
  LocalHit hit;
  ASSERT_TRUE(sphere.intersect({{1, 2, 3}, {0, 2, 0}, 0}, 1e-9, kInfinity, hit));
  EXPECT_NEAR(hit.t, 1, 1e-12);
  EXPECT_FALSE(sphere.intersect({{1, 2, -7}, {0, 0, -1}, 0}, 0, kInfinity, hit));
}

TEST(SphereTest, RandomRays) {
  shape_checks::check_random_rays(Sphere({0.5, -1, 2}, 1.3), true);
}
