#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "shape_checks.hpp"
#include "snell/geometry/axial_ray.hpp"
#include "snell/geometry/lathe.hpp"
#include "snell/geometry/sor.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

namespace {

// A closed profile: from the axis out to r = 1, up to y = 2 and back: a capped cylinder.
Lathe cylinder_lathe() {
  const std::vector<Vec2> p{{0, 0}, {1, 0}, {1, 2}, {0, 2}};
  return Lathe(Outline(lathe_pieces(SplineKind::linear, p)));
}

}  // namespace

TEST(LatheTest, LinearCylinder) {
  const Lathe lathe = cylinder_lathe();
  HitList hits;
  lathe.all_hits({{-5, 1, 0}, {2, 0, 0}, 0}, 0, kInfinity, hits);  // horizontal
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 2, 1e-12);
  EXPECT_NEAR(hits[1].t, 3, 1e-12);
  expect_near(hits[0].normal, {-1, 0, 0}, 1e-12);
  expect_near(hits[1].normal, {1, 0, 0}, 1e-12);
  hits.clear();
  lathe.all_hits({{0.5, 5, 0.2}, {0, -1, 0}, 0}, 0, kInfinity, hits);  // along the axis
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 3, 1e-12);
  EXPECT_NEAR(hits[1].t, 5, 1e-12);
  expect_near(hits[0].normal, {0, 1, 0}, 1e-12);
  // A slanted ray through the wall at 45 degrees: enters at x = -1, y = 0.5.
  LocalHit hit;
  ASSERT_TRUE(lathe.intersect({{-3, 2.5, 0}, {1, -1, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 2, 1e-9);
  EXPECT_TRUE(lathe.inside({0.5, 1, 0.5}));
  EXPECT_FALSE(lathe.inside({0.8, 1, 0.8}));
  EXPECT_FALSE(lathe.inside({0, 2.5, 0}));
}

TEST(LatheTest, CurvedProfilesPassThroughTheirKnots) {
  // Profile knots on the unit circle's right half, y from -1 to 1: a sphere-like solid of radius 1.
  const auto knot = [](double i) {
    const double a = -snell::math::kPi / 2 + i * snell::math::kPi / 6;
    return Vec2{std::cos(a), std::sin(a)};
  };
  std::vector<Vec2> quadratic{knot(-1)}, cubic{knot(-1)};
  for (int i = 0; i <= 6; ++i) {
    quadratic.push_back(knot(i));
    cubic.push_back(knot(i));
  }
  cubic.push_back(knot(7));
  for (const auto& [kind, points] :
       {std::pair{SplineKind::quadratic, quadratic}, std::pair{SplineKind::cubic, cubic}}) {
    const Lathe lathe(Outline(lathe_pieces(kind, points)));
    LocalHit hit;
    // Knot 3 is (1, 0): a horizontal ray at y = 0 meets it at x = -1.
    ASSERT_TRUE(lathe.intersect({{-5, 0, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
    EXPECT_NEAR(hit.t, 4, 1e-9);
    EXPECT_GT(-hit.normal.x, 0.99);
    // Knot 4 is (cos 30, sin 30) = (0.866, 0.5), reached by a slanted ray too.
    ASSERT_TRUE(lathe.intersect({{0, 0.5 + 3, -std::sqrt(0.75) - 3}, {0, -1, 1}, 0}, 0, kInfinity, hit));
    EXPECT_NEAR(hit.t, 3, 1e-9);
    shape_checks::check_random_rays(lathe, true, 500);
  }
}

TEST(LatheTest, BezierCone) {
  // One straight Bezier piece from (1, 0) to (0, 1) plus the base: a cone of height 1.
  const std::vector<Vec2> p{{0, 0}, {1.0 / 3, 0},       {2.0 / 3, 0},       {1, 0},
                            {1, 0}, {2.0 / 3, 1.0 / 3}, {1.0 / 3, 2.0 / 3}, {0, 1}};
  const Lathe lathe(Outline(lathe_pieces(SplineKind::bezier, p)));
  LocalHit hit;
  ASSERT_TRUE(lathe.intersect({{-5, 0.25, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 4.25, 1e-9);
  expect_near(hit.normal, Vec3(-1, 1, 0) / std::sqrt(2.0), 1e-9);
  shape_checks::check_random_rays(lathe, true, 500);
}

TEST(LatheTest, RandomRays) {
  shape_checks::check_random_rays(cylinder_lathe(), true);
}

TEST(SorTest, CylinderWithCaps) {
  const std::vector<Vec2> p{{1, -1}, {1, 0}, {1, 1}, {1, 2}};
  const Sor sor(p, false);
  HitList hits;
  sor.all_hits({{-5, 0.5, 0}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 4, 1e-12);
  EXPECT_NEAR(hits[1].t, 6, 1e-12);
  expect_near(normalize(hits[0].normal), {-1, 0, 0}, 1e-12);
  hits.clear();
  sor.all_hits({{0.5, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 4, 1e-12);  // top cap at y = 1 (the next-to-last point)
  EXPECT_NEAR(hits[1].t, 5, 1e-12);
  expect_near(hits[0].normal, {0, 1, 0}, 1e-12);
  LocalHit hit;
  EXPECT_FALSE(Sor(p, true).intersect({{0.5, 5, 0}, {0, -1, 0}, 0}, 0, kInfinity, hit));  // open
  shape_checks::check_random_rays(sor, true);
}

TEST(SorTest, HermiteCubicReproducesACone) {
  // r = y: r^2 = y^2 is a quadratic, which the Hermite cubic reproduces exactly.
  const std::vector<Vec2> p{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  const Sor sor(p, false);
  EXPECT_NEAR(sor.radius_squared(1.5), 2.25, 1e-12);
  LocalHit hit;
  ASSERT_TRUE(sor.intersect({{-5, 1.5, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 3.5, 1e-12);
  expect_near(normalize(hit.normal), Vec3(-1, -1, 0) / std::sqrt(2.0), 1e-12);
  ASSERT_TRUE(sor.intersect({{0, 1.5, -5}, {0, 0.1, 1}, 0}, 0, kInfinity, hit));
  const Vec3 q = Vec3(0, 1.5, -5) + hit.t * Vec3(0, 0.1, 1);
  EXPECT_NEAR(q.x * q.x + q.z * q.z, q.y * q.y, 1e-9);
  shape_checks::check_random_rays(sor, true);
}

TEST(SorTest, RejectsFallingHeights) {
  const std::vector<Vec2> p{{1, 0}, {1, 1}, {1, 0.5}, {1, 2}};
  EXPECT_THROW(Sor(p, false), std::invalid_argument);
}

// The heights at which a ray is near the axis, by which lathe and sor skip pieces out of reach.
TEST(AxialRayTest, HeightsWithinReach) {
  AxialRay axial;
  // From x = -5 climbing at 45 degrees through the axis plane: within 1 of it for x in [-1, 1], which the
  // ray passes at heights 4 to 6.
  ASSERT_TRUE(axial.prepare({{-5, 0, 0}, {2, 2, 0}, 0}));
  auto [lo, hi] = axial.heights_within(1, axial.u_of(0), axial.u_of(kInfinity));
  EXPECT_NEAR(lo, 4, 1e-12);
  EXPECT_NEAR(hi, 6, 1e-12);
  // A window ending at t = 2.5 (x = 0, y = 5) keeps the lower half only.
  std::tie(lo, hi) = axial.heights_within(1, axial.u_of(0), axial.u_of(2.5));
  EXPECT_NEAR(lo, 4, 1e-12);
  EXPECT_NEAR(hi, 5, 1e-12);
  // Going down, the same band in the other order.
  ASSERT_TRUE(axial.prepare({{-5, 10, 0}, {1, -1, 0}, 0}));
  std::tie(lo, hi) = axial.heights_within(1, axial.u_of(0), axial.u_of(kInfinity));
  EXPECT_NEAR(lo, 4, 1e-12);
  EXPECT_NEAR(hi, 6, 1e-12);
  // Passing 2 from the axis: never within 1 of it.
  ASSERT_TRUE(axial.prepare({{-5, 0, 2}, {1, 1, 0}, 0}));
  std::tie(lo, hi) = axial.heights_within(1, axial.u_of(0), axial.u_of(kInfinity));
  EXPECT_GT(lo, hi);
  // Along the axis at distance 0.5: every height of the window.
  ASSERT_TRUE(axial.prepare({{0.5, 1, 0}, {0, 1, 0}, 0}));
  std::tie(lo, hi) = axial.heights_within(1, axial.u_of(0), axial.u_of(3));
  EXPECT_NEAR(lo, 1, 1e-12);
  EXPECT_NEAR(hi, 4, 1e-12);
}

// A many-piece outline (the wine glass of POV-Ray's sor1.pov), whose rays skip most pieces as out of
// reach: the skipped ones must be those the band tests would skip, whatever the window.
TEST(SorTest, ManyPiecesAgreeWithInsideAndWindows) {
  const std::vector<Vec2> glass{
      {.517241379, -.132625995}, {.249336870, 0.000000},    {.068965517, .031830239},
      {.021220159, .050397878},  {.058355438, .347480106},  {.132625995, .381962865},
      {.196286472, .464190981},  {.238726790, .602122016},  {.249336870, .721485411},
      {.233421751, .864721485},  {.167108753, 1.000000000}, {.084880637, 1.055702918}};
  shape_checks::check_random_rays(Sor(glass, false), true, 3000);
  std::vector<Vec2> outline;
  for (const Vec2& p : glass) outline.push_back(p);
  shape_checks::check_random_rays(Lathe(Outline(lathe_pieces(SplineKind::cubic, outline))), false, 3000);
}
