#include "snell/geometry/surface_uv.hpp"

#include <gtest/gtest.h>

#include <memory>

#include "snell/geometry/cylinder.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/geometry/torus.hpp"
#include "snell/material/pigment.hpp"
#include "snell/texture/pattern_pigment.hpp"

namespace snell {
namespace {

// A uv_mapping pigment asks for surface uv when it is made, and the sphere then gives POV-Ray's spherical
// mapping: u = 0.5 + atan2(x, z) / 2pi around y, v = 0.5 + asin(y) / pi from the south pole to the north.
// So (0, 0, 1) is (0.5, 0.5), (1, 0, 0) has u = 0.75 and the north pole v = 1.
TEST(SurfaceUvTest, UvMappedPigmentRequestsTheSpheresUv) {
  const texture::UvMappedPigment pigment(
      std::make_shared<material::SolidPigment>(material::Rgbft{math::Color(1, 0, 0)}));
  EXPECT_TRUE(geometry::surface_uv_requested());
  const geometry::Sphere sphere({0, 0, 0}, 1);
  geometry::LocalHit hit;
  ASSERT_TRUE(sphere.intersect({{0, 0, 5}, {0, 0, -1}, 0}, 0, 100, hit));
  EXPECT_NEAR(hit.uv.u, 0.5, 1e-12);
  EXPECT_NEAR(hit.uv.v, 0.5, 1e-12);
  ASSERT_TRUE(sphere.intersect({{0, 5, 0}, {0, -1, 0}, 0}, 0, 100, hit));
  EXPECT_NEAR(hit.uv.v, 1.0, 1e-12);
  ASSERT_TRUE(sphere.intersect({{5, 0, 0}, {-1, 0, 0}, 0}, 0, 100, hit));  // +x: a quarter turn on
  EXPECT_NEAR(hit.uv.u, 0.75, 1e-12);
  // The torus (u around y, v around its tube) and the cylinder (v along the axis) too.
  const geometry::Torus torus(2, 0.5);
  ASSERT_TRUE(torus.intersect({{5, 0, 0}, {-1, 0, 0}, 0}, 0, 100, hit));
  EXPECT_NEAR(hit.uv.u, 0.5, 1e-9);
  EXPECT_NEAR(hit.uv.v, 0.5, 1e-9);
  const geometry::Cylinder cylinder({0, 0, 0}, {0, 4, 0}, 1, false);
  ASSERT_TRUE(cylinder.intersect({{5, 1, 0}, {-1, 0, 0}, 0}, 0, 100, hit));
  EXPECT_NEAR(hit.uv.v, 0.25, 1e-12);
}

}  // namespace
}  // namespace snell
