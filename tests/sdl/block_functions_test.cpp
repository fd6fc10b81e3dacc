// Functions made from blocks (POV-Ray 3.7 reference, "Declaring User-Defined Color Functions" and
// "... Vector Functions"): pigment, pattern, spline and transform functions, their members inside
// compiled functions, `inside()`, the object pattern and average maps without weights.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"

using namespace snell;

namespace {

/// The solid colour of the only object, whose pigment the scene computes from expressions.
material::Rgbft only_color(const std::string& text) {
  const scene::Scene s = sdl::test::parse(text);
  EXPECT_EQ(s.objects.size(), 1u);
  return sdl::test::solid_color(*s.objects.front());
}

material::Rgbft pigment_at(const std::string& text, const math::Vec3& p) {
  const scene::Scene s = sdl::test::parse(text);
  material::PatternPoint point;
  point.p = s.objects.front()->texture->transform.inverse_point(p);
  return s.objects.front()->texture->pigment->at(point);
}

}  // namespace

TEST(BlockFunctions, PigmentFunctionGivesTheColourAndItsMembers) {
  const auto c = only_color(
      "#declare P = function { pigment { rgbft <0.2, 0.4, 0.6, 0.1, 0.3> } }\n"
      "#declare G = function { P(x, y, z).gray }\n"
      "#declare B = function { P(x, y, z).blue + P(x, y, z).transmit }\n"
      "#declare C = P(1, 2, 3);\n"
      "plane { y, 0 pigment { rgb <C.green, G(0, 0, 0), B(5, 5, 5)> } }");
  EXPECT_NEAR(c.rgb.r, 0.4, 1e-12);
  // POV-Ray's grey: 0.297 red + 0.589 green + 0.114 blue.
  EXPECT_NEAR(c.rgb.g, 0.297 * 0.2 + 0.589 * 0.4 + 0.114 * 0.6, 1e-12);
  EXPECT_NEAR(c.rgb.b, 0.9, 1e-12);
}

TEST(BlockFunctions, PatternFunctionReturnsThePatternValueWithItsModifiers) {
  const auto c = only_color(
      "#declare F = function { pattern { gradient x scale 2 } }\n"
      "#declare K = function { pattern { checker } }\n"
      "plane { y, 0 pigment { rgb <F(0.5, 0, 0), K(0.5, 0.5, 0.5), K(1.5, 0.5, 0.5)> } }");
  EXPECT_NEAR(c.rgb.r, 0.25, 1e-12);  // gradient x scaled by 2: x/2
  EXPECT_EQ(c.rgb.g, 0);
  EXPECT_EQ(c.rgb.b, 1);
}

TEST(BlockFunctions, SplineAndTransformFunctionsAreVectors) {
  const auto c = only_color(
      "#declare S = function { spline { linear_spline 0, <0, 0, 0> 1, <1, 2, 4> } }\n"
      "#declare T = function { transform { scale 2 translate <1, 0, 0> } }\n"
      "#declare V = T(0.5, 0.25, 0);\n"
      "#declare W = function { S(x).z }\n"
      "plane { y, 0 pigment { rgb <S(0.5).y, V.x, W(0.25, 0, 0)> } }");
  EXPECT_NEAR(c.rgb.r, 1.0, 1e-12);
  EXPECT_NEAR(c.rgb.g, 2.0, 1e-12);
  EXPECT_NEAR(c.rgb.b, 1.0, 1e-12);
}

TEST(BlockFunctions, InsideAsksTheObject) {
  const auto c = only_color(
      "#declare Ball = sphere { <1, 0, 0>, 1 }\n"
      "plane { y, 0 pigment { rgb <inside(Ball, <1.5, 0, 0>), inside(Ball, <-0.5, 0, 0>), 0> } }");
  EXPECT_EQ(c.rgb.r, 1);
  EXPECT_EQ(c.rgb.g, 0);
}

TEST(BlockFunctions, ObjectPatternIsTheFirstEntryOutsideAndTheSecondInside) {
  const std::string scene =
      "plane { y, 0 pigment { object { sphere { 0, 1 } rgb <1, 0, 0>, rgb <0, 0, 1> } } }";
  EXPECT_EQ(pigment_at(scene, {0, 0, 0}).rgb.b, 1);
  EXPECT_EQ(pigment_at(scene, {2, 0, 0}).rgb.r, 1);
}

TEST(BlockFunctions, AverageMapEntriesMayLeaveOutTheirWeight) {
  // POV-Ray 3.7 reads a missing weight in an average map as 1 (Parse_Blend_Map's Allow_Float(1.0)).
  const auto c =
      pigment_at("plane { y, 0 pigment { average pigment_map { [rgb 1] [3 rgb 0] } } }", {0, 0, 0});
  EXPECT_NEAR(c.rgb.r, 0.25, 1e-12);
}
