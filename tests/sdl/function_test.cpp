// `function { }` in the scene language: compiled bodies, parameters, nested calls, calls from ordinary
// expressions, internal() and functions.inc / shapes.inc. Values are checked against hand computation
// (and, where noted, against POV-Ray 3.7 itself).
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"
#include "snell/geometry/sphere.hpp"
#include "snell/math/constants.hpp"

namespace snell::sdl {
namespace {

/// The value of `expression` after `declarations` (carried by a sphere centre's x, which may be any float).
double value_of(const std::string& declarations, const std::string& expression) {
  const auto scene = test::parse(declarations + "\nsphere { <" + expression + ", 0, 0>, 1 }");
  return dynamic_cast<const geometry::Sphere*>(scene.objects.at(0)->shape.get())->center().x;
}

TEST(SdlFunction, DefaultParametersAreXYZ) {
  const std::string f = "#declare F = function { x * 100 + y * 10 + z }";
  EXPECT_DOUBLE_EQ(value_of(f, "F(1, 2, 3)"), 123);
  EXPECT_DOUBLE_EQ(value_of(f, "F(-1, 0, 0.5) * 2"), -199);
}

TEST(SdlFunction, SceneConstantsAreConstantsInsideFunctions) {
  // gamma_showcase.pov divides by image_height inside a function; the defaults are 320 x 240.
  EXPECT_DOUBLE_EQ(value_of("#declare F = function { x / image_height + image_width }", "F(120, 0, 0)"),
                   320.5);
  EXPECT_DOUBLE_EQ(value_of("#declare F = function { tau / pi + true }", "F(0, 0, 0)"), 3);
}

TEST(SdlFunction, NamedParametersAndPrecedence) {
  // Checked with POV-Ray 3.7: m(10, 3) = 4; 1+2<4&0|1 = 1.
  EXPECT_DOUBLE_EQ(value_of("#declare M = function(a, b) { a - b * 2 }", "M(10, 3)"), 4);
  EXPECT_DOUBLE_EQ(value_of("#declare H = function { 1 + 2 < 4 & 0 | 1 }", "H(0, 0, 0)"), 1);
  EXPECT_DOUBLE_EQ(value_of("#declare G = function { -2 * 3 + (1 - 4) / 2 }", "G(0, 0, 0)"), -7.5);
  EXPECT_DOUBLE_EQ(value_of("#declare N = function(a) { !a + (a >= 2) + (a != 3) }", "N(2)"), 2);
}

TEST(SdlFunction, BuiltinsAndDeclaredConstants) {
  EXPECT_DOUBLE_EQ(value_of("#declare F = function { sqrt(x) + pow(y, 3) + abs(z) }", "F(16, 2, -1)"), 13);
  EXPECT_DOUBLE_EQ(value_of("#declare F = function { min(x, y, z) * 10 + max(x, y) }", "F(3, 1, 2)"), 13);
  EXPECT_DOUBLE_EQ(value_of("#declare F = function { select(x, 1, 2) + select(x, 10, 20, 30) }", "F(0,0,0)"),
                   22);
  EXPECT_DOUBLE_EQ(value_of("#declare F = function { select(x, 1, 2) + select(x, 10, 20, 30) }", "F(-1,0,0)"),
                   11);
  EXPECT_DOUBLE_EQ(value_of("#declare F = function { mod(x, 3) + floor(y) + int(z) }", "F(7, -0.5, -1.5)"),
                   -1);
  EXPECT_NEAR(
      value_of("#declare F = function { atan2(x, y) + cos(pi) + ln(exp(2)) + log(100) }", "F(1, 0, 0)"),
      math::kPi / 2 - 1 + 2 + 2, 1e-12);
  // A declared float is folded in at compile time: redeclaring it later does not change the function.
  EXPECT_DOUBLE_EQ(value_of("#declare K = 4; #declare F = function { K * x } #declare K = 5;", "F(2, 0, 0)"),
                   8);
  EXPECT_DOUBLE_EQ(value_of("#declare V = <1, 2, 3>; #declare F = function { V.z + x }", "F(1, 0, 0)"), 4);
}

TEST(SdlFunction, NestedCalls) {
  const std::string decls = R"(
    #declare Sq = function(a) { a * a }
    #declare Len2 = function { Sq(x) + Sq(y) + Sq(z) }
    #declare Shift = function(a, b, c) { Len2(a - 1, b, c + 1) }
  )";
  EXPECT_DOUBLE_EQ(value_of(decls, "Shift(1, 2, 1)"), 8);
  EXPECT_DOUBLE_EQ(value_of(decls, "Len2(1, 2, 2) + Sq(3)"), 18);
}

TEST(SdlFunction, InternalFunctionsThroughFunctionsInc) {
  const std::string inc = "#include \"functions.inc\"";
  EXPECT_DOUBLE_EQ(value_of(inc, "f_sphere(3, 4, 0, 1)"), 4);
  EXPECT_DOUBLE_EQ(value_of(inc, "f_torus(0, 0, 5, 2, 0.5)"), 2.5);
  EXPECT_DOUBLE_EQ(value_of(inc, "f_r(1, 2, 2)"), 3);
  // f_snoise3d = 2 * f_noise3d - 1 (a user function over an internal); POV-Ray 3.7.0 prints
  // -0.158019651342 for #debug str(f_snoise3d(1, 2, 3), 0, 12).
  EXPECT_NEAR(value_of(inc, "f_snoise3d(1, 2, 3)"), -0.158019651342, 1e-11);
  EXPECT_DOUBLE_EQ(value_of(inc + " #declare F = function { f_sphere(x, y, z, 2) }", "F(0, 0, 3)"), 1);
}

TEST(SdlFunction, FunctionsPassByNameToMacrosAndDeclares) {
  // math.inc's fn_Gradient takes a function by name: |grad(x^2 + y^2 + z^2)| = 2|p| (central differences
  // are exact for a quadratic, up to rounding).
  const std::string decls = R"(
    #include "math.inc"
    #declare Q = function { x * x + y * y + z * z }
    #declare G = fn_Gradient(Q)
    #declare Q2 = Q
  )";
  EXPECT_NEAR(value_of(decls, "G(1, 2, 2)"), 6, 1e-6);
  EXPECT_DOUBLE_EQ(value_of(decls, "Q2(1, 1, 1)"), 3);
}

