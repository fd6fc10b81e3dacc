#include "snell/geometry/sphere_sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

TEST(SphereSweepTest, LinearCapsule) {
  // Two unit spheres 4 apart: a capsule, its middle a cylinder of radius 1.
  const std::vector<SweepSphere> p{{{0, 0, 0}, 1}, {{4, 0, 0}, 1}};
  const SphereSweep sweep(sweep_path(SweepSpline::linear, p));
  HitList hits;
  sweep.all_hits({{2, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 4, 1e-9);
  EXPECT_NEAR(hits[1].t, 6, 1e-9);
  expect_near(normalize(hits[0].normal), {0, 1, 0}, 1e-9);
  hits.clear();
  sweep.all_hits({{-5, 0, 0}, {1, 0, 0}, 0}, 0, kInfinity, hits);  // along the axis: only the end caps
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 4, 1e-9);
  EXPECT_NEAR(hits[1].t, 10, 1e-9);
  EXPECT_TRUE(sweep.inside({2, 0.9, 0}));
  EXPECT_FALSE(sweep.inside({2, 1.1, 0}));
  shape_checks::check_random_rays(sweep, true, 500);
}

TEST(SphereSweepTest, TaperedConeIsTangentToBothSpheres) {
  // Radii 2 and 1, 4 apart: sin a = 1/4. The top line of the envelope is tangent to both circles.
  const std::vector<SweepSphere> p{{{0, 0, 0}, 2}, {{4, 0, 0}, 1}};
  const SphereSweep sweep(sweep_path(SweepSpline::linear, p));
  LocalHit hit;
  // A ray down at x = 2: the envelope's height there is (2 - x sin a) / cos a along the normal...
  // ...equivalently the distance from the centre line through the tangent circles.
  ASSERT_TRUE(sweep.intersect({{2, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hit));
  const double sin_a = 0.25, cos_a = std::sqrt(1 - sin_a * sin_a);
  // Line through (2 sin a, 2 cos a) with slope -tan a: y = 2 cos a - (x - 2 sin a) tan a.
  const double y = 2 * cos_a - (2 - 2 * sin_a) * sin_a / cos_a;
  EXPECT_NEAR(hit.t, 5 - y, 1e-9);
  expect_near(normalize(hit.normal), {sin_a, cos_a, 0}, 1e-9);
  shape_checks::check_random_rays(sweep, true, 500);
}

TEST(SphereSweepTest, CurvedSplinesInterpolate) {
  // Catmull-Rom passes through the inner points; a B-spline of collinear, evenly spaced points with
  // equal radii is the same straight capsule from P1 to P2 shortened to (P0 + 4 P1 + P2) / 6.
  const std::vector<SweepSphere> p{{{-1, 0, 0}, 0.5}, {{0, 0, 0}, 0.5}, {{1, 0, 0}, 0.5}, {{2, 0, 0}, 0.5}};
  const auto cubic = sweep_path(SweepSpline::cubic, p);
  ASSERT_EQ(cubic.size(), static_cast<size_t>(kSweepSteps + 1));
  expect_near(cubic.front().center, {0, 0, 0}, 1e-12);
  expect_near(cubic.back().center, {1, 0, 0}, 1e-12);
  const auto b = sweep_path(SweepSpline::b_spline, p);
  expect_near(b.front().center, {0, 0, 0}, 1e-12);
  EXPECT_NEAR(b.front().radius, 0.5, 1e-12);
  const SphereSweep sweep(b);
  shape_checks::check_random_rays(sweep, true, 300);
}
