// Expressions are checked through `#declare` and a sphere whose radius / centre carries the value.
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"
#include "snell/geometry/sphere.hpp"

namespace snell::sdl {
namespace {

double radius_of(const std::string& declarations, const std::string& radius_expression) {
  const auto scene = test::parse(declarations + "\nsphere { 0, " + radius_expression + " }");
  const auto* s = dynamic_cast<const geometry::Sphere*>(scene.objects.at(0)->shape.get());
  return s->radius();
}

math::Vec3 center_of(const std::string& text) {
  const auto scene = test::parse("sphere { " + text + ", 1 }");
  return dynamic_cast<const geometry::Sphere*>(scene.objects.at(0)->shape.get())->center();
}

TEST(SdlExpressions, ArithmeticPrecedenceAndUnary) {
  EXPECT_DOUBLE_EQ(radius_of("", "1 + 2 * 3"), 7);
  EXPECT_DOUBLE_EQ(radius_of("", "(1 + 2) * 3"), 9);
  EXPECT_DOUBLE_EQ(radius_of("", "-2 * -3 + .5"), 6.5);
  EXPECT_DOUBLE_EQ(radius_of("", "1e-3 * 1000"), 1);
  EXPECT_DOUBLE_EQ(radius_of("", "10 / 4 - 1"), 1.5);
}

TEST(SdlExpressions, ComparisonsLogicAndTernary) {
  EXPECT_DOUBLE_EQ(radius_of("", "(2 < 3) + (3 <= 3) + (4 = 4) + (4 != 4) + 1"), 4);
  EXPECT_DOUBLE_EQ(radius_of("", "(1 & 0) + (1 | 0) + !0 + 1"), 3);
  EXPECT_DOUBLE_EQ(radius_of("", "(2 > 1 ? 5 : 6)"), 5);
}

TEST(SdlExpressions, VectorsPromoteFloatsAndSelectComponents) {
  EXPECT_EQ(center_of("<1, 2, 3> * 2 + 1"), math::Vec3(3, 5, 7));
  EXPECT_EQ(center_of("x * 2 - z"), math::Vec3(2, 0, -1));
  EXPECT_EQ(center_of("3"), math::Vec3(3, 3, 3));
  EXPECT_DOUBLE_EQ(radius_of("#declare V = <4, 5, 6>;", "V.x + V.y + V.z"), 15);
  EXPECT_DOUBLE_EQ(
      radius_of("#declare C = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;", "C.red + C.filter + C.transmit"), 1.0);
  EXPECT_DOUBLE_EQ(radius_of("", "vlength(<3, 4, 0>)"), 5);
  EXPECT_DOUBLE_EQ(radius_of("", "vdot(<1, 2, 3>, <4, 5, 6>)"), 32);
  EXPECT_EQ(center_of("vcross(x, y)"), math::Vec3(0, 0, 1));
}

TEST(SdlExpressions, BuiltInFunctionsMatchTheirDefinitions) {
  EXPECT_NEAR(radius_of("", "sin(pi / 2) + cos(0)"), 2, 1e-15);
  EXPECT_DOUBLE_EQ(radius_of("", "pow(2, 10) / 1024 + sqrt(16)"), 5);
  EXPECT_DOUBLE_EQ(radius_of("", "abs(-3) + min(4, 2, 8) + max(1, 7)"), 12);
  EXPECT_DOUBLE_EQ(radius_of("", "floor(2.7) + ceil(2.2) + int(-2.7)"), 3);
  EXPECT_DOUBLE_EQ(radius_of("", "mod(7, 3) + div(7, 2)"), 4);
  EXPECT_NEAR(radius_of("", "degrees(radians(90))"), 90, 1e-12);
  EXPECT_NEAR(radius_of("", "atan2(1, 1) * 4"), M_PI, 1e-15);
  EXPECT_DOUBLE_EQ(radius_of("", "log(1000) + ln(exp(2))"), 5);
  EXPECT_DOUBLE_EQ(radius_of("", "select(-1, 2, 3) + select(1, 10, 20, 30)"), 32);
  EXPECT_DOUBLE_EQ(radius_of("", "strlen(concat(\"ab\", str(12.5, 0, 1)))"), 6);
}

TEST(SdlExpressions, BuiltInConstants) {
  EXPECT_DOUBLE_EQ(radius_of("", "true + on + yes + false + off + no"), 3);
  EXPECT_DOUBLE_EQ(radius_of("#version 3.6;", "version"), 3.6);
  EXPECT_DOUBLE_EQ(radius_of("", "image_width / image_height"), 320.0 / 240.0);
  EXPECT_DOUBLE_EQ(radius_of("", "clock + 1"), 1);
}

TEST(SdlExpressions, ColoursFromEverySyntax) {
  const auto scene = test::parse(R"(
    #include "colors.inc"
    sphere { 0, 1 pigment { color red 1 green 0.5 blue 0.25 filter 0.1 transmit 0.2 } }
    sphere { 0, 1 pigment { rgb 0.5 } }
    sphere { 0, 1 pigment { rgbf <1, 0.2, 0.2, 0.8> } }
    sphere { 0, 1 pigment { color rgbt <0.2, 0.3, 1, 0.6> } }
    sphere { 0, 1 pigment { color rgb <1, 1, 1> * 0.02 } }
    sphere { 0, 1 pigment { color Red * 0.5 + Blue } }
    sphere { 0, 1 pigment { White } }
  )");
  ASSERT_EQ(scene.objects.size(), 7u);
  EXPECT_EQ(test::solid_color(*scene.objects[0]), (material::Rgbft{{1, 0.5, 0.25}, 0.1, 0.2}));
  EXPECT_EQ(test::solid_color(*scene.objects[1]), (material::Rgbft{{0.5, 0.5, 0.5}, 0, 0}));
  EXPECT_EQ(test::solid_color(*scene.objects[2]), (material::Rgbft{{1, 0.2, 0.2}, 0.8, 0}));
  EXPECT_EQ(test::solid_color(*scene.objects[3]), (material::Rgbft{{0.2, 0.3, 1}, 0, 0.6}));
  EXPECT_EQ(test::solid_color(*scene.objects[4]).rgb, math::Color(0.02));
  EXPECT_EQ(test::solid_color(*scene.objects[5]).rgb, math::Color(0.5, 0, 1));
  EXPECT_EQ(test::solid_color(*scene.objects[6]).rgb, math::Color(1));
}

TEST(SdlExpressions, CommentsNestAndColourIsColor) {
  const auto scene =
      test::parse("/* outer /* inner */ still comment */ // line\nsphere { 0, 1 pigment { colour rgb 1 } }");
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(test::solid_color(*scene.objects[0]).rgb, math::Color(1));
}

}  // namespace
}  // namespace snell::sdl
