// Bounds of unbounded shapes, as a CSG intersection narrows them (POV-Ray 3.7 csg.cpp, CSG::Compute_BBox):
// an axis-aligned plane bounds its inside half-space, a quadric without mixed terms is confined to a box by
// solving its inequality on each axis. The expected numbers are the closed forms of the surfaces.
#include <gtest/gtest.h>

#include <cmath>

#include "snell/geometry/plane.hpp"
#include "snell/geometry/quadric.hpp"
#include "snell/math/transform.hpp"

using namespace snell;
using geometry::Plane;
using geometry::Quadric;
using math::Bounds3;
using math::Vec3;

TEST(UnboundedShapeBounds, AxisPlaneBoundsItsInsideHalfSpace) {
  const Bounds3 up = Plane({0, 1, 0}, 5).bounds();  // y < 5
  EXPECT_EQ(up.hi.y, 5);
  EXPECT_TRUE(std::isinf(up.lo.y) && std::isinf(up.lo.x) && std::isinf(up.hi.z));
  const Bounds3 down = Plane({0, -2, 0}, 3).bounds();  // -y < 3: y > -3
  EXPECT_EQ(down.lo.y, -3);
  EXPECT_TRUE(std::isinf(down.hi.y));
  const Bounds3 tilted = Plane({1, 1, 0}, 0).bounds();
  EXPECT_FALSE(tilted.is_finite());
  EXPECT_TRUE(std::isinf(tilted.hi.x) && std::isinf(tilted.hi.y));
}

TEST(UnboundedShapeBounds, InfiniteCylinderIsBoundedAcrossItsAxis) {
  // shapes.inc Cylinder_Y: x^2 + z^2 - 1 = 0.
  const Quadric cylinder({1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1);
  const Bounds3 b = cylinder.inside_bounds_within(Bounds3::infinite());
  EXPECT_NEAR(b.lo.x, -1, 1e-8);
  EXPECT_NEAR(b.hi.z, 1, 1e-8);
  EXPECT_TRUE(std::isinf(b.lo.y) && std::isinf(b.hi.y));
}

TEST(UnboundedShapeBounds, HyperboloidBetweenPlanesIsFinite) {
  // shapes.inc Hyperboloid_Y: x^2 - y^2 + z^2 - 1 = 0 for 2 <= y <= 3 reaches |x| = sqrt(1 + 9).
  const Quadric hyperboloid({1, -1, 1}, {0, 0, 0}, {0, 0, 0}, -1);
  const Bounds3 b = hyperboloid.inside_bounds_within({Vec3(-1e300, 2, -1e300), Vec3(1e300, 3, 1e300)});
  EXPECT_NEAR(b.hi.x, std::sqrt(10.0), 1e-8);
  EXPECT_NEAR(b.lo.z, -std::sqrt(10.0), 1e-8);
  EXPECT_EQ(b.lo.y, 2);
  EXPECT_EQ(b.hi.y, 3);
}

TEST(UnboundedShapeBounds, QuadricWithNoInsideInTheBoxIsEmpty) {
  // A sphere of radius 1 at the origin has no inside where x > 2.
  const Quadric sphere({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1);
  EXPECT_TRUE(sphere.inside_bounds_within({Vec3(2, -5, -5), Vec3(3, 5, 5)}).empty());
}

TEST(UnboundedShapeBounds, TransformKeepsHalfInfiniteBoxes) {
  // y < 5 scaled by 2 and moved up 1: y < 11, other axes still unbounded.
  const math::Transform t = math::Transform::translate({0, 1, 0}) * math::Transform::scale({2, 2, 2});
  const Bounds3 b = t.bounds(Plane({0, 1, 0}, 5).bounds());
  EXPECT_DOUBLE_EQ(b.hi.y, 11);
  EXPECT_TRUE(std::isinf(b.lo.y) && std::isinf(b.lo.x) && std::isinf(b.hi.x));
}
