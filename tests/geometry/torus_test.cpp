#include "snell/geometry/torus.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

TEST(TorusTest, FourHitsThroughTheHole) {
  const Torus torus(2, 0.5);
  HitList hits;
  torus.all_hits({{-5, 0, 0}, {0.5, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 4u);
  const double expected[] = {5, 7, 13, 15};  // x = -2.5, -1.5, 1.5, 2.5 at speed 0.5
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(hits[i].t, expected[i], 1e-9);
  expect_near(hits[0].normal, {-1, 0, 0}, 1e-9);
  expect_near(hits[1].normal, {1, 0, 0}, 1e-9);  // inner wall faces the hole
}

TEST(TorusTest, DownThroughTheTube) {
  const Torus torus(2, 0.5);
  LocalHit hit;
  ASSERT_TRUE(torus.intersect({{0, 5, 2}, {0, -1, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 4.5, 1e-9);
  expect_near(hit.normal, {0, 1, 0}, 1e-9);
  // From the centre of the tube only the exit remains.
  ASSERT_TRUE(torus.intersect({{0, 0, 2}, {0, -1, 0}, 0}, 1e-9, kInfinity, hit));
  EXPECT_NEAR(hit.t, 0.5, 1e-9);
  EXPECT_FALSE(torus.intersect({{0, 5, 2}, {0, 1, 0}, 0}, 0, kInfinity, hit));   // behind
  EXPECT_FALSE(torus.intersect({{0, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hit));  // through the hole
}

TEST(TorusTest, DistantRayKeepsPrecision) {
  const Torus torus(2, 0.5);
  LocalHit hit;
  ASSERT_TRUE(torus.intersect({{-1e5, 0, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 1e5 - 2.5, 1e-7);
}

TEST(TorusTest, GrazingTopDoesNotCrash) {
  const Torus torus(2, 0.5);
  HitList hits;
  torus.all_hits({{-5, 0.5, 0}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  EXPECT_LE(hits.size(), 4u);
  for (const LocalHit& h : hits) EXPECT_NEAR(std::fabs(h.t - 5), 2, 1e-3);
}

TEST(TorusTest, Inside) {
  const Torus torus(2, 0.5);
  EXPECT_TRUE(torus.inside({2, 0, 0}));
  EXPECT_TRUE(torus.inside({0, 0.3, -2.2}));
  EXPECT_FALSE(torus.inside({0, 0, 0}));
  EXPECT_FALSE(torus.inside({2, 0.6, 0}));
}

TEST(TorusTest, RandomRays) {
  shape_checks::check_random_rays(Torus(2, 0.5), true);
  // Spindle torus (minor > major): its inner lemon-shaped sheet lies inside the solid, so no outward check.
  shape_checks::check_random_rays(Torus(0.5, 1), false);
}

TEST(TorusTest, BadInputThrows) {
  EXPECT_THROW(Torus(1, 0), std::invalid_argument);
  EXPECT_THROW(Torus(-1, 0.5), std::invalid_argument);
}
