#include "snell/geometry/cone.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

TEST(ConeTest, SideHitsAtTheLocalRadius) {
  // Radius 1 at y=0 shrinking to 0.5 at y=2: at y=1 the radius is 0.75.
  const Cone cone({0, 0, 0}, 1, {0, 2, 0}, 0.5, false);
  HitList hits;
  cone.all_hits({{-5, 1, 0}, {2, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, (5 - 0.75) / 2, 1e-12);
  EXPECT_NEAR(hits[1].t, (5 + 0.75) / 2, 1e-12);
  // Outward normal leans up by the half-angle: slope 0.25 per unit height -> (1, 0.25, 0)/|.|.
  expect_near(hits[0].normal, normalize(Vec3(-1, 0.25, 0)), 1e-12);
}

TEST(ConeTest, PointedApexHasNoCap) {
  const Cone cone({0, 0, 0}, 1, {0, 1, 0}, 0, false);
  HitList hits;
  // Straight down the axis: the apex (t = 4) then the base cap (t = 5).
  cone.all_hits({{0, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 4.0, 1e-12);
  EXPECT_NEAR(hits[1].t, 5.0, 1e-12);
  expect_near(hits[1].normal, {0, -1, 0}, 0);
  EXPECT_TRUE(is_finite(hits[0].normal));
  EXPECT_GT(length(hits[0].normal), 0);
}

TEST(ConeTest, MirroredNappeIsNotHit) {
  // The double cone x^2 + z^2 = (1 - y)^2 continues above the apex; only y in [0, 1] belongs to the shape.
  const Cone cone({0, 0, 0}, 1, {0, 1, 0}, 0, true);
  LocalHit hit;
  EXPECT_FALSE(cone.intersect({{-5, 1.5, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
}

TEST(ConeTest, OpenConeHasNoCapsAndScaledRayMatches) {
  const Cone cone({0, 0, 0}, 1, {0, 2, 0}, 0.5, true);
  HitList hits;
  cone.all_hits({{0.1, -5, 0}, {0, 1, 0}, 0}, 0, kInfinity, hits);
  EXPECT_TRUE(hits.empty());
  LocalHit a, b;
  ASSERT_TRUE(cone.intersect({{-5, 1, 0.1}, {1, 0, 0}, 0}, 0, kInfinity, a));
  ASSERT_TRUE(cone.intersect({{-5, 1, 0.1}, {0.1, 0, 0}, 0}, 0, kInfinity, b));
  EXPECT_NEAR(a.t * 10, b.t, 1e-9);
}

TEST(ConeTest, InsideTheFrustum) {
  const Cone cone({0, 0, 0}, 1, {0, 2, 0}, 0.5, true);
  EXPECT_TRUE(cone.inside({0.7, 1, 0}));
  EXPECT_FALSE(cone.inside({0.8, 1, 0}));
  EXPECT_FALSE(cone.inside({0, -0.1, 0}));
}

TEST(ConeTest, RandomRays) {
  shape_checks::check_random_rays(Cone({0, 0, 0}, 1, {0.5, 2, 0.3}, 0.2, false), true);
  shape_checks::check_random_rays(Cone({0, 0, 0}, 0, {0, 0, 2}, 1, false), true);
  shape_checks::check_random_rays(Cone({0, 0, 0}, 1, {0.5, 2, 0.3}, 0.2, true), false);
}

TEST(ConeTest, BadInputThrows) {
  EXPECT_THROW(Cone({0, 0, 0}, 1, {0, 0, 0}, 0.5, false), std::invalid_argument);
  EXPECT_THROW(Cone({0, 0, 0}, -1, {0, 1, 0}, 0.5, false), std::invalid_argument);
  EXPECT_THROW(Cone({0, 0, 0}, 0, {0, 1, 0}, 0, false), std::invalid_argument);
}
