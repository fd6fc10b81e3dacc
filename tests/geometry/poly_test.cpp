#include "snell/geometry/poly.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "shape_checks.hpp"
#include "snell/geometry/torus.hpp"

using namespace snell::geometry;
using snell::geometry::shape_checks::expect_near;
using snell::math::kInfinity;

namespace {

// The unit sphere x^2 + y^2 + z^2 - 1 as POV-Ray's order-2 poly: x2 xy xz x y2 yz y z2 z 1.
Poly unit_sphere() {
  return Poly(2, {1, 0, 0, 0, 1, 0, 0, 1, 0, -1});
}

// examples/objects/quartic/torus.pov: (x^2+y^2+z^2)^2 - 104 x^2 + 56 y^2 - 104 z^2 + 784, which is
// (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) with R^2 = 40, r^2 = 12.
Poly example_torus() {
  return Poly(4, {1, 0, 0, 0, 2, 0, 0, 2,  0, -104, 0, 0, 0, 0, 0,    0, 0,  0,
                  0, 0, 1, 0, 0, 2, 0, 56, 0, 0,    0, 0, 1, 0, -104, 0, 784});
}

}  // namespace

TEST(PolyTest, CoefficientCounts) {
  EXPECT_EQ(poly_coefficient_count(2), 10);
  EXPECT_EQ(poly_coefficient_count(3), 20);
  EXPECT_EQ(poly_coefficient_count(4), 35);
  EXPECT_THROW(Poly(4, std::vector<double>(34, 1.0)), std::invalid_argument);
  EXPECT_THROW(Poly(7, std::vector<double>(120, 1.0)), std::invalid_argument);
  EXPECT_THROW(Poly(2, std::vector<double>(10, 0.0)), std::invalid_argument);
}

TEST(PolyTest, CubicTermOrderFollowsTheReference) {
  // POV-Ray reference, "Cubic": term 12 is y^2 z and term 20 the constant.
  std::vector<double> c(20, 0.0);
  c[11] = 1;
  c[19] = -1;
  const Poly cubic(3, c);
  EXPECT_NEAR(cubic.value({7, 2, 0.25}), 0, 1e-12);
  EXPECT_NEAR(cubic.value({0, 1, 2}), 1, 1e-12);
  expect_near(cubic.gradient({5, 2, 3}), {0, 12, 4}, 1e-12);
}

TEST(PolyTest, SphereHitsAndNormals) {
  const Poly sphere = unit_sphere();
  HitList hits;
  sphere.all_hits({{-5, 0, 0}, {0.5, 0, 0}, 0}, 0, kInfinity, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].t, 8, 1e-9);
  EXPECT_NEAR(hits[1].t, 12, 1e-9);
  expect_near(normalize(hits[0].normal), {-1, 0, 0}, 1e-9);
  expect_near(normalize(hits[1].normal), {1, 0, 0}, 1e-9);
  EXPECT_TRUE(sphere.inside({0.5, 0.5, 0.5}));
  EXPECT_FALSE(sphere.inside({0.7, 0.7, 0.7}));
}

TEST(PolyTest, QuarticTorusMatchesTheTorus) {
  const Poly quartic = example_torus();
  const Torus torus(std::sqrt(40.0), std::sqrt(12.0));
  snell::math::Pcg32 rng(7);
  int compared = 0;
  for (int i = 0; i < 500; ++i) {
    const Vec3 origin = 30.0 * shape_checks::random_unit(rng);
    const Vec3 target = 8.0 * rng.next_double() * shape_checks::random_unit(rng);
    const Ray ray{origin, normalize(target - origin), 0};
    HitList expected, got;
    torus.all_hits(ray, 1e-9, kInfinity, expected);
    quartic.all_hits(ray, 1e-9, kInfinity, got);
    // Grazing rays may legitimately differ by a double root; compare the clear cases.
    if (expected.size() != got.size()) {
      EXPECT_TRUE(expected.size() % 2 == 0 && got.size() % 2 == 0);
      continue;
    }
    for (size_t k = 0; k < got.size(); ++k) {
      EXPECT_NEAR(got[k].t, expected[k].t, 1e-6);
      expect_near(normalize(got[k].normal), normalize(expected[k].normal), 1e-5);
      EXPECT_EQ(quartic.inside(ray.at(got[k].t) + 1e-4 * normalize(got[k].normal)), false);
    }
    compared += !got.empty();
  }
  EXPECT_GT(compared, 100);
}

TEST(PolyTest, DistantRayKeepsPrecision) {
  LocalHit hit;
  ASSERT_TRUE(unit_sphere().intersect({{-1e5, 0, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 1e5 - 1, 1e-7);
}

TEST(PolyTest, MissAndBehind) {
  LocalHit hit;
  EXPECT_FALSE(unit_sphere().intersect({{-5, 2, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
  EXPECT_FALSE(unit_sphere().intersect({{5, 0, 0}, {1, 0, 0}, 0}, 0, kInfinity, hit));
}
