// Splines, trace, extents, string functions, #break, by-reference macro arguments and animation values.
// Expected numbers are worked by hand from POV-Ray 3.7's documented semantics.
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"
#include "snell/geometry/sphere.hpp"

namespace snell::sdl {
namespace {

math::Vec3 center_of(const std::string& declarations, const std::string& center,
                     const ParseOptions& base = {}) {
  ParseOptions options = base;
  options.library_paths.push_back(POVRAY_INCLUDE_DIR);
  options.message_sink = [](const std::string&) {};
  const auto scene = parse_scene_string(declarations + "\nsphere { " + center + ", 1 }", "test.pov", options);
  return dynamic_cast<const geometry::Sphere*>(scene.objects.at(0)->shape.get())->center();
}

double value_of(const std::string& declarations, const std::string& expression,
                const ParseOptions& base = {}) {
  return center_of(declarations, "<" + expression + ", 0, 0>", base).x;
}

/// The #debug output of a scene.
std::string debug_of(const std::string& text) {
  std::vector<std::string> messages;
  test::parse(text, &messages);
  std::string all;
  for (const auto& m : messages) all += m;
  return all;
}

void expect_near(const math::Vec3& a, const math::Vec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(a.z, b.z, 1e-9);
}

TEST(SdlSplines, LinearInterpolatesAndHoldsItsEnds) {
  const std::string s = "#declare S = spline { linear_spline 0, <0,0,0> 1, <2,4,6> }";
  expect_near(center_of(s, "S(0.25)"), {0.5, 1, 1.5});
  expect_near(center_of(s, "S(-1)"), {0, 0, 0});
  expect_near(center_of(s, "S(2)"), {2, 4, 6});
}

TEST(SdlSplines, QuadraticFitsAParabolaThroughThreePoints) {
  // Points of y = t^2: the parabola is exact on both segments.
  const std::string s = "#declare S = spline { quadratic_spline 0, 0, 1, 1, 2, 4 }";
  EXPECT_NEAR(value_of(s, "S(1.5).x"), 2.25, 1e-12);
  EXPECT_NEAR(value_of(s, "S(0.5).x"), 0.25, 1e-12);
}

TEST(SdlSplines, CubicIsCatmullRomBetweenTheInnerPoints) {
  // Catmull-Rom reproduces a quadratic on evenly spaced points; before the second point it holds it.
  const std::string s = "#declare S = spline { cubic_spline 0, 0, 1, 1, 2, 4, 3, 9 }";
  EXPECT_NEAR(value_of(s, "S(1.5).x"), 2.25, 1e-12);
  EXPECT_NEAR(value_of(s, "S(0.5).x"), 1, 1e-12);
  EXPECT_NEAR(value_of(s, "S(1.5, linear_spline).x"), 2.5, 1e-12);
}

TEST(SdlSplines, FloatValuesBecomeTwoVectorsAsInPovRay) {
  // POV-Ray promotes a float spline value v to <v, v>: `F(t).y` is valid and equals `F(t).x`.
  EXPECT_DOUBLE_EQ(value_of("#declare F = spline { 0, 1, 1, 3 }", "F(0.5).x + F(0.5).y * 10"), 22);
}

TEST(SdlSplines, NaturalHasZeroCurvatureAtItsEnds) {
  // Through (0,0) (1,1) (2,0): S = 1.5 t - 0.5 t^3 on [0,1], so S(0.5) = 0.6875.
  const std::string s = "#declare S = spline { natural_spline 0, 0, 1, 1, 2, 0 }";
  EXPECT_NEAR(value_of(s, "S(0.5).x"), 0.6875, 1e-12);
  EXPECT_NEAR(value_of(s, "S(1.5).x"), 0.6875, 1e-12);
}

TEST(SdlSplines, PassedToAMacroAndCopied) {
  const std::string s =
      "#declare S = spline { 0, <0,0,0> 10, <10,0,0> }\n#declare T = spline { S }\n"
      "#macro At(Sp, Time) Sp(Time) #end";
  expect_near(center_of(s, "At(T, 3)"), {3, 0, 0});
}

TEST(SdlObjectQueries, TraceFindsTheNearestSurfaceAndItsNormal) {
  const std::string s =
      "#declare Ball = sphere { 0, 1 translate x }\n#declare N = <9, 9, 9>;\n"
      "#declare P = trace(Ball, <1, 0, -5>, z, N);";
  expect_near(center_of(s, "P"), {1, 0, -1});
  expect_near(center_of(s, "N"), {0, 0, -1});
  // A miss gives <0,0,0> and a zero normal.
  const std::string miss = "#declare N = x;\n#declare P = trace(sphere { 0, 1 }, <5, 5, -5>, z, N);";
  expect_near(center_of(miss, "P + N"), {0, 0, 0});
}

TEST(SdlObjectQueries, ExtentsOfATransformedBox) {
  const std::string s = "#declare B = box { <-1, -2, -3>, <1, 2, 3> translate x }";
  expect_near(center_of(s, "min_extent(B)"), {0, -2, -3});
  expect_near(center_of(s, "max_extent(B)"), {2, 2, 3});
  expect_near(center_of("", "max_extent(union { sphere { 0, 1 } sphere { 5*y, 2 } })"), {2, 7, 2});
}

TEST(SdlStrings, FormattingAndComparison) {
  EXPECT_EQ(debug_of("#debug vstr(3, <1, 2, 3>, \", \", 0, 1)"), "1.0, 2.0, 3.0");
  EXPECT_EQ(debug_of("#debug vstr(2, 5, \"/\", -4, 0)"), "0005/0005");
  EXPECT_EQ(debug_of("#debug str(3.14159, 0, 2)"), "3.14");
  EXPECT_EQ(debug_of("#debug datetime(0, \"%Y-%m-%d\")"), "2000-01-01");
  EXPECT_EQ(debug_of("#debug concat(strupr(\"ab\"), chr(65), substr(\"hello\", 2, 3))"), "ABAell");
  EXPECT_DOUBLE_EQ(value_of("", "strcmp(\"a\", \"b\") * 10 + strcmp(\"b\", \"b\") + strlen(\"abc\")"), -7);
  EXPECT_DOUBLE_EQ(value_of("", "file_exists(\"colors.inc\") + file_exists(\"no such file.inc\")"), 1);
}

TEST(SdlDirectives, BreakLeavesTheInnermostLoop) {
  const std::string s =
      "#declare N = 0;\n#while (1)\n  #declare N = N + 1;\n  #if (N = 5) #break #end\n#end\n"
      "#declare M = 0;\n#for (I, 1, 100)\n  #switch (I) #case (3) #break #end\n  #if (I = 4) #break #end\n"
      "  #declare M = M + I;\n#end";
  EXPECT_DOUBLE_EQ(value_of(s, "N"), 5);
  EXPECT_DOUBLE_EQ(value_of(s, "M"), 1 + 2 + 3);
  EXPECT_NE(test::error_of("#break").find("#break outside"), std::string::npos);
}

TEST(SdlMacros, LoneIdentifierArgumentsArePassedByReference) {
  const std::string s =
      "#macro Inc(A) #declare A = A + 1; #end\n#declare N = 1;\nInc(N)\nInc(N)\n"
      "#declare K = 1;\nInc(K + 0)";
  EXPECT_DOUBLE_EQ(value_of(s, "N"), 3);
  EXPECT_DOUBLE_EQ(value_of(s, "K"), 1);  // an expression is passed by value
}

TEST(SdlAnimation, ClockValuesComeFromTheOptions) {
  ParseOptions o;
  o.initial_frame = 1;
  o.final_frame = 5;
  o.initial_clock = 0;
  o.final_clock = 2;
  o.frame_number = 3;
  o.clock = 1;
  o.clock_on = true;
  EXPECT_DOUBLE_EQ(value_of("", "clock_delta", o), 0.5);
  EXPECT_DOUBLE_EQ(value_of("", "clock_on + frame_number * 10 + final_frame * 100", o), 531);
  EXPECT_DOUBLE_EQ(value_of("", "initial_clock + final_clock * 10 + initial_frame * 100", o), 120);
  EXPECT_DOUBLE_EQ(value_of("", "clock_on + clock_delta"), 1);  // a still: no animation, delta 1
}

TEST(SdlExpressions, VectorMayEndWithAComma) {
  expect_near(center_of("", "<1, 2, 3,>"), {1, 2, 3});
}

}  // namespace
}  // namespace snell::sdl

