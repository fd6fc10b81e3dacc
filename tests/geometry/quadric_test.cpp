// Quadrics written for surfaces whose crossings are known in closed form (POV-Ray 3.7 reference,
// "Quadric": A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0, inside where < 0).
#include "snell/geometry/quadric.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "shape_checks.hpp"

namespace snell::geometry {
namespace {

using shape_checks::expect_near;

TEST(QuadricTest, UnitSphereHitsAtDistanceMinusRadius) {
  const Quadric q({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1);
  LocalHit hit;
  ASSERT_TRUE(q.intersect(Ray{{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4, 1e-12);
  expect_near(normalize(hit.normal), {0, 0, -1}, 1e-12);
  HitList all;
  q.all_hits(Ray{{0, 0, -5}, {0, 0, 2}, 0}, 1e-9, math::kInfinity, all);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_NEAR(all[0].t, 2, 1e-12);
  EXPECT_NEAR(all[1].t, 3, 1e-12);
  EXPECT_TRUE(q.inside({0.5, 0.5, 0.5}));
  EXPECT_FALSE(q.inside({0.8, 0.8, 0}));
}

TEST(QuadricTest, ShiftedEllipsoidGetsTightBoundsAndPassesShapeChecks) {
  // (x-1)^2/4 + (y+2)^2 + z^2/9 = 1 expanded: x^2/4 + y^2 + z^2/9 - x/2 + 4y + 1/4 + 4 - 1 = 0.
  const Quadric q({0.25, 1, 1.0 / 9}, {0, 0, 0}, {-0.5, 4, 0}, 3.25);
  const Bounds3 b = q.bounds();
  expect_near(b.lo, {-1, -3, -3}, 1e-6);
  expect_near(b.hi, {3, -1, 3}, 1e-6);
  shape_checks::check_random_rays(q, true);
}

TEST(QuadricTest, RotatedEllipsoidBoundsFromCrossTerms) {
  // x^2 + y^2 - xy = 1 rotated 45 degrees has semi-axes sqrt(2) (along x=y) and sqrt(2/3); its extent
  // along x is sqrt(4/3), from the inverse of the form's matrix [[1,-1/2],[-1/2,1]] (diagonal 4/3).
  const Quadric q({1, 1, 1}, {-1, 0, 0}, {0, 0, 0}, -1);
  const Bounds3 b = q.bounds();
  EXPECT_NEAR(b.hi.x, std::sqrt(4.0 / 3), 1e-6);
  EXPECT_NEAR(b.hi.y, std::sqrt(4.0 / 3), 1e-6);
  EXPECT_NEAR(b.hi.z, 1, 1e-6);
  LocalHit hit;
  // Along the diagonal the surface is at distance sqrt(2) from the centre.
  ASSERT_TRUE(q.intersect(Ray{{0, 0, 0}, normalize(Vec3{1, 1, 0}), 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, std::sqrt(2.0), 1e-12);
  shape_checks::check_random_rays(q, true);
}

TEST(QuadricTest, InfiniteCylinderAlongY) {
  // shapes_old.inc Cylinder_Y: x^2 + z^2 - 1 = 0.
  const Quadric q({1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1);
  EXPECT_FALSE(q.bounds().is_finite());
  LocalHit hit;
  ASSERT_TRUE(q.intersect(Ray{{-3, 100, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 2, 1e-12);
  expect_near(normalize(hit.normal), {-1, 0, 0}, 1e-12);
  // A ray along the axis never crosses it.
  EXPECT_FALSE(q.intersect(Ray{{0.5, -10, 0}, {0, 1, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_TRUE(q.inside({0.5, 1e6, 0.5}));
}

TEST(QuadricTest, PlaneAsLinearQuadric) {
  // y - 2 = 0: a plane, inside below it, with the single crossing of a line.
  const Quadric q({0, 0, 0}, {0, 0, 0}, {0, 1, 0}, -2);
  LocalHit hit;
  ASSERT_TRUE(q.intersect(Ray{{1, 0, 1}, {0, 0.5, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4, 1e-12);
  expect_near(normalize(hit.normal), {0, 1, 0}, 1e-12);
  HitList all;
  q.all_hits(Ray{{1, 0, 1}, {1, 1, 0}, 0}, 1e-9, math::kInfinity, all);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_NEAR(all[0].t, 2, 1e-12);
  EXPECT_TRUE(q.inside({0, 1.9, 0}));
  EXPECT_FALSE(q.inside({0, 2.1, 0}));
}

TEST(QuadricTest, HyperboloidCrossesTwiceThroughTheWaist) {
  // x^2 + z^2 - y^2 = 1 (one sheet); along x at y = 0 it is the unit circle.
  const Quadric q({1, -1, 1}, {0, 0, 0}, {0, 0, 0}, -1);
  HitList all;
  q.all_hits(Ray{{-5, 0, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, all);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_NEAR(all[0].t, 4, 1e-12);
  EXPECT_NEAR(all[1].t, 6, 1e-12);
}

TEST(QuadricTest, ConeApexGetsAUsableNormal) {
  // x^2 + z^2 - y^2 = 0 is a double cone whose gradient vanishes at the apex, the origin.
  const Quadric q({1, -1, 1}, {0, 0, 0}, {0, 0, 0}, 0);
  LocalHit hit;
  ASSERT_TRUE(q.intersect(Ray{{-1, 0, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 1, 1e-9);
  EXPECT_GT(length(hit.normal), 0);
  EXPECT_TRUE(is_finite(hit.normal));
}

TEST(QuadricTest, DegenerateInputIsRejected) {
  EXPECT_THROW(Quadric({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1), std::invalid_argument);
  EXPECT_THROW(Quadric({NAN, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1), std::invalid_argument);
}

}  // namespace
}  // namespace snell::geometry
