// Isosurface root finding against analytic answers and the sphere-tracing vectors of
// ../shared/reference-values.md section 7 (Hart 1996; Mike Williams' isosurface tutorial).
#include "snell/geometry/isosurface.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/geometry/box.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/constants.hpp"

namespace snell::geometry {
namespace {

using function::Function;

std::shared_ptr<const Function> unit_sphere_sdf() {
  return Function::native(
      "sdf", 3, [](const double* a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) - 1; });
}

IsosurfaceSettings in_box(std::shared_ptr<const Function> f, double half) {
  IsosurfaceSettings s;
  s.function = std::move(f);
  s.container = std::make_shared<Box>(Vec3(-half), Vec3(half));
  return s;
}

TEST(IsosurfaceTest, SphereSdfHeadOnHitsAtFour) {
  IsosurfaceSettings s = in_box(unit_sphere_sdf(), 2);
  s.accuracy = 1e-6;
  s.max_gradient = 1;
  const Isosurface iso(s);
  LocalHit hit;
  ASSERT_TRUE(iso.intersect({{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4, 1e-6);
  const Vec3 n = normalize(hit.normal);
  EXPECT_NEAR(n.z, -1, 1e-3);
}

TEST(IsosurfaceTest, EvaluationCountFollowsTheLipschitzBound) {
  // Exact distance to the unit sphere, L = 1, container box half size 2. A ray passing 0.5 above the
  // sphere is never nearer than 0.5, so every safe step is >= 0.5 over its 4 units in the box: at most 8
  // safe steps, each possibly after a failed over-relaxed try, plus the entry sample: <= 17 evaluations.
  IsosurfaceSettings s = in_box(unit_sphere_sdf(), 2);
  s.max_gradient = 1;
  s.count_work = true;
  const Isosurface miss(s);
  LocalHit hit;
  EXPECT_FALSE(miss.intersect({{0, 1.5, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_GE(miss.evaluations(), 5u);
  EXPECT_LE(miss.evaluations(), 17u);
  // Head on: the entry sample (g = 1 at z = -2), one over-relaxed step to z = -0.1 (g = -0.9, covered
  // since 1 + 0.9 >= 1.9), whose regula falsi point is the exact root z = -1 (g = 0, done), then the
  // normal's four samples: 7.
  const Isosurface head_on(s);
  ASSERT_TRUE(head_on.intersect({{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4, 1e-12);
  EXPECT_EQ(head_on.evaluations(), 7u);
}

TEST(IsosurfaceTest, ARayBackAlongAMarchedOneReusesItsProof) {
  // A light at the camera: the shadow ray from the hit point back to the camera retraces the camera ray,
  // whose march proved that stretch free of roots. It gets the same answer (no blocker) without marching:
  // one evaluation (is it on the surface?) against the march's many.
  IsosurfaceSettings s = in_box(unit_sphere_sdf(), 2);
  s.max_gradient = 20;  // a loose bound: the march takes many short steps
  s.count_work = true;
  const Isosurface iso(s), fresh(s);
  LocalHit hit, none;
  ASSERT_TRUE(iso.intersect({{0.3, 0.2, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  const Vec3 p = Vec3(0.3, 0.2, -5) + Vec3(0, 0, 1) * hit.t;
  const std::uint64_t before = iso.evaluations();
  EXPECT_FALSE(iso.intersect({p, {0, 0, -1}, 0}, 1e-9, hit.t, none));
  EXPECT_EQ(iso.evaluations() - before, 1u);
  // The same shadow ray on an isosurface that marched nothing yet: the same answer, marched.
  EXPECT_FALSE(fresh.intersect({p, {0, 0, -1}, 0}, 1e-9, hit.t, none));
  EXPECT_GT(fresh.evaluations(), 20u);
  // A ray off that line by more than a hair marches.
  const std::uint64_t again = iso.evaluations();
  EXPECT_FALSE(iso.intersect({p + Vec3(1e-5, 0, 0), {0, 0, -1}, 0}, 1e-9, hit.t, none));
  EXPECT_GT(iso.evaluations() - again, 20u);
}

TEST(IsosurfaceTest, CrossesAnswersAsIntersectWithoutTheNormal) {
  // Rays through, beside and ending short of the unit sphere, and one starting inside it: crosses agrees
  // with intersect, and a ray that hits costs the normal's four samples less.
  IsosurfaceSettings s = in_box(unit_sphere_sdf(), 2);
  s.max_gradient = 1;
  s.count_work = true;
  const struct {
    Ray ray;
    double t_max;
    bool hits;
  } cases[] = {{{{0, 0, -5}, {0, 0, 1}, 0}, math::kInfinity, true},
               {{{0, 1.5, -5}, {0, 0, 1}, 0}, math::kInfinity, false},
               {{{0, 0, -5}, {0, 0, 1}, 0}, 3.5, false},
               {{{0.3, 0.2, 0}, {1, 0.5, 0}, 0}, math::kInfinity, true}};
  for (const auto& c : cases) {
    const Isosurface by_intersect(s), by_crosses(s);
    LocalHit hit;
    EXPECT_EQ(by_intersect.intersect(c.ray, 1e-9, c.t_max, hit), c.hits);
    EXPECT_EQ(by_crosses.crosses(c.ray, 1e-9, c.t_max), c.hits);
    EXPECT_EQ(by_crosses.evaluations() + (c.hits ? 4 : 0), by_intersect.evaluations());
  }
}

TEST(IsosurfaceTest, SphereSdfOffCentreMatchesReferenceVector) {
  IsosurfaceSettings s = in_box(unit_sphere_sdf(), 2);
  s.accuracy = 1e-6;
  s.max_gradient = 1;
  const Isosurface iso(s);
  LocalHit hit;
  ASSERT_TRUE(iso.intersect({{-3, 0.5, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 3 - std::sqrt(0.75), 1e-6);  // 2.1339746
}

TEST(IsosurfaceTest, SquaredRadiusInSphereContainerWithTutorialGradient) {
  // f = x^2 + y^2 + z^2 - 1 in sphere r = 1.2 with max_gradient 2.4, from (-1.2, 0, 0) along +x: t = 0.2.
  IsosurfaceSettings s;
  s.function =
      Function::native("r2", 3, [](const double* a) { return a[0] * a[0] + a[1] * a[1] + a[2] * a[2] - 1; });
  s.container = std::make_shared<Sphere>(Vec3(0), 1.2);
  s.max_gradient = 2.4;
  const Isosurface iso(s);
  LocalHit hit;
  ASSERT_TRUE(iso.intersect({{-1.2, 0, 0}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 0.2, 1e-3);
  EXPECT_LE(iso.steepest_slope(), 2.4);  // 2|p| <= 2.4 inside the container
}

TEST(IsosurfaceTest, ClosedContainerShowsItsWallWhereInsideReachesIt) {
  // f = x: the half x < 0 is inside, cut by the box [-1, 1]^3.
  const auto half_space = Function::native("x", 3, [](const double* a) { return a[0]; });
  IsosurfaceSettings s = in_box(half_space, 1);
  LocalHit hit;
  ASSERT_TRUE(Isosurface(s).intersect({{-0.5, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 4, 1e-12);
  EXPECT_NEAR(normalize(hit.normal).z, -1, 1e-12);
  s.open = true;  // no wall: the ray never crosses f = 0
  EXPECT_FALSE(Isosurface(s).intersect({{-0.5, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  // From the outside half the ray meets the plane x = 0 itself.
  ASSERT_TRUE(Isosurface(s).intersect({{0.5, 0, 0}, {-1, 0, 0}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 0.5, 1e-3);
  EXPECT_NEAR(normalize(hit.normal).x, 1, 1e-9);
}

TEST(IsosurfaceTest, MaxTraceLimitsCrossingsForCsg) {
  IsosurfaceSettings s = in_box(unit_sphere_sdf(), 2);
  HitList hits;
  Isosurface(s).all_hits({{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hits);
  EXPECT_EQ(hits.size(), 1u);  // POV-Ray's default max_trace 1
  s.max_trace = 1 << 30;       // all_intersections
  hits.clear();
  Isosurface(s).all_hits({{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 4, 1e-3);
  EXPECT_NEAR(hits[1].t, 6, 1e-3);
}

TEST(IsosurfaceTest, InsideIsBelowThresholdWithinContainer) {
  IsosurfaceSettings s = in_box(unit_sphere_sdf(), 2);
  s.threshold = 0.5;  // the surface is the sphere of radius 1.5
  const Isosurface iso(s);
  EXPECT_TRUE(iso.inside({1.4, 0, 0}));
  EXPECT_FALSE(iso.inside({1.6, 0, 0}));
  EXPECT_FALSE(iso.inside({1.4, 1.4, 1.4}));
}

TEST(IsosurfaceTest, SteeperSlopeThanMaxGradientIsReported) {
  const auto steep = Function::native("10x", 3, [](const double* a) { return 10 * a[0]; });
  IsosurfaceSettings s = in_box(steep, 1);
  const Isosurface iso(s);
  LocalHit hit;
  iso.intersect({{0.9, 0, 0}, {-1, 0, 0}, 0}, 1e-9, math::kInfinity, hit);
  EXPECT_NEAR(iso.steepest_slope(), 10, 1e-6);
}

TEST(IsosurfaceTest, EstimatedGradientBoundsTheTrueOne) {
  // |grad (x^2 + y^2 + z^2)| = 2|p| peaks at the corners of [-1, 1]^3: 2 sqrt(3).
  const auto r2 =
      Function::native("r2", 3, [](const double* a) { return a[0] * a[0] + a[1] * a[1] + a[2] * a[2]; });
  const double g = estimate_max_gradient(*r2, Bounds3(Vec3(-1), Vec3(1)), 0, 1);
  EXPECT_NEAR(g, 2 * std::sqrt(3.0), 0.3);
  EXPECT_EQ(estimate_max_gradient(*r2, Bounds3(Vec3(-1), Vec3(1)), 50, 1), 50);
}

}  // namespace
}  // namespace snell::geometry
