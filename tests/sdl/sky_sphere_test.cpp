// POV-Ray `sky_sphere`: rays that miss everything see its pigment in their direction, over the background.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sdl_test_util.hpp"
#include "snell/math/transform.hpp"

namespace snell::sdl {
namespace {

TEST(SdlSkySphere, SolidPigmentReplacesBackground) {
  const auto scene = test::parse("background { rgb 1 } sky_sphere { pigment { rgb <0.2, 0.4, 0.6> } }");
  ASSERT_TRUE(scene.sky_sphere.has_value());
  const math::Color c = scene.miss_color({0, 0, 1});
  EXPECT_DOUBLE_EQ(c.r, 0.2);
  EXPECT_DOUBLE_EQ(c.b, 0.6);
}

TEST(SdlSkySphere, GradientFollowsDirectionAndTransform) {
  const std::string sky = "sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } }";
  const auto plain = test::parse(sky + " }");
  // Thirty degrees above the horizon the unit direction has y = 0.5: the middle of the map.
  EXPECT_NEAR(plain.miss_color({0, 0.5, std::sqrt(0.75)}).r, 0.5, 1e-9);
  // A transformed sky seen along R d looks exactly like the plain sky along d.
  const auto rotated = test::parse(sky + " rotate <90, 0, 30> }");
  const auto r = math::Transform::rotate_xyz_degrees({90, 0, 30});
  for (const math::Vec3 d : {math::Vec3(0, 0.5, 0.8), math::Vec3(0.3, 0.2, -0.9), math::Vec3(-0.6, 0.7, 0.1)})
    EXPECT_NEAR(rotated.miss_color(r.vector(d)).r, plain.miss_color(d).r, 1e-9);
}

TEST(SdlSkySphere, TransparentLayerShowsBackground) {
  const auto scene =
      test::parse("background { rgb <1, 0, 0> } sky_sphere { pigment { rgbt <0, 0, 1, 0.25> } }");
  const math::Color c = scene.miss_color({1, 0, 0});
  EXPECT_DOUBLE_EQ(c.r, 0.25);
  EXPECT_DOUBLE_EQ(c.b, 0.75);
}

}  // namespace
}  // namespace snell::sdl

TEST(SdlSkySphere, DeclaredSkySphereIsReusedAndModified) {
  // skies.inc declares its skies this way: `#declare S = sky_sphere {..}` then `sky_sphere { S }`.
  const snell::scene::Scene s = snell::sdl::test::parse(R"(
    #declare S = sky_sphere { pigment { rgb <0.2, 0.4, 0.6> } }
    sky_sphere { S rotate y * 30 })");
  ASSERT_TRUE(s.sky_sphere.has_value());
  EXPECT_EQ(s.sky_sphere->pigments.size(), 1u);
}
