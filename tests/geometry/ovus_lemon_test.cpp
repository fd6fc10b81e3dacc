// ovus and lemon against their geometric definitions (POV-Ray 3.7 reference "Ovus", 3.8 "Lemon"): spheres
// joined by a circle arc turned around the axis that touches them, and an arc through both rims.
#include <gtest/gtest.h>

#include <cmath>

#include "shape_checks.hpp"
#include "snell/geometry/lemon.hpp"
#include "snell/geometry/ovus.hpp"

namespace snell::geometry {
namespace {

using math::kInfinity;
using shape_checks::expect_near;

/// The first crossing of a ray along +x at height y (and z = 0), from x = -5.
double first_x(const Shape& s, double y) {
  LocalHit hit;
  if (!s.intersect({{-5, y, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit)) return NAN;
  return -5 + hit.t;
}

TEST(OvusTest, SphereCapsAlongTheAxis) {
  const Ovus egg(1, 0.5);  // bottom sphere r 1 at the origin, top sphere r 0.5 at y = 1 (POV-Ray's default)
  HitList hits;
  egg.all_hits({{0, 5, 0}, {0, -2, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, (5 - 1.5) / 2, 1e-12);  // top of the top sphere
  EXPECT_NEAR(hits[1].t, (5 + 1) / 2, 1e-12);    // bottom of the bottom sphere
  expect_near(normalize(hits[0].normal), {0, 1, 0}, 1e-12);
  expect_near(normalize(hits[1].normal), {0, -1, 0}, 1e-12);
  // Below the lower seam the wall is the bottom sphere, above the upper seam the top sphere.
  EXPECT_NEAR(first_x(egg, -0.5), -std::sqrt(1 - 0.25), 1e-12);
  EXPECT_NEAR(first_x(egg, 1.45), -std::sqrt(0.25 - 0.45 * 0.45), 1e-12);
}

TEST(OvusTest, BandTouchesBothSpheres) {
  const Ovus egg(1, 0.5);
  // The connecting circle (radius 2 = 2 max(b, t)) is tangent inside both spheres: its centre lies at
  // distance 2 - 1 from the bottom centre and 2 - 0.5 from the top centre, across the axis.
  const double cy = (1 + 1 - 2.25) / 2, cx = -std::sqrt(1 - cy * cy);
  for (const double y : {0.2, 0.5, 0.8, 1.1, 1.3}) {
    const double rho = -first_x(egg, y);
    EXPECT_NEAR(std::hypot(rho - cx, y - cy), 2, 1e-9) << y;
  }
  // The wall is smooth across the seams: the radius and the normal match on both sides.
  for (const double seam : {egg.bottom_seam(), egg.top_seam()}) {
    LocalHit below, above;
    ASSERT_TRUE(egg.intersect({{-5, seam - 1e-7, 0}, {1, 0, 0}, 0}, 0, kInfinity, below));
    ASSERT_TRUE(egg.intersect({{-5, seam + 1e-7, 0}, {1, 0, 0}, 0}, 0, kInfinity, above));
    EXPECT_NEAR(below.t, above.t, 1e-6);
    expect_near(normalize(below.normal), normalize(above.normal), 1e-5);
  }
}

TEST(OvusTest, InsideAndRandomRays) {
  const Ovus egg(1, 0.5);
  EXPECT_TRUE(egg.inside({0, 0, 0}));
  EXPECT_TRUE(egg.inside({0, 1.45, 0}));
  EXPECT_TRUE(egg.inside({0.7, 0.6, 0}));
  EXPECT_FALSE(egg.inside({0, 1.55, 0}));
  EXPECT_FALSE(egg.inside({0.9, 1.2, 0}));
  shape_checks::check_random_rays(egg, true);
  shape_checks::check_random_rays(Ovus(0.5, 1), true);  // top heavier than the bottom
}

TEST(OvusTest, RejectsWhatPovRayRejects) {
  EXPECT_THROW(Ovus(0, 1), std::invalid_argument);
  EXPECT_THROW(Ovus(1, -1), std::invalid_argument);
  EXPECT_THROW(Ovus(1, 1, 1.2), std::invalid_argument);  // connecting radius below (1 + 1 + 1) / 2
}

TEST(LemonTest, ArcThroughBothRims) {
  // Rims of radius 0.5 at y = 0 and y = 2, arc radius 2: its centre (cx, 1) with (0.5 - cx)^2 + 1 = 4.
  const Lemon lemon({0, 0, 0}, 0.5, {0, 2, 0}, 0.5, 2, false);
  const double cx = 0.5 - std::sqrt(3.0);
  for (const double y : {0.1, 0.5, 1.0, 1.7}) {
    const double rho = -first_x(lemon, y);
    EXPECT_NEAR(std::hypot(rho - cx, y - 1), 2, 1e-9) << y;
  }
  EXPECT_NEAR(first_x(lemon, 1), -(cx + 2), 1e-9);  // the equator
  // Closed ends: the discs at the base and the cap.
  HitList hits;
  lemon.all_hits({{0.2, -3, 0.1}, {0, 1, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 3, 1e-12);
  EXPECT_NEAR(hits[1].t, 5, 1e-12);
  expect_near(normalize(hits[0].normal), {0, -1, 0}, 1e-12);
  expect_near(normalize(hits[1].normal), {0, 1, 0}, 1e-12);
  // Open: the ray passes through.
  const Lemon open({0, 0, 0}, 0.5, {0, 2, 0}, 0.5, 2, true);
  hits.clear();
  open.all_hits({{0.2, -3, 0.1}, {0, 1, 0}, 0}, 0, kInfinity, hits);
  EXPECT_TRUE(hits.empty());
}

TEST(LemonTest, TiltedAxisAndInside) {
  // The same lemon along the diagonal from <1,1,1>: a ray through the equator's centre, perpendicular to
  // the axis, meets the wall at the equator radius.
  const Vec3 axis = normalize(Vec3(1, 1, 1));
  const Vec3 base(1, 1, 1);
  const Lemon lemon(base, 0.5, base + 2 * axis, 0.5, 2, false);
  const double equator = 2 - (std::sqrt(3.0) - 0.5);
  const Vec3 middle = base + axis;
  const Vec3 side = normalize(Vec3(1, -1, 0));
  LocalHit hit;
  ASSERT_TRUE(lemon.intersect({middle + 5 * side, -side, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 5 - equator, 1e-9);
  expect_near(normalize(hit.normal), side, 1e-9);
  EXPECT_TRUE(lemon.inside(middle + 0.9 * equator * side));
  EXPECT_FALSE(lemon.inside(middle + 1.1 * equator * side));
  EXPECT_FALSE(lemon.inside(base - 0.01 * axis));
  shape_checks::check_random_rays(lemon, true);
}

TEST(LemonTest, PointedEndsAndTooSmallInnerRadius) {
  // Pointed ends (rims 0) and inner radius 1 over a unit axis: widest at half height, 1 - sqrt(3) / 2.
  const Lemon pointed({0, 0, 0}, 0, {0, 1, 0}, 0, 1, false);
  EXPECT_NEAR(first_x(pointed, 0.5), -(1 - std::sqrt(3.0) / 2), 1e-9);
  shape_checks::check_random_rays(pointed, true);
  // Below sqrt((a^2 - b^2)^2 + 2 (a^2 + b^2) + 1) / 2 (POV-Ray 3.8) the inner radius is raised to it.
  const Lemon thin({0, 0, 0}, 0, {0, 1, 0}, 0, 0.2, false);
  EXPECT_NEAR(thin.inner_radius(), 0.5, 1e-12);
  EXPECT_THROW(Lemon({0, 0, 0}, 1, {0, 0, 0}, 1, 2, false), std::invalid_argument);
  EXPECT_THROW(Lemon({0, 0, 0}, -1, {0, 1, 0}, 1, 2, false), std::invalid_argument);
}

}  // namespace
}  // namespace snell::geometry
