// parametric against the shapes it describes: a parametric sphere must behave as the sphere.
#include "snell/geometry/parametric.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "shape_checks.hpp"
#include "snell/geometry/box.hpp"
#include "snell/geometry/sphere.hpp"

namespace snell::geometry {
namespace {

using function::Function;
using math::kInfinity;
using math::kPi;

/// x = cos v cos u, y = sin v, z = cos v sin u over u in [0, 2 pi], v in [-pi/2, pi/2]: the unit sphere.
ParametricSettings unit_sphere(double box_low_y = -1) {
  ParametricSettings s;
  s.functions = {Function::native("x", 3, [](const double* a) { return std::cos(a[1]) * std::cos(a[0]); }),
                 Function::native("y", 3, [](const double* a) { return std::sin(a[1]); }),
                 Function::native("z", 3, [](const double* a) { return std::cos(a[1]) * std::sin(a[0]); })};
  s.uv_min = {0, -kPi / 2};
  s.uv_max = {2 * kPi, kPi / 2};
  s.container = std::make_shared<Box>(Vec3(-1.1, box_low_y, -1.1), Vec3(1.1));
  s.lattice = 48;
  return s;
}

TEST(ParametricTest, SphereHitsAsTheSphere) {
  const Parametric surface(unit_sphere());
  const Sphere sphere({0, 0, 0}, 1);
  math::Pcg32 rng(7);
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const Vec3 origin = 4 * shape_checks::random_unit(rng);
    const Vec3 target = 1.2 * rng.next_double() * shape_checks::random_unit(rng);
    const Ray ray{origin, normalize(target - origin) * 0.7, 0};
    LocalHit expected, got;
    const bool any = sphere.intersect(ray, 1e-9, kInfinity, expected);
    const bool found = surface.intersect(ray, 1e-9, kInfinity, got);
    // Rays grazing the rim may differ: the lattice finds the patch, only then Newton refines.
    const Vec3 p = ray.at(expected.t);
    if (any && std::fabs(dot(normalize(p), normalize(ray.direction))) < 0.05) continue;
    ASSERT_EQ(any, found) << i;
    if (!any) continue;
    ++hits;
    EXPECT_NEAR(got.t, expected.t, 1e-8);
    // POV-Ray's normal, the cross product of the u and v differences, is the outward one up to sign.
    EXPECT_NEAR(std::fabs(dot(normalize(got.normal), normalize(expected.normal))), 1, 1e-5);
    // uv is (u, v) of the hit point.
    EXPECT_NEAR(std::sin(got.uv.v), p.y, 1e-7);
  }
  EXPECT_GT(hits, 100);
}

TEST(ParametricTest, ContainerCutsTheSurface) {
  const Parametric upper(unit_sphere(0));  // only y >= 0 is kept
  LocalHit hit;
  EXPECT_FALSE(upper.intersect({{0, -0.5, -5}, {0, 0, 1}, 0}, 0, kInfinity, hit));
  ASSERT_TRUE(upper.intersect({{0, 0.5, -5}, {0, 0, 1}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 5 - std::sqrt(0.75), 1e-8);
  // From below, the ray crosses the open bowl's inside and meets its far wall.
  ASSERT_TRUE(upper.intersect({{0, -5, 0.5}, {0, 1, 0}, 0}, 0, kInfinity, hit));
  EXPECT_NEAR(hit.t, 5 + std::sqrt(0.75), 1e-8);
  EXPECT_FALSE(upper.inside({0, 0.5, 0}));  // no interior, as in POV-Ray
}

TEST(ParametricTest, RejectsBadSettings) {
  ParametricSettings s = unit_sphere();
  s.functions[1] = nullptr;
  EXPECT_THROW(Parametric{s}, std::invalid_argument);
  ParametricSettings flat = unit_sphere();
  flat.functions = {Function::native("0", 3, [](const double*) { return 0.0; }), flat.functions[0],
                    Function::native("0", 3, [](const double*) { return 0.0; })};
  EXPECT_THROW(Parametric{flat}, std::invalid_argument);  // a curve: no triangle has area
}

}  // namespace
}  // namespace snell::geometry
