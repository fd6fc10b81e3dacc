// Superellipsoid hits against the implicit equation (POV-Ray 3.7 reference, "Superquadric Ellipsoid").
#include "snell/geometry/superellipsoid.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "shape_checks.hpp"

namespace snell::geometry {
namespace {

TEST(SuperellipsoidTest, OneOneIsTheUnitSphere) {
  const Superellipsoid s(1, 1);
  LocalHit hit;
  ASSERT_TRUE(s.intersect({{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4, 1e-8);
  shape_checks::expect_near(normalize(hit.normal), {0, 0, -1}, 1e-8);
  ASSERT_TRUE(s.intersect({{-3, 0.5, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 3 - std::sqrt(0.75), 1e-8);
}

TEST(SuperellipsoidTest, SmallExponentsRoundACubesCorner) {
  // e = n = 0.1 at x = y = 0.9: 2 * 0.9^20 + |z|^20 = 1.
  const Superellipsoid s(0.1, 0.1);
  LocalHit hit;
  ASSERT_TRUE(s.intersect({{0.9, 0.9, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  const double z = std::pow(1 - 2 * std::pow(0.9, 20), 1.0 / 20);
  EXPECT_NEAR(hit.t, 5 - z, 1e-7);
}

TEST(SuperellipsoidTest, TwoTwoIsTheOctahedron) {
  // e = n = 2: |x| + |y| + |z| = 1.
  const Superellipsoid s(2, 2);
  LocalHit hit;
  ASSERT_TRUE(s.intersect({{0.25, 0.25, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4.5, 1e-7);
  shape_checks::expect_near(normalize(hit.normal), normalize(Vec3(1, 1, -1)), 1e-6);
  EXPECT_TRUE(s.inside({0.3, 0.3, 0.3}));
  EXPECT_FALSE(s.inside({0.4, 0.4, 0.4}));
}

TEST(SuperellipsoidTest, RayLeavingTheSurfaceDoesNotHitItAgain) {
  const Superellipsoid s(0.5, 0.5);
  LocalHit hit;
  ASSERT_TRUE(s.intersect({{0.2, 0.1, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  const Vec3 p = Ray{{0.2, 0.1, -5}, {0, 0, 1}, 0}.at(hit.t);
  LocalHit again;
  EXPECT_FALSE(s.intersect({p, normalize(hit.normal), 0}, 1e-9, math::kInfinity, again));
}

TEST(SuperellipsoidTest, PassesShapeChecks) {
  shape_checks::check_random_rays(Superellipsoid(0.3, 1.5), true, 500, 1e-5);
  shape_checks::check_random_rays(Superellipsoid(1.8, 0.4), true, 500, 1e-5);
}

}  // namespace
}  // namespace snell::geometry