TEST(SdlFunction, FunctionsIncAndShapesIncParse) {
  EXPECT_EQ(test::error_of("#include \"functions.inc\""), "");
  EXPECT_EQ(test::error_of("#include \"shapes.inc\""), "");
}

TEST(SdlFunction, ErrorsAreClear) {
  const std::string inc = "#include \"functions.inc\"\n";
  EXPECT_NE(test::error_of(inc + "#declare F = function { internal(77) } #declare A = F(0, 0, 0);")
                .find("f_pattern"),
            std::string::npos);
  // functions.inc's pattern functions (f_agate is `function { pattern { agate } }`) now evaluate.
  EXPECT_EQ(
      test::error_of(inc + "#declare A = f_agate(0.3, 0.2, 0.1);\n#if (A < 0 | A > 1) #error \"range\" #end"),
      "");
  EXPECT_NE(test::error_of(inc + "#declare A = f_sphere(0, 0, 0);").find("takes 4 argument"),
            std::string::npos);
  EXPECT_NE(test::error_of("#declare F = function { q + 1 }").find("unknown identifier 'q'"),
            std::string::npos);
  EXPECT_NE(test::error_of("#declare F = function(a) { a + 1 } #declare G = function { F(x, y) }")
                .find("takes 1 argument"),
            std::string::npos);
  EXPECT_NE(test::error_of("#declare F = function { internal(200) }").find("no such internal"),
            std::string::npos);
  EXPECT_NE(test::error_of("#declare F = function { x + }").find("error"), std::string::npos);
  EXPECT_NE(test::error_of("#declare F = function(a, a) { a }").find("twice"), std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
