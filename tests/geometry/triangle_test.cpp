#include "snell/geometry/triangle.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

TEST(TriangleTest, HitWithBarycentricUv) {
  const Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  LocalHit hit;
  ASSERT_TRUE(tri.intersect({{0.25, 0.5, 5}, {0, 0, -2}, 0}, 0, kInfinity, hit));
  EXPECT_DOUBLE_EQ(hit.t, 2.5);
  expect_near(normalize(hit.normal), {0, 0, 1}, 1e-15);
  EXPECT_DOUBLE_EQ(hit.uv.u, 0.25);
  EXPECT_DOUBLE_EQ(hit.uv.v, 0.5);
  EXPECT_EQ(length(hit.shading_normal), 0);  // flat triangle: no shading normal
}

TEST(TriangleTest, MissesOutsideBehindAndParallel) {
  const Triangle tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  LocalHit hit;
  EXPECT_FALSE(tri.intersect({{0.6, 0.6, 5}, {0, 0, -1}, 0}, 0, kInfinity, hit));
  EXPECT_FALSE(tri.intersect({{0.2, 0.2, 5}, {0, 0, 1}, 0}, 0, kInfinity, hit));
  EXPECT_FALSE(tri.intersect({{-1, 0.2, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_FALSE(tri.inside({0.2, 0.2, -1}));
}

TEST(TriangleTest, SmoothNormalsInterpolate) {
  const Vec3 na{0, 0, 1}, nb{1, 0, 1}, nc{0, 1, 1};
  const Triangle tri({0, 0, 0}, na, {1, 0, 0}, nb, {0, 1, 0}, nc);
  EXPECT_EQ(tri.kind(), "smooth_triangle");
  LocalHit hit;
  ASSERT_TRUE(tri.intersect({{0.5, 0, 1}, {0, 0, -1}, 0}, 0, kInfinity, hit));  // midpoint of edge a-b
  expect_near(hit.shading_normal, normalize(0.5 * normalize(na) + 0.5 * normalize(nb)), 1e-12);
  ASSERT_TRUE(tri.intersect({{0, 1, 1}, {0, 0, -3}, 0}, 0, kInfinity, hit));  // at vertex c
  expect_near(hit.shading_normal, normalize(nc), 1e-12);
}

TEST(TriangleTest, DegenerateNeverHitsNorCrashes) {
  const Triangle tri({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
  LocalHit hit;
  EXPECT_FALSE(tri.intersect({{0.5, 0.5, 5}, {0, 0, -1}, 0}, 0, kInfinity, hit));
}

TEST(TriangleTest, RandomRays) {
  shape_checks::check_random_rays(Triangle({0, 0, 0}, {1, 0.3, 0}, {0.2, 1, 0.7}), false);
}
