#include "snell/geometry/poly_bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "shape_checks.hpp"
#include "snell/geometry/poly.hpp"

using namespace snell::geometry;
using snell::math::Bounds3;
using snell::math::Vec3;

namespace {

double sum(const std::vector<PolyTerm>& terms, const Vec3& p) {
  double s = 0;
  for (const PolyTerm& t : terms) s += t.c * std::pow(p.x, t.i) * std::pow(p.y, t.j) * std::pow(p.z, t.k);
  return s;
}

// (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) with R^2 = 40, r^2 = 12 (examples/objects/quartic/torus.pov):
// a torus about the y axis, outer radius sqrt(40) + sqrt(12) = 9.789, half height sqrt(12) = 3.464.
const std::vector<PolyTerm> kTorus = {{4, 0, 0, 1},    {2, 2, 0, 2},  {2, 0, 2, 2},    {0, 4, 0, 1},
                                      {0, 2, 2, 2},    {0, 0, 4, 1},  {2, 0, 0, -104}, {0, 2, 0, 56},
                                      {0, 0, 2, -104}, {0, 0, 0, 784}};

// x^4 - x^2 + y^2 + z^2 (examples/objects/primitiv.pov's poly 4): y^2 + z^2 = x^2 (1 - x^2) <= 1/4, so
// |x| <= 1 and |y|, |z| <= 1/2. Its highest form x^4 alone is not definite: weighted, not total, degree.
const std::vector<PolyTerm> kPinched = {{4, 0, 0, 1}, {2, 0, 0, -1}, {0, 2, 0, 1}, {0, 0, 2, 1}};

/// Every point sampled outside `box` (within three times its size) has a positive sum, and the box is
/// no more than `slack` larger than `tight` on each side.
void expect_encloses(const std::vector<PolyTerm>& terms, const Bounds3& box, const Bounds3& tight,
                     double slack) {
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(box.lo[a], tight.lo[a]) << "axis " << a;
    EXPECT_GE(box.hi[a], tight.hi[a]) << "axis " << a;
    EXPECT_GE(box.lo[a], tight.lo[a] - slack) << "axis " << a;
    EXPECT_LE(box.hi[a], tight.hi[a] + slack) << "axis " << a;
  }
  std::mt19937 rng(7);
  const Vec3 c = box.center(), e = 1.5 * box.extent() + Vec3(1);
  std::uniform_real_distribution<double> u(-1, 1);
  int outside = 0;
  for (int n = 0; n < 200000; ++n) {
    const Vec3 p = c + Vec3(u(rng) * e.x, u(rng) * e.y, u(rng) * e.z);
    if (box.contains(p)) continue;
    ++outside;
    ASSERT_GT(sum(terms, p), 0) << p.x << " " << p.y << " " << p.z;
  }
  EXPECT_GT(outside, 100000);
}

}  // namespace

TEST(PolyBoundsTest, TorusGetsATightBox) {
  const auto box = poly_negative_region_bounds(kTorus);
  ASSERT_TRUE(box);
  const double outer = std::sqrt(40.0) + std::sqrt(12.0), half = std::sqrt(12.0);
  expect_encloses(kTorus, *box, {Vec3(-outer, -half, -outer), Vec3(outer, half, outer)}, 1.5);
}

TEST(PolyBoundsTest, WeightedDegreeBoundsAShapeWhoseTopFormIsNotDefinite) {
  const auto box = poly_negative_region_bounds(kPinched);
  ASSERT_TRUE(box);
  expect_encloses(kPinched, *box, {Vec3(-1, -0.5, -0.5), Vec3(1, 0.5, 0.5)}, 0.1);
}

TEST(PolyBoundsTest, SphereAndEllipsoid) {
  const std::vector<PolyTerm> ellipsoid = {{2, 0, 0, 1}, {0, 2, 0, 4}, {0, 0, 2, 16}, {0, 0, 0, -1}};
  const auto box = poly_negative_region_bounds(ellipsoid);
  ASSERT_TRUE(box);
  expect_encloses(ellipsoid, *box, {Vec3(-1, -0.5, -0.25), Vec3(1, 0.5, 0.25)}, 0.05);
}

