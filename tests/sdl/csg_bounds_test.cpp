// A CSG intersection of unbounded children gets finite bounds, as POV-Ray's CSG::Compute_BBox gives them:
// axis-aligned planes cut half-spaces, quadrics are confined by the others' box. The numbers are those of
// the chess pieces in advanced/chess2.pov: shapes.inc's Hyperboloid_Y (x^2 - y^2 + z^2 = 1) moved up 5 and
// narrowed to 0.5 between y = 2.5 and 5.5 reaches |x| = 0.5 sqrt(1 + 2.5^2) = 1.3463.
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"

using namespace snell;

TEST(CsgBounds, PlanesAndCylinderMakeABox) {
  const scene::Scene s = sdl::test::parse(R"(
    #include "shapes.inc"
    intersection { plane { y, 10 } object { Cylinder_Y scale <2, 1, 2> } plane { -y, -8 } }
  )");
  const math::Bounds3 b = s.objects.front()->world_bounds();
  ASSERT_TRUE(b.is_finite());
  EXPECT_NEAR(b.lo.x, -2, 1e-6);
  EXPECT_NEAR(b.hi.z, 2, 1e-6);
  EXPECT_NEAR(b.lo.y, 8, 1e-6);
  EXPECT_NEAR(b.hi.y, 10, 1e-6);
}

TEST(CsgBounds, HyperboloidBetweenPlanes) {
  const scene::Scene s = sdl::test::parse(R"(
    #include "shapes.inc"
    intersection { plane { y, 5.5 } object { Hyperboloid_Y translate 5*y scale <0.5, 1, 0.5> } plane { -y, -2.5 } }
  )");
  const math::Bounds3 b = s.objects.front()->world_bounds();
  ASSERT_TRUE(b.is_finite());
  EXPECT_NEAR(b.hi.x, 0.5 * std::sqrt(1 + 2.5 * 2.5), 1e-6);
  EXPECT_NEAR(b.lo.z, -0.5 * std::sqrt(1 + 2.5 * 2.5), 1e-6);
}