namespace snell::sdl {
namespace {

TEST(SdlLeniency, OptionalCommasAsPovRayAccepts) {
  // Macro parameters without a comma or with a trailing one (shapes3.inc), array items across lines
  // without commas (tiling.pov), vectors side by side (grenadine's lemon.inc), a stray '#'.
  const std::string s =
      "#macro Sum(A B, C,) A + B + C #end\n"
      "#declare Arr = array[4] { <1, 2> <3, 4>, 5\n 6 #\n }";
  EXPECT_DOUBLE_EQ(value_of(s, "Sum(1, 2, 3) + Arr[0].y + Arr[1].x + Arr[3]"), 6 + 2 + 3 + 6);
  EXPECT_NE(test::error_of("#declare Arr = array[3] { 1, 2 }").find("has 2 elements here, expected 3"),
            std::string::npos);
}

TEST(SdlLeniency, LightSourceStartsFromADeclaredLight) {
  const auto scene =
      test::parse("#declare L = light_source { <1, 2, 3> rgb 0.5 }\nlight_source { L translate x }");
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].position, math::Vec3(2, 2, 3));
  EXPECT_EQ(scene.lights[0].color, math::Color(0.5));
}

}  // namespace
}  // namespace snell::sdl

namespace snell::sdl {
namespace {

TEST(SdlLimits, HostileStringArgumentsGiveErrorsNotCrashes) {
  EXPECT_NE(test::error_of("#debug chr(1e300)").find("character code"), std::string::npos);
  EXPECT_NE(test::error_of("#debug datetime(1e300)").find("datetime needs"), std::string::npos);
  EXPECT_NE(test::error_of("#debug substr(\"abc\", 1e10, 1e10)").find("reaches outside"), std::string::npos);
  EXPECT_EQ(test::error_of("#debug str(1e300, 1e20, 1e20)"), "");
  EXPECT_NE(test::error_of("#declare S = \"xxxxxxxxxxxxxxxx\";\n#while (1) #declare S = concat(S, S); #end")
                .find("string longer than"),
            std::string::npos);
}

TEST(SdlLimits, LoopIterationLimitIsAnError) {
  ParseOptions options;
  options.max_while_iterations = 1000;
  try {
    parse_scene_string("#declare I = 0;\n#while (I < 5000) #declare I = I + 1; #end", "loop.pov", options);
    FAIL() << "expected an error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("loop.pov:2:1: error: #while loop ran more than 1000"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace snell::sdl