TEST(PolyBoundsTest, TermsOfFullWeightTakeTheirShareFirst) {
  // x^4 + y^4 + z^4 - x^2 y^2 - 1: AM-GM gives x^2 y^2 <= (x^4 + y^4) / 2, so a positive definite top.
  const std::vector<PolyTerm> terms = {
      {4, 0, 0, 1}, {0, 4, 0, 1}, {0, 0, 4, 1}, {2, 2, 0, -1}, {0, 0, 0, -1}};
  const auto box = poly_negative_region_bounds(terms);
  ASSERT_TRUE(box);
  // On the diagonal x = y the sum is x^4 - 1 (z = 0): the surface reaches |x| = |y| = 1; along z, 1.
  expect_encloses(terms, *box, {Vec3(-1, -1, -1), Vec3(1, 1, 1)}, 0.6);
}

TEST(PolyBoundsTest, UnboundedOrUndecidedSurfacesGetNone) {
  // A cubic's odd highest power, a hyperboloid x^2 - y^2 + z^2 - 1, a paraboloid (no pure y power
  // of even degree), a cylinder (no z at all), and x^4 + y^4 + z^4 - 3 x^2 y^2 (the top form dips
  // below zero on the diagonal, so it is negative far out).
  const std::vector<std::vector<PolyTerm>> shapes = {
      {{2, 0, 0, 1}, {0, 3, 0, 1}, {0, 2, 0, 0.45}, {0, 0, 2, 1}, {0, 0, 0, -1}},
      {{2, 0, 0, 1}, {0, 2, 0, -1}, {0, 0, 2, 1}, {0, 0, 0, -1}},
      {{2, 0, 0, 1}, {0, 1, 0, -1}, {0, 0, 2, 1}},
      {{2, 0, 0, 1}, {0, 2, 0, 1}, {0, 0, 0, -1}},
      {{4, 0, 0, 1}, {0, 4, 0, 1}, {0, 0, 4, 1}, {2, 2, 0, -3}},
  };
  for (size_t n = 0; n < shapes.size(); ++n) EXPECT_FALSE(poly_negative_region_bounds(shapes[n])) << n;
}

TEST(PolyBoundsTest, PolyShapeReportsTheBoxAndHitsAsBefore) {
  // POV-Ray's order 4 coefficient list of primitiv.pov's poly: x^4, x^2 (10th), y^2 (26th), z^2 (33rd).
  std::vector<double> c(35, 0.0);
  c[0] = 1;
  c[9] = -1;
  c[25] = 1;
  c[32] = 1;
  const Poly pinched(4, c);
  EXPECT_TRUE(pinched.inside_within_bounds());
  const Bounds3 b = pinched.bounds();
  EXPECT_TRUE(b.is_finite());
  EXPECT_LE(b.hi.x, 1.1);
  EXPECT_GE(b.hi.x, 1.0);
  // Hits inside the box, crosses agreeing with intersect, no inside point outside the box (normals not
  // checked: the two lobes meet in a cone point at the origin, where a step along the normal may land
  // in the other lobe).
  shape_checks::check_random_rays(pinched, false, 500);
  LocalHit hit;
  ASSERT_TRUE(pinched.intersect({{-5, 0.1, 0}, {1, 0, 0}, 0}, 0, 100, hit));
  EXPECT_GT(hit.t, 4);
  // A cubic is never bounded.
  std::vector<double> cubic(20, 0.0);
  cubic[3] = 1;
  cubic[19] = -1;
  EXPECT_FALSE(Poly(3, cubic).inside_within_bounds());
  EXPECT_FALSE(Poly(3, cubic).bounds().is_finite());
}
