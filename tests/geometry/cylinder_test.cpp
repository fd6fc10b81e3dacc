#include "snell/geometry/cylinder.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

TEST(CylinderTest, SideHitsAtRadius) {
  const Cylinder cyl({0, -1, 0}, {0, 1, 0}, 0.5, false);
  HitList hits;
  cyl.all_hits({{-3, 0, 0}, {0.5, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 5.0, 1e-12);  // x = -0.5 at t = 2.5 / 0.5
  EXPECT_NEAR(hits[1].t, 7.0, 1e-12);
  expect_near(hits[0].normal, {-1, 0, 0}, 1e-12);
  expect_near(hits[1].normal, {1, 0, 0}, 1e-12);
}

TEST(CylinderTest, ClosedHasCapsOpenHasNone) {
  const Ray along{{0.1, -5, 0}, {0, 1, 0}, 0};
  HitList closed_hits, open_hits;
  Cylinder({0, -1, 0}, {0, 1, 0}, 0.5, false).all_hits(along, 0, kInfinity, closed_hits);
  Cylinder({0, -1, 0}, {0, 1, 0}, 0.5, true).all_hits(along, 0, kInfinity, open_hits);
  ASSERT_EQ(closed_hits.size(), 2u);
  EXPECT_DOUBLE_EQ(closed_hits[0].t, 4.0);
  EXPECT_DOUBLE_EQ(closed_hits[1].t, 6.0);
  expect_near(closed_hits[0].normal, {0, -1, 0}, 0);
  expect_near(closed_hits[1].normal, {0, 1, 0}, 0);
  EXPECT_TRUE(open_hits.empty());
}

TEST(CylinderTest, OpenCylinderSeenThroughTheEnd) {
  // A slanted ray entering through the open end meets the inside of the wall.
  const Cylinder cyl({0, 0, 0}, {0, 0, 4}, 1, true);
  HitList hits;
  cyl.all_hits({{0, 0, -1}, {0.25, 0, 1}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].t, 4.0, 1e-12);  // x = 1 at t = 4, z = 3
}

TEST(CylinderTest, ArbitraryAxisAndFromInside) {
  const Vec3 a{1, 2, 3}, b{4, 6, 3};  // axis length 5 in the xy plane
  const Cylinder cyl(a, b, 2, false);
  LocalHit hit;
  // From the middle of the axis straight along it: exits through the cap at distance 2.5.
  ASSERT_TRUE(cyl.intersect({0.5 * (a + b), (b - a) / 5 * 0.5, 0}, 1e-9, kInfinity, hit));
  EXPECT_NEAR(hit.t, 5.0, 1e-12);
  expect_near(hit.normal, (b - a) / 5, 1e-12);
  // From the axis, perpendicular (along z): exits through the wall at distance 2.
  ASSERT_TRUE(cyl.intersect({0.5 * (a + b), {0, 0, 1}, 0}, 1e-9, kInfinity, hit));
  EXPECT_NEAR(hit.t, 2.0, 1e-12);
}

TEST(CylinderTest, InsideIsTheSolidEvenWhenOpen) {
  for (bool open : {false, true}) {
    const Cylinder cyl({0, 0, 0}, {0, 2, 0}, 1, open);
    EXPECT_TRUE(cyl.inside({0.5, 1, 0}));
    EXPECT_FALSE(cyl.inside({0.5, 2.5, 0}));
    EXPECT_FALSE(cyl.inside({1.5, 1, 0}));
  }
}

TEST(CylinderTest, MissesAndBehind) {
  const Cylinder cyl({0, -1, 0}, {0, 1, 0}, 0.5, false);
  LocalHit hit;
  EXPECT_FALSE(cyl.intersect({{-3, 0, 0}, {-1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_FALSE(cyl.intersect({{-3, 1.5, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_FALSE(cyl.intersect({{-3, 0, 0.6}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  // Grazing the wall: the tangent point counts once at most.
  HitList hits;
  cyl.all_hits({{-3, 0, 0.5}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  EXPECT_LE(hits.size(), 1u);
}

TEST(CylinderTest, RandomRays) {
  shape_checks::check_random_rays(Cylinder({-1, 0, 0.5}, {1, 2, -0.5}, 0.7, false), true);
  shape_checks::check_random_rays(Cylinder({-1, 0, 0.5}, {1, 2, -0.5}, 0.7, true), false);
}

TEST(CylinderTest, DegenerateInputThrows) {
  EXPECT_THROW(Cylinder({0, 0, 0}, {0, 0, 0}, 1, false), std::invalid_argument);
  EXPECT_THROW(Cylinder({0, 0, 0}, {0, 1, 0}, -1, false), std::invalid_argument);
}
