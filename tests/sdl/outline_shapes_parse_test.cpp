// poly/cubic/quartic, polygon, prism, lathe, sor and text as the parser builds them (POV-Ray 3.7
// reference, "Poly, Cubic and Quartic", "Polygon", "Prism", "Lathe", "Surface of Revolution", "Text").
#include <gtest/gtest.h>

#include <string>

#include "sdl_test_util.hpp"
#include "snell/math/constants.hpp"
#include "snell/scene/csg.hpp"

namespace snell::sdl {
namespace {

using math::Vec3;

// Distance along +x from x = -10 (at height y, depth z) to the first surface of the scene's only object.
double first_hit_along_x(const scene::Scene& s, double y = 0.5, double z = 0) {
  EXPECT_EQ(s.objects.size(), 1u);
  scene::SurfaceHit hit;
  if (!s.objects[0]->intersect({{-10, y, z}, {1, 0, 0}, 0}, 1e-9, math::kInfinity, hit)) return -1;
  return hit.t;
}

TEST(SdlOutlineShapes, QuarticFromShapesqAndSturmModifier) {
  // shapesq.inc's Piriform is used as `object { Piriform sturm }` in teardrop.pov.
  const scene::Scene s = test::parse(R"(
    #include "shapes.inc"
    #include "shapesq.inc"
    object { Piriform sturm translate <1, 0, 0> }
  )");
  ASSERT_EQ(s.objects.size(), 1u);
}

TEST(SdlOutlineShapes, PolySphereWithTransforms) {
  const scene::Scene s =
      test::parse("poly { 2, <1,0,0,0, 1,0,0, 1,0, -1> sturm scale 2 translate <1, 0, 0> }");
  EXPECT_NEAR(first_hit_along_x(s, 0), 9, 1e-9);
  EXPECT_TRUE(s.objects[0]->inside({2.5, 0, 0}));
}

TEST(SdlOutlineShapes, PrismLatheSorPolygon) {
  EXPECT_NEAR(
      first_hit_along_x(test::parse("prism { linear_sweep linear_spline 0, 1, 4, <-1,-1>, <1,-1>, <0,1>, "
                                    "<-1,-1> }")),
      9.5, 1e-9);  // at z = 0 the left edge, from (-1, -1) to (0, 1), is at x = -0.5
  EXPECT_NEAR(first_hit_along_x(test::parse("lathe { linear_spline 4, <0,0>, <2,0>, <2,1>, <0,1> }")), 8,
              1e-9);
  EXPECT_NEAR(first_hit_along_x(test::parse("sor { 4, <1,-1>, <1,0>, <1,1>, <1,2> open }")), 9, 1e-9);
  EXPECT_NEAR(first_hit_along_x(test::parse("polygon { 4, <0,0,0>, <0,1,0>, <0,1,1>, <0,0,0> }"), 0.5, 0.25),
              10, 1e-9);
}

TEST(SdlOutlineShapes, UnclosedLinearPrismIsClosedWithAWarning) {
  std::vector<std::string> messages;
  const scene::Scene s = test::parse("prism { 0, 1, 3, <-1,-1>, <1,-1>, <0,1> }", &messages);
  EXPECT_NEAR(first_hit_along_x(s), 9.5, 1e-9);
  bool warned = false;
  for (const auto& m : messages) warned |= m.find("not closed") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(SdlOutlineShapes, TextInCsg) {
  // A font name without ".ttf" is found as POV-Ray finds it; the letter I of Times is about 0.3 wide.
  const scene::Scene s = test::parse(R"(
    difference { text { ttf "timrom" "I", 1, 0 } box { <-1, -1, -1>, <1, 2, 0.5> } }
  )");
  ASSERT_EQ(s.objects.size(), 1u);
  scene::SurfaceHit hit;
  // Straight down the z axis into the stem of the I: the box removes the front half.
  ASSERT_TRUE(s.objects[0]->intersect({{0.15, 0.3, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  EXPECT_NEAR(hit.t, 5.5, 1e-9);
}

TEST(SdlOutlineShapes, Errors) {
  EXPECT_NE(test::error_of("quartic { <1, 2, 3> }").find("needs 35 coefficients"), std::string::npos);
  EXPECT_NE(test::error_of("poly { 9, <1> }").find("poly order"), std::string::npos);
  EXPECT_NE(test::error_of("prism { cubic_spline 0, 1, 3, <0,0>, <1,0>, <0,1> }").find("needs between 6"),
            std::string::npos);
  EXPECT_NE(test::error_of("prism { bezier_spline 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,1> }").find("not closed"),
            std::string::npos);
  EXPECT_NE(test::error_of("sor { 4, <1,0>, <1,1>, <1,0.5>, <1,2> }").find("increasing heights"),
            std::string::npos);
  EXPECT_NE(test::error_of("polygon { 3, <0,0,0>, <1,0,0>, <2,0,0> }").find("plane"), std::string::npos);
  EXPECT_NE(test::error_of("text { ttf \"nosuchfont.ttf\" \"A\" 1, 0 }").find("cannot find the font"),
            std::string::npos);
  EXPECT_NE(test::error_of("lathe { 1e9, <0,0> }").find("points"), std::string::npos);
  EXPECT_EQ(test::error_of("polygon { 3, <0,0,0>, <1,0,0>, <0,1,0> }"), "");
}

}  // namespace
}  // namespace snell::sdl
