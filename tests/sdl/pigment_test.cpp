// Pattern pigments as parsed from scene text: checker defaults, colour and pigment maps in their forms,
// declared maps, transforms inside pigments, declared pigments with modifiers (POV-Ray 3.7 reference,
// "Pigment", "Color Maps", "Pigment Maps").
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"

using namespace snell;

namespace {

/// The colour of the only object's pigment at texture-space point p.
material::Rgbft color_at(const std::string& scene_text, const math::Vec3& p) {
  const scene::Scene s = sdl::test::parse(scene_text);
  const auto& objects = s.objects;
  EXPECT_EQ(objects.size(), 1u);
  material::PatternPoint point;
  point.p = objects.front()->texture->transform.inverse_point(p);
  return objects.front()->texture->pigment->at(point);
}

void expect_rgb(const material::Rgbft& c, double r, double g, double b) {
  EXPECT_NEAR(c.rgb.r, r, 1e-9);
  EXPECT_NEAR(c.rgb.g, g, 1e-9);
  EXPECT_NEAR(c.rgb.b, b, 1e-9);
}

}  // namespace

TEST(SdlPigment, CheckerDefaultsAreBlueAndGreen) {
  const std::string scene = "plane { y, 0 pigment { checker } }";
  expect_rgb(color_at(scene, {0.5, 0.5, 0.5}), 0, 0, 1);
  expect_rgb(color_at(scene, {1.5, 0.5, 0.5}), 0, 1, 0);
}

TEST(SdlPigment, CheckerWithOneColourKeepsTheSecondDefault) {
  const std::string scene = "plane { y, 0 pigment { checker color rgb <1, 0, 0> } }";
  expect_rgb(color_at(scene, {0.5, 0.5, 0.5}), 1, 0, 0);
  expect_rgb(color_at(scene, {1.5, 0.5, 0.5}), 0, 1, 0);
}

TEST(SdlPigment, SecondRgbKeywordStartsTheNextColour) {
  // POV-Ray's Parse_Colour ends a colour at an rgb keyword once it has begun (parser_expressions.cpp).
  const std::string scene = "plane { y, 0 pigment { checker rgb 1 rgb 0.5 } }";
  expect_rgb(color_at(scene, {0.5, 0.5, 0.5}), 1, 1, 1);
  expect_rgb(color_at(scene, {1.5, 0.5, 0.5}), 0.5, 0.5, 0.5);
}

TEST(SdlPigment, AverageIsTheWeightedMeanOfItsMap) {
  // POV-Ray reference, "Average": weights need not sum to 1; the result is the same at every point.
  const std::string scene =
      "plane { y, 0 pigment { average pigment_map { [1 rgb <1, 0, 0>] [3 pigment { checker rgb z rgb z }] } "
      "} }";
  expect_rgb(color_at(scene, {0.5, 0.5, 0.5}), 0.25, 0, 0.75);
  expect_rgb(color_at(scene, {7.5, -3.5, 2.5}), 0.25, 0, 0.75);
  EXPECT_NE(sdl::test::error_of("plane { y, 0 pigment { average } }").find("average needs a pigment_map"),
            std::string::npos);
}

TEST(SdlPigment, FunctionPatternEvaluatesTheUserFunction) {
  // POV-Ray reference, "Function Pattern": the value of f(x, y, z) through the colour map; the ramp wave
  // folds 1.25 to 0.25.
  const std::string scene =
      "plane { y, 0 pigment { function { x * 0.5 } color_map { [0 rgb 0] [1 rgb <1, 0, 1>] } } }";
  expect_rgb(color_at(scene, {0.5, 0, 0}), 0.25, 0, 0.25);
  EXPECT_NEAR(color_at(scene, {2.5, 0, 0}).rgb.r, 0.25, 2e-5);
  EXPECT_NE(sdl::test::error_of("plane { y, 0 pigment { function(a) { a } } }").find("three arguments"),
            std::string::npos);
}

TEST(SdlPigment, PigmentPatternUsesTheGreyValue) {
  // POV-Ray's PigmentPattern: greyscale 0.297 R + 0.589 G + 0.114 B (base/colour.h) through the colour map.
  const std::string scene =
      "plane { y, 0 pigment { pigment_pattern { checker rgb <1, 0, 0> rgb <0, 1, 0> } "
      "color_map { [0 rgb 0] [1 rgb 1] } } }";
  expect_rgb(color_at(scene, {0.5, 0.5, 0.5}), 0.297, 0.297, 0.297);
  expect_rgb(color_at(scene, {1.5, 0.5, 0.5}), 0.589, 0.589, 0.589);
}

TEST(SdlPigment, CheckerOfPigmentsAndScale) {
  const std::string scene = R"(
    plane { y, 0 pigment { checker pigment { rgb 1 }, pigment { gradient x } scale 2 } })";
  expect_rgb(color_at(scene, {1.5, 0.5, 0.5}), 1, 1, 1);  // still the first 2-unit cube
  // Second cube: the gradient is scaled with the checker, so x = 3 gives 3/2 -> 0.5 after folding.
  expect_rgb(color_at(scene, {3, 0.5, 0.5}), 0.5, 0.5, 0.5);
}

