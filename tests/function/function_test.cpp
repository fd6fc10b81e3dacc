// The function VM and POV-Ray's internal functions, against hand-computed values and the formulas that
// POV-Ray 3.7's functions.inc documents.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "snell/function/function.hpp"
#include "snell/function/internals.hpp"
#include "snell/math/constants.hpp"

namespace snell::function {
namespace {

double eval(const Function& f, std::vector<double> args) {
  return f(std::span<const double>(args));
}

TEST(FunctionVm, StackProgramEvaluatesPostfixCode) {
  // (a - 2 * b) / c with a = 10, b = 3, c = 2 -> 2.
  ProgramBuilder b;
  b.parameter(0);
  b.constant(2);
  b.parameter(1);
  b.op(Op::multiply);
  b.op(Op::subtract);
  b.parameter(2);
  b.op(Op::divide);
  const auto f = Function::compiled({"a", "b", "c"}, b.finish());
  EXPECT_DOUBLE_EQ(eval(*f, {10, 3, 2}), 2);
  EXPECT_DOUBLE_EQ(eval(*f, {0, -1, 4}), 0.5);
}

TEST(FunctionVm, ComparisonsAndLogicGiveZeroOrOne) {
  ProgramBuilder b;  // (x < y) | !(x = y)  with & binding its operands first
  b.parameter(0);
  b.parameter(1);
  b.op(Op::less);
  b.parameter(0);
  b.parameter(1);
  b.op(Op::equal);
  b.op(Op::logical_not);
  b.op(Op::logical_and);
  const auto f = Function::compiled({"x", "y"}, b.finish());
  EXPECT_EQ(eval(*f, {1, 2}), 1);
  EXPECT_EQ(eval(*f, {2, 2}), 0);
  EXPECT_EQ(eval(*f, {3, 2}), 0);
}

TEST(FunctionVm, CallsPassArgumentsInOrder) {
  ProgramBuilder inner;  // a - b
  inner.parameter(0);
  inner.parameter(1);
  inner.op(Op::subtract);
  const auto minus = Function::compiled({"a", "b"}, inner.finish());
  ProgramBuilder outer;  // minus(x * 10, sqrt(y))
  outer.parameter(0);
  outer.constant(10);
  outer.op(Op::multiply);
  outer.parameter(1);
  outer.unary([](double v) { return std::sqrt(v); });
  outer.call(minus, 2);
  const auto f = Function::compiled({"x", "y"}, outer.finish());
  EXPECT_DOUBLE_EQ(eval(*f, {2, 9}), 17);
}

TEST(FunctionVm, DeepProgramsUseAHeapStack) {
  // 1 + (1 + (1 + ...)): every constant stays on the stack until the adds at the end.
  ProgramBuilder b;
  for (int i = 0; i < 200; ++i) b.constant(1);
  for (int i = 0; i < 199; ++i) b.op(Op::add);
  const auto f = Function::compiled({}, b.finish());
  EXPECT_DOUBLE_EQ(eval(*f, {}), 200);
}

TEST(FunctionVm, WrongArgumentCountAndUnsupportedCallsThrow) {
  ProgramBuilder b;
  b.parameter(0);
  const auto f = Function::compiled({"x"}, b.finish());
  EXPECT_THROW(eval(*f, {1, 2}), FunctionError);
  const auto u = Function::unsupported("f_demo", 3, "f_demo is not implemented");
  EXPECT_FALSE(u->supported());
  EXPECT_THROW(eval(*u, {1, 2, 3}), FunctionError);
  ProgramBuilder empty;
  EXPECT_THROW(empty.finish(), FunctionError);
}

TEST(FunctionInternals, SphereTorusAndRadiusFollowTheirFormulas) {
  const auto sphere = internal_function(61);
  EXPECT_EQ(sphere->name(), "f_sphere");
  EXPECT_EQ(sphere->arity(), 4u);
  EXPECT_DOUBLE_EQ(eval(*sphere, {3, 4, 0, 1}), 4);   // |p| - r = 5 - 1
  EXPECT_DOUBLE_EQ(eval(*sphere, {0, 0, 0, 2}), -2);  // inside is negative
  const auto torus = internal_function(70);
  EXPECT_EQ(torus->arity(), 5u);
  // Major radius 2 in the x-z plane, minor 0.5: the point (2, 0.5, 0) lies on the tube.
  EXPECT_NEAR(eval(*torus, {2, 0.5, 0, 2, 0.5}), 0, 1e-15);
  EXPECT_DOUBLE_EQ(eval(*torus, {0, 0, 5, 2, 0.5}), 2.5);  // sqrt((5-2)^2) - 0.5
  EXPECT_DOUBLE_EQ(eval(*internal_function(57), {1, 2, 2}), 3);
}

TEST(FunctionInternals, AnglesThAndPh) {
  // f_th = atan2(x, z): azimuth around y from +z; f_ph = atan2(sqrt(x^2 + z^2), y): angle from +y.
  EXPECT_DOUBLE_EQ(eval(*internal_function(69), {1, 7, 0}), math::kPi / 2);
  EXPECT_DOUBLE_EQ(eval(*internal_function(69), {0, 0, -1}), math::kPi);
  EXPECT_DOUBLE_EQ(eval(*internal_function(47), {0, 1, 0}), 0);
  EXPECT_DOUBLE_EQ(eval(*internal_function(47), {3, 0, 4}), math::kPi / 2);
}

TEST(FunctionInternals, RoundedBox) {
  const auto box = internal_function(60);  // radius, then half sizes along x, y, z
  EXPECT_EQ(box->arity(), 7u);
  // On a face: distance 0 (less POV-Ray's 1e-6 offset).
  EXPECT_NEAR(eval(*box, {1, 0, 0, 0.1, 1, 1, 1}), -1e-6, 1e-12);
  // Outside a face by 0.5.
  EXPECT_NEAR(eval(*box, {1.5, 0, 0, 0.1, 1, 1, 1}), 0.5 - 1e-6, 1e-12);
  // Beyond the corner: the rounded corner is a sphere of radius 0.1 about (0.9, 0.9, 0.9).
  const double d = std::sqrt(3.0) * 0.1;  // from (1, 1, 1)
  EXPECT_NEAR(eval(*box, {1, 1, 1, 0.1, 1, 1, 1}), d - 0.1 - 1e-6, 1e-12);
}

TEST(FunctionInternals, EllipsoidAndSuperellipsoid) {
  // f_ellipsoid(x, y, z, a, b, c) = sqrt((a x)^2 + (b y)^2 + (c z)^2).
  EXPECT_DOUBLE_EQ(eval(*internal_function(17), {1, 2, 3, 3, 2, 0}), 5);
  // f_superellipsoid with e = n = 1 is a sphere: 1 - |p|.
  const auto se = internal_function(68);
  EXPECT_NEAR(eval(*se, {0.6, 0, 0.8, 1, 1}), 0, 1e-12);
  EXPECT_NEAR(eval(*se, {0, 0.5, 0, 1, 1}), 0.5, 1e-12);
  // e = n = 0.5 (rounder box): |x|^4 + |y|^4 + |z|^4 = 1 on the surface.
  const double c = std::pow(1.0 / 3, 0.25);
  EXPECT_NEAR(eval(*se, {c, c, c, 0.5, 0.5}), 0, 1e-12);
}

TEST(FunctionInternals, Noise3dStaysInZeroOne) {
  const auto noise = internal_function(76);
  // POV-Ray 3.7.0 prints 0.417469580551 for #debug str(f_noise3d(3, -2, 7), 0, 12).
  EXPECT_NEAR(eval(*noise, {3, -2, 7}), 0.417469580551, 1e-11);
  for (int i = 0; i < 100; ++i) {
    const double v = eval(*noise, {i * 0.37, i * 0.11, -i * 0.23});
    EXPECT_GE(v, 0);
    EXPECT_LE(v, 1);
  }
}

TEST(FunctionInternals, NoiseGeneratorPicksPovRaysVariant) {
  // POV-Ray 3.7.0's #debug str(f_noise_generator(0.3, 0.7, 1.1, G), 0, 12): G = 0 takes the original
  // generator's path (as G = 1 does), G = 3 is Perlin's noise.
  const auto noise = internal_function(78);
  EXPECT_NEAR(eval(*noise, {0.3, 0.7, 1.1, 0}), 0.855310987588, 1e-11);
  EXPECT_NEAR(eval(*noise, {0.3, 0.7, 1.1, 3}), 0.573302353883, 1e-11);
}

TEST(FunctionInternals, RidgedMultifractalUsesItsNoiseGenerator) {
  // POV-Ray 3.7.0.10's #debug str(f_ridged_mf(0.1, 0.2, 0.3, H, L, octaves, offset, gain, G), 0, 12), each
  // the first f_ridged_mf call of its scene: POV-Ray keeps the first call's frequency weights for all later
  // calls (fnintern.cpp caches them once), which snell does not copy.
  const auto ridged = internal_function(59);
  EXPECT_NEAR(eval(*ridged, {0.1, 0.2, 0.3, 0.07, 2.2, 7, 0.6, 0.9, 1}), 0.049560277353, 1e-11);
  EXPECT_NEAR(eval(*ridged, {0.1, 0.2, 0.3, 0.1, 3.1, 8, 0.7, 0.8, 2}), 0.342919513484, 1e-11);
}

TEST(FunctionInternals, RidgeAndHeteroMultifractalEqualPovRay) {
  // POV-Ray 3.7.0.10's #debug str(f(x, y, z, ...), 0, 15) with functions.inc, fractional octave counts
  // included (the last octave weighs its fraction).
  const auto ridge = internal_function(58), hetero = internal_function(29);
  EXPECT_NEAR(eval(*ridge, {0.3, -0.2, 0.5, 2.1, 4.5, 0.6, 0.3, 0.4, 2}), -0.160842377663678, 1e-13);
  EXPECT_NEAR(eval(*ridge, {12.5, 3.25, -7.75, 2, 3, 0.5, 0.7, 0.55, 1}), -0.067650493897843, 1e-13);
  EXPECT_NEAR(eval(*hetero, {1.71, 0.43, -2.26, 0.5, 2.2, 5.5, 0.3, 1, 2}), 0.246100236279077, 1e-13);
  EXPECT_NEAR(eval(*hetero, {12.5, 3.25, -7.75, 0.7, 2.0, 4, 0.1, 2, 3}), -0.182728968199747, 1e-13);
}

TEST(FunctionInternals, UnimplementedOnesDeclareButCallsNameThem) {
  const auto pattern = internal_function(77);
  EXPECT_EQ(pattern->arity(), 3u);  // x, y, z
  try {
    eval(*pattern, {0, 0, 0});
    FAIL() << "f_pattern evaluated";
  } catch (const FunctionError& e) {
    EXPECT_NE(std::string(e.what()).find("f_pattern"), std::string::npos) << e.what();
  }
  EXPECT_THROW(internal_function(79), FunctionError);
  EXPECT_THROW(internal_function(-1), FunctionError);
}

}  // namespace
}  // namespace snell::function
