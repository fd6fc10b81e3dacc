#include "snell/geometry/box.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

TEST(BoxTest, HitFromOutsideEntersAndLeaves) {
  const Box box({1, 1, 1}, {-1, -1, -1});  // corners in any order
  const Ray ray{{-5, 0.2, 0.3}, {2, 0, 0}, 0};
  HitList hits;
  box.all_hits(ray, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_DOUBLE_EQ(hits[0].t, 2.0);
  EXPECT_DOUBLE_EQ(hits[1].t, 3.0);
  expect_near(hits[0].normal, {-1, 0, 0}, 0);
  expect_near(hits[1].normal, {1, 0, 0}, 0);
}

TEST(BoxTest, FromInsideOnlyTheExit) {
  const Box box({-1, -2, -3}, {1, 2, 3});
  LocalHit hit;
  ASSERT_TRUE(box.intersect({{0, 0, 0}, {0, 0, -0.5}, 0}, 1e-9, kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 6.0);
  expect_near(hit.normal, {0, 0, -1}, 0);
}

TEST(BoxTest, RayStartingOnTheSurfaceFindsTheFarSide) {
  const Box box({-1, -1, -1}, {1, 1, 1});
  LocalHit hit;
  ASSERT_TRUE(box.intersect({{-1, 0, 0}, {1, 0, 0}, 0}, 1e-9, kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 2.0);
}

TEST(BoxTest, MissesBehindAndParallel) {
  const Box box({-1, -1, -1}, {1, 1, 1});
  LocalHit hit;
  EXPECT_FALSE(box.intersect({{-5, 0, 0}, {-1, 0, 0}, 0}, 0, kInfinity, hit));  // box behind
  EXPECT_FALSE(box.intersect({{-5, 2, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));   // passes above
  EXPECT_FALSE(box.intersect({{-5, 0, 0}, {1, 0, 0}, 0}, 0, 3.5, hit));         // t_max before it
  // Grazing along a face plane (origin exactly on the slab of a parallel axis) still counts as inside it.
  ASSERT_TRUE(box.intersect({{-5, 1, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 4.0);
}

TEST(BoxTest, InsideIncludesFacesAsPovRay) {
  const Box box({-1, -1, -1}, {1, 1, 1});
  EXPECT_TRUE(box.inside({0, 0, 0}));
  EXPECT_TRUE(box.inside({1, 0, 0}));
  EXPECT_FALSE(box.inside({1.001, 0, 0}));
}

TEST(BoxTest, RandomRaysRespectBoundsAndNormals) {
  shape_checks::check_random_rays(Box({-1, -0.5, 0}, {2, 0.5, 3}), true);
}

TEST(BoxTest, NonFiniteCornerThrows) {
  EXPECT_THROW(Box({0, 0, 0}, {kInfinity, 1, 1}), std::invalid_argument);
}