TEST(SdlPigment, ColorMapInterpolatesBetweenEntries) {
  const std::string scene = R"(
    sphere { 0, 1 pigment { gradient x color_map { [0 rgb 0] [0.5 color red 1] [1.0, rgb 1] } } })";
  expect_rgb(color_at(scene, {0.25, 0, 0}), 0.5, 0, 0);
  expect_rgb(color_at(scene, {0.75, 0, 0}), 1, 0.5, 0.5);
  expect_rgb(color_at(scene, {1.25, 0, 0}), 0.5, 0, 0);  // repeats every unit
}

TEST(SdlPigment, OldStyleColorMapBands) {
  const std::string scene = R"(
    sphere { 0, 1 pigment { gradient y colour_map { [0.0 0.5 color rgb <1,0,0> color rgb <0,0,1>]
                                                    [0.5, 1.0 color rgb <0,1,0> color rgb <0,1,0>] } } })";
  expect_rgb(color_at(scene, {0, 0.25, 0}), 0.5, 0, 0.5);
  expect_rgb(color_at(scene, {0, 0.75, 0}), 0, 1, 0);
}

TEST(SdlPigment, DeclaredColorMapAndWaveModifiers) {
  const std::string scene = R"(
    #declare M = color_map { [0 rgb 0] [1 rgb 1] }
    sphere { 0, 1 pigment { onion color_map { M } triangle_wave frequency 2 } })";
  // distance 0.125 -> 0.25 after frequency 2 -> triangle 0.5
  expect_rgb(color_at(scene, {0.125, 0, 0}), 0.5, 0.5, 0.5);
  expect_rgb(color_at(scene, {0.25, 0, 0}), 1, 1, 1);
}

TEST(SdlPigment, SpiralsDefaultToTheTriangleWave) {
  // POV-Ray's SpiralPattern folds with the triangle wave unless told otherwise. spiral1 3 at <1, 0, 0.1>:
  // z + r + 3 * angle / 2 pi with the angle pi / 2 from -y gives 1.85, folded by POV-Ray's period 1.00001
  // to 0.84999, triangle 0.30002 (the ramp would give 0.85).
  const std::string scene = R"(sphere { 0, 2 pigment { spiral1 3 color_map { [0 rgb 0] [1 rgb 1] } } })";
  const double v = 2 * (1 - std::fmod(1.85, 1.00001));
  expect_rgb(color_at(scene, {1, 0, 0.1}), v, v, v);
}

TEST(SdlPigment, PigmentMapBlendsSubPigments) {
  const std::string scene = R"(
    #declare P = pigment { rgb <0, 0, 1> }
    sphere { 0, 1 pigment { gradient x pigment_map { [0 P] [1 checker rgb 1, rgb 0] } } })";
  // x = 0.5 halfway; the checker cube at (0.5, 0.5, 0.5) is white.
  expect_rgb(color_at(scene, {0.5, 0.5, 0.5}), 0.5, 0.5, 1);
  expect_rgb(color_at(scene, {0.5, 1.5, 0.5}), 0, 0, 0.5);
}

TEST(SdlPigment, DeclaredPatternPigmentTakesModifiers) {
  const std::string scene = R"(
    #declare G = pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } }
    sphere { 0, 1 pigment { G scale 4 } })";
  expect_rgb(color_at(scene, {1, 0, 0}), 0.25, 0, 0);
}

TEST(SdlPigment, TexturePigmentPatternsAndTextureTransform) {
  const std::string scene = R"(
    #declare T = texture { pigment { spherical color_map { [0 rgb 0] [1 rgb 1] } } scale 2 }
    sphere { 0, 1 texture { T } })";
  expect_rgb(color_at(scene, {0, 0, 0}), 1, 1, 1);
  expect_rgb(color_at(scene, {1, 0, 0}), 0.5, 0.5, 0.5);
}

TEST(SdlPigment, HexagonAndBrickTakeTheirEntries) {
  expect_rgb(color_at("plane { y, 0 pigment { hexagon rgb 1, rgb 0.5, rgb 0 } }", {0, 0, 0}), 1, 1, 1);
  const std::string brick =
      "box { -1, 1 pigment { brick rgb 1, rgb <1, 0, 0> brick_size <2, 1, 2> mortar 0.2 } }";
  expect_rgb(color_at(brick, {1, 0.5, 1}), 1, 0, 0);
  expect_rgb(color_at(brick, {1, -0.15, 1}), 1, 1, 1);  // the mortar layer
}

TEST(SdlPigment, WarpTurbulenceMovesThePatternPoint) {
  const std::string plain = "sphere { 0, 1 pigment { gradient x } }";
  const std::string warped = "sphere { 0, 1 pigment { gradient x warp { turbulence 0.5 octaves 3 } } }";
  const math::Vec3 p{0.3, 0.41, 0.77};
  EXPECT_NEAR(color_at(plain, p).rgb.r, 0.3, 1e-9);
  EXPECT_GT(std::fabs(color_at(warped, p).rgb.r - 0.3), 1e-4);
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 pigment { onion warp { spin 0, 1 } } }").find("spin"),
            std::string::npos);
}

TEST(SdlPigment, BadPatternsAreClearErrors) {
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 pigment { tiling 6 } }").find("not supported"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 pigment { checker color_map { [0 rgb 0] } } }")
                .find("value pattern"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 pigment { gradient x color_map { } } }").find("no entries"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 pigment { onion mortar 1 } }").find("brick"),
            std::string::npos);
}
