#include "snell/geometry/blob.hpp"

#include <gtest/gtest.h>

#include "shape_checks.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;
using snell::math::Transform;

namespace {
BlobComponent sphere(const Vec3& c, double radius, double strength) {
  BlobComponent b;
  b.center = c;
  b.radius = radius;
  b.strength = strength;
  return b;
}
BlobComponent cylinder(const Vec3& a, const Vec3& e, double radius, double strength) {
  BlobComponent b = sphere(a, radius, strength);
  b.kind = BlobComponent::Kind::cylinder;
  b.end = e;
  return b;
}
}  // namespace

TEST(BlobTest, SingleComponentIsASphereOfKnownRadius) {
  // s (1 - (r/R)^2)^2 = th  =>  r = R sqrt(1 - sqrt(th / s)).
  const double s = 2, R = 1.5, th = 0.5;
  const double r = R * std::sqrt(1 - std::sqrt(th / s));
  const Blob blob(th, {sphere({1, 0, 0}, R, s)});
  HitList hits;
  blob.all_hits({{1, -5, 0}, {0, 0.5, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 2 * (5 - r), 1e-9);
  EXPECT_NEAR(hits[1].t, 2 * (5 + r), 1e-9);
  expect_near(hits[0].normal, {0, -1, 0}, 1e-9);
  expect_near(hits[1].normal, {0, 1, 0}, 1e-9);
  EXPECT_TRUE(blob.inside({1, r - 1e-6, 0}));
  EXPECT_FALSE(blob.inside({1, r + 1e-6, 0}));
  // From inside only the exit remains.
  LocalHit hit;
  ASSERT_TRUE(blob.intersect({{1, 0, 0}, {0, 0, 3}, 0}, 1e-9, kInfinity, hit));
  EXPECT_NEAR(hit.t, r / 3, 1e-9);
}

TEST(BlobTest, TwoComponentsAddAsDocumented) {
  // blob.pov: `component 1.0, 1.0, <+-0.75,0,0>` (strength, radius, centre) with threshold 0.6.
  const Blob blob(0.6, {sphere({0.75, 0, 0}, 1, 1), sphere({-0.75, 0, 0}, 1, 1)});
  const double each = (1 - 0.75 * 0.75) * (1 - 0.75 * 0.75);
  EXPECT_NEAR(blob.density({0, 0, 0}), 2 * each, 1e-15);
  EXPECT_EQ(blob.density({3, 0, 0}), 0);
  // 2 * 0.1914 = 0.383 < 0.6: the two blobs are separate, a ray along y through x=0 misses.
  LocalHit hit;
  EXPECT_FALSE(blob.intersect({{0, -5, 0}, {0, 1, 0}, 0}, 0, kInfinity, hit));
  // Every hit lies where the field equals the threshold.
  HitList hits;
  blob.all_hits({{-5, 0.1, 0.05}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 4u);
  for (const LocalHit& h : hits) EXPECT_NEAR(blob.density({-5 + h.t, 0.1, 0.05}), 0.6, 1e-9);
}

TEST(BlobTest, NegativeComponentCarvesAHole) {
  // Strength 2 radius 2 at the origin minus strength 2 radius 0.5: along x, four crossings.
  const Blob blob(0.5, {sphere({0, 0, 0}, 2, 2), sphere({0, 0, 0}, 0.5, -2)});
  HitList hits;
  blob.all_hits({{-5, 0, 0}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 4u);
  const double outer = 2 * std::sqrt(1 - std::sqrt(0.25));
  EXPECT_NEAR(hits[0].t, 5 - outer, 1e-9);
  EXPECT_NEAR(hits[3].t, 5 + outer, 1e-9);
  EXPECT_FALSE(blob.inside({0, 0, 0}));
  EXPECT_TRUE(blob.inside({1, 0, 0}));
}

TEST(BlobTest, CylinderComponentHasHemisphericalEnds) {
  // Strength 1 radius 1 threshold 0.25: surface at distance d with (1 - d^2)^2 = 0.25, d = sqrt(0.5).
  const double d = std::sqrt(0.5);
  const Blob blob(0.25, {cylinder({-1, 0, 0}, {1, 0, 0}, 1, 1)});
  LocalHit hit;
  ASSERT_TRUE(blob.intersect({{0.3, -5, 0}, {0, 1, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 5 - d, 1e-9);
  expect_near(hit.normal, {0, -1, 0}, 1e-9);
  HitList hits;
  blob.all_hits({{-5, 0, 0}, {1, 0, 0}, 0}, 0, kInfinity, hits);  // along the axis: through both caps
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 5 - 1 - d, 1e-9);
  EXPECT_NEAR(hits[1].t, 5 + 1 + d, 1e-9);
  // Slanted through the hemispherical end: the point lies at distance d from the end point.
  ASSERT_TRUE(blob.intersect({{1.5, -5, 0.1}, {0, 1, 0}, 0}, 0, kInfinity, hit));
  const Vec3 p{1.5, -5 + hit.t, 0.1};
  EXPECT_NEAR(length(p - Vec3(1, 0, 0)), d, 1e-9);
}

TEST(BlobTest, ComponentTransformIsApplied) {
  BlobComponent c = sphere({0, 0, 0}, 1, 1);
  c.transform = Transform::translate({0, 0, 3}) * Transform::scale({2, 1, 1});  // ellipsoid at z = 3
  const double r = std::sqrt(1 - std::sqrt(0.25));
  const Blob blob(0.25, {c});
  HitList hits;
  blob.all_hits({{-5, 0, 3}, {1, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 5 - 2 * r, 1e-9);
  expect_near(hits[0].normal, {-1, 0, 0}, 1e-9);
  EXPECT_TRUE(blob.inside({1.5 * r, 0, 3}));
  EXPECT_FALSE(blob.inside({1.5 * r, 0, 0}));
  // Normal on the ellipsoid's side is the inverse-transpose one: along (x/4, y, 0) direction.
  LocalHit hit;
  ASSERT_TRUE(blob.intersect({{r, -5, 3}, {0, 1, 0}, 0}, 0, kInfinity, hit));
  const Vec3 p{r, -5 + hit.t, 0};
  expect_near(hit.normal, normalize(Vec3(p.x / 4, p.y, 0)), 1e-9);
}

TEST(BlobTest, DistantRayAndScaledDirection) {
  const Blob blob(0.5, {sphere({0, 0, 0}, 1.5, 2)});
  const double r = 1.5 * std::sqrt(0.5);
  LocalHit hit;
  ASSERT_TRUE(blob.intersect({{0, 0, -1e5}, {0, 0, 1e-3}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, (1e5 - r) * 1e3, 1e-3);
  EXPECT_FALSE(blob.intersect({{0, 0, -1e5}, {0, 0, -1}, 0}, 0, kInfinity, hit));
}

TEST(BlobTest, RandomRays) {
  BlobComponent t = cylinder({0, 0, 0}, {0, 1.5, 0}, 0.6, 1.5);
  t.transform = Transform::rotate_xyz_degrees({20, 0, 30});
  shape_checks::check_random_rays(
      Blob(0.6, {sphere({0.75, 0, 0}, 1, 1), sphere({-0.75, 0, 0}, 1, 1), sphere({0, 0.5, 0}, 0.8, 1.2),
                 sphere({0, 0.2, 0.3}, 0.4, -0.5), t}),
      true);
}

TEST(BlobTest, BadInputThrows) {
  EXPECT_THROW(Blob(0, {sphere({0, 0, 0}, 1, 1)}), std::invalid_argument);
  EXPECT_THROW(Blob(0.5, {}), std::invalid_argument);
  EXPECT_THROW(Blob(0.5, {sphere({0, 0, 0}, 0, 1)}), std::invalid_argument);
}
