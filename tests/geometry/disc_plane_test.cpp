#include <gtest/gtest.h>

#include "shape_checks.hpp"
#include "snell/geometry/disc.hpp"
#include "snell/geometry/plane.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

TEST(PlaneTest, DistanceIsNotRescaledByNormalLength) {
  // POV-Ray 3.7 Parse_Plane normalises the normal but keeps the distance: plane { 2*y, 1 } is y = 1.
  const Plane plane({0, 2, 0}, 1);
  LocalHit hit;
  ASSERT_TRUE(plane.intersect({{0, 5, 0}, {0, -2, 0}, 0}, 0, kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 2.0);
  expect_near(hit.normal, {0, 1, 0}, 0);
  EXPECT_TRUE(plane.inside({0, 0.9, 0}));
  EXPECT_FALSE(plane.inside({0, 1.1, 0}));
}

TEST(PlaneTest, ParallelBehindAndDegenerate) {
  const Plane plane({0, 1, 0}, 0);
  LocalHit hit;
  EXPECT_FALSE(plane.intersect({{0, 1, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_FALSE(plane.intersect({{0, 1, 0}, {0, 1, 0}, 0}, 0, kInfinity, hit));
  EXPECT_THROW(Plane({0, 0, 0}, 1), std::invalid_argument);
}

TEST(DiscTest, HitInsideRingOnly) {
  const Disc disc({0, 1, 0}, {0, 3, 0}, 2, 0.5);
  LocalHit hit;
  ASSERT_TRUE(disc.intersect({{1, 5, 0}, {0, -0.5, 0}, 0}, 0, kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 8.0);
  expect_near(hit.normal, {0, 1, 0}, 0);
  EXPECT_FALSE(disc.intersect({{0.25, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hit));  // in the hole
  EXPECT_FALSE(disc.intersect({{2.5, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hit));   // beyond the rim
  EXPECT_FALSE(disc.intersect({{1, 5, 0}, {0, 1, 0}, 0}, 0, kInfinity, hit));      // behind
  HitList hits;
  disc.all_hits({{1, -5, 0}, {0, 1, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_DOUBLE_EQ(hits[0].t, 6.0);
}

TEST(DiscTest, InsideIsTheHalfSpaceBelowAsPovRay) {
  const Disc disc({0, 0, 0}, {0, 0, 1}, 1, 0);
  EXPECT_TRUE(disc.inside({5, 5, -0.1}));  // far outside the radius, still below: inside
  EXPECT_FALSE(disc.inside({0, 0, 0.1}));
}

TEST(DiscTest, TiltedDiscBoundsHoldEveryHit) {
  shape_checks::check_random_rays(Disc({0.5, 0, 0}, {1, 2, 0.5}, 1.5, 0.3), false);
}

TEST(DiscTest, BadInputThrows) {
  EXPECT_THROW(Disc({0, 0, 0}, {0, 0, 0}, 1, 0), std::invalid_argument);
  EXPECT_THROW(Disc({0, 0, 0}, {0, 1, 0}, -1, 0), std::invalid_argument);
}
