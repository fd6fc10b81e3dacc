// The register form of compiled functions: the same values as the stack program describes, with
// constants folded, shared subexpressions computed once, compiled callees inlined, and several points
// evaluated at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "snell/function/builtins.hpp"
#include "snell/function/function.hpp"
#include "snell/function/internals.hpp"
#include "snell/function/register_code.hpp"

namespace snell::function {
namespace {

double cosine(double a) {
  return std::cos(a);
}

/// x * cos(y) + z * cos(y): two cosines of the same operand.
Program twisted() {
  ProgramBuilder b;
  b.parameter(0);
  b.parameter(1);
  b.unary(cosine);
  b.op(Op::multiply);
  b.parameter(2);
  b.parameter(1);
  b.unary(cosine);
  b.op(Op::multiply);
  b.op(Op::add);
  return b.finish();
}

TEST(RegisterCode, SharedSubexpressionsAreComputedOnce) {
  const RegisterCode code(twisted(), 3);
  // cos(y), x * cos(y), z * cos(y), their sum: the second cos(y) is the first one's register.
  EXPECT_EQ(code.instruction_count(), 4u);
  const double args[3] = {2, 0.5, 3};
  EXPECT_DOUBLE_EQ(code.run(args), 5 * std::cos(0.5));
}

TEST(RegisterCode, OperationsOnConstantsAreFolded) {
  ProgramBuilder b;  // (x + 2 * 3) - cos(0)
  b.parameter(0);
  b.constant(2);
  b.constant(3);
  b.op(Op::multiply);
  b.op(Op::add);
  b.constant(0);
  b.unary(cosine);
  b.op(Op::subtract);
  const RegisterCode code(b.finish(), 1);
  EXPECT_EQ(code.instruction_count(), 2u);  // (x + 6) - 1: the operations on x itself stay
  EXPECT_EQ(code.constant_count(), 2u);     // 6 and cos(0) = 1; 2, 3 and 0 are gone
  const double x = 10;
  EXPECT_DOUBLE_EQ(code.run(&x), 15);
}

TEST(RegisterCode, CompiledCalleesAreInlinedAndNativesCalledDirectly) {
  // inner(a, b) = f_sphere(a, b, 0, 1) * 2; outer(x, y) = inner(y, x) - inner(x, 0).
  ProgramBuilder ib;
  ib.parameter(0);
  ib.parameter(1);
  ib.constant(0);
  ib.constant(1);
  ib.call(internal_function(61), 4);
  ib.constant(2);
  ib.op(Op::multiply);
  const auto inner = Function::compiled({"a", "b"}, ib.finish());
  ProgramBuilder ob;
  ob.parameter(1);
  ob.parameter(0);
  ob.call(inner, 2);
  ob.parameter(0);
  ob.constant(0);
  ob.call(inner, 2);
  ob.op(Op::subtract);
  ASSERT_NE(inner->stack_program(), nullptr);
  const RegisterCode code(ob.finish(), 2);
  // Two sphere calls, two doublings, one subtraction; no call of `inner` is left.
  EXPECT_EQ(code.instruction_count(), 5u);
  const double args[2] = {3, 4};
  EXPECT_DOUBLE_EQ(code.run(args), 4);  // 2 (|(4, 3, 0)| - 1) - 2 (|(3, 0, 0)| - 1) = 8 - 4
  const double other[2] = {0, 2};       // 2 (|(2, 0, 0)| - 1) - 2 (|(0, 0, 0)| - 1) = 2 + 2
  EXPECT_DOUBLE_EQ(code.run(other), 4);
}

TEST(RegisterCode, LanesGiveEachPointsValueBitForBit) {
  const auto f = Function::compiled({"x", "y", "z"}, twisted());
  std::vector<double> xs, ys, zs;
  for (int l = 0; l < 8; ++l) {
    xs.push_back(0.3 * l - 1), ys.push_back(0.7 * l), zs.push_back(2 - 0.1 * l * l);
  }
  const double* const args[3] = {xs.data(), ys.data(), zs.data()};
  for (std::size_t lanes : {1u, 4u, 8u}) {
    double out[8];
    f->call_lanes(args, lanes, out);
    for (std::size_t l = 0; l < lanes; ++l) {
      const double point[3] = {xs[l], ys[l], zs[l]};
      EXPECT_EQ(out[l], f->call(point)) << "lane " << l;
      EXPECT_DOUBLE_EQ(out[l], (xs[l] + zs[l]) * std::cos(ys[l]));
    }
  }
  // A native function goes lane by lane through the same entry point.
  const auto noise = internal_function(76);
  double out[2];
  noise->call_lanes(args, 2, out);
  const double p1[3] = {xs[1], ys[1], zs[1]};
  EXPECT_EQ(out[1], noise->call(p1));
}

const Builtin& builtin(std::string_view name) {
  for (const Builtin& b : builtins())
    if (name == b.name) return b;
  throw std::invalid_argument("no built-in " + std::string(name));
}

TEST(RegisterCode, LaneKernelsAgreeWithScalarCalls) {
  // sqrt(x*x + z*z) - 0.9 + sin(12 * atan2(x, z)) * cos(y) * 0.1: every instruction on whole registers.
  ProgramBuilder b;
  b.parameter(0);
  b.unary(builtin("sqr").unary);
  b.parameter(2);
  b.unary(builtin("sqr").unary);
  b.op(Op::add);
  b.unary(builtin("sqrt").unary);
  b.constant(0.9);
  b.op(Op::subtract);
  b.constant(12);
  b.parameter(0);
  b.parameter(2);
  b.binary(builtin("atan2").binary);
  b.op(Op::multiply);
  b.unary(builtin("sin").unary);
  b.parameter(1);
  b.unary(builtin("cos").unary);
  b.op(Op::multiply);
  b.constant(0.1);
  b.op(Op::multiply);
  b.op(Op::add);
  const auto f = Function::compiled({"x", "y", "z"}, b.finish());
  EXPECT_TRUE(f->vectorised());
  EXPECT_FALSE(Function::compiled({"x", "y", "z"}, twisted())->vectorised());  // cosine is no built-in
  for (int k = 0; k < 200; ++k) {
    double xs[8], ys[8], zs[8], out[8];
    for (int l = 0; l < 8; ++l)
      xs[l] = std::sin(k + 0.37 * l) * 3, ys[l] = 0.01 * k * l - 2, zs[l] = std::cos(1.7 * k - l) * 2;
    const double* const args[3] = {xs, ys, zs};
    const std::size_t lanes = 1 + k % 8;
    f->call_lanes(args, lanes, out);
    for (std::size_t l = 0; l < lanes; ++l) {
      const double point[3] = {xs[l], ys[l], zs[l]};
      const double want = std::sqrt(xs[l] * xs[l] + zs[l] * zs[l]) - 0.9 +
                          std::sin(12 * std::atan2(xs[l], zs[l])) * std::cos(ys[l]) * 0.1;
      EXPECT_NEAR(out[l], f->call(point), 1e-14) << "lane " << l;
      EXPECT_NEAR(out[l], want, 1e-14);
    }
  }
}

/// Arguments for a native at 8 points: x, y, z spread over [-2, 2], the extra parameters as given.
struct NativeLanes {
  std::vector<std::vector<double>> columns;
  std::vector<const double*> pointers;
  NativeLanes(int seed, const std::vector<double>& extra) {
    for (int i = 0; i < 3; ++i) {
      columns.emplace_back();
      for (int l = 0; l < 8; ++l) columns.back().push_back(2 * std::sin(seed * 0.71 + l * 1.3 + i * 2.1));
    }
    for (double e : extra) columns.emplace_back(8, e);
    for (const auto& c : columns) pointers.push_back(c.data());
  }
  std::vector<double> point(int l) const {
    std::vector<double> p;
    for (const auto& c : columns) p.push_back(c[l]);
    return p;
  }
};

TEST(RegisterCode, NativesWithLaneEntriesGiveTheOnePointValues) {
  // Number, extra parameters; the angles (47 f_ph, 69 f_th) use the vector atan2, within 2 ulp of libm.
  const std::vector<std::pair<int, std::vector<double>>> natives = {
      {17, {1, 2, 0.5}}, {47, {}},  {57, {}},        {60, {0.15, 0.7, 1, 0.7}},
      {61, {1}},         {69, {}},  {70, {1, 0.35}}, {76, {}},
      {78, {1}},         {78, {2}}, {78, {3}}};
  for (const auto& [number, extra] : natives) {
    const auto f = internal_function(number);
    ASSERT_NE(f->lane_native_function(), nullptr) << f->name();
    EXPECT_TRUE(f->vectorised()) << f->name();
    const bool angle = number == 47 || number == 69;
    for (int seed = 0; seed < 50; ++seed) {
      const NativeLanes lanes(seed, extra);
      for (std::size_t count : {3u, 8u}) {
        double out[8];
        f->call_lanes(lanes.pointers.data(), count, out);
        for (std::size_t l = 0; l < count; ++l) {
          const double one = f->call(lanes.point(static_cast<int>(l)).data());
          if (angle)
            EXPECT_NEAR(out[l], one, 1e-15 * std::max(1.0, std::fabs(one))) << f->name();
          else
            EXPECT_EQ(out[l], one) << f->name() << " lane " << l;
        }
      }
    }
  }
}

TEST(RegisterCode, FunctionsCallingLaneNativesRunOnWholeRegisters) {
  // f_torus(x, y, z, 1, 0.35) - f_noise3d(5x, 5y, 5z) * 0.2: both natives have lane entries.
  ProgramBuilder b;
  b.parameter(0);
  b.parameter(1);
  b.parameter(2);
  b.constant(1);
  b.constant(0.35);
  b.call(internal_function(70), 5);
  for (std::uint32_t i = 0; i < 3; ++i) {
    b.parameter(i);
    b.constant(5);
    b.op(Op::multiply);
  }
  b.call(internal_function(76), 3);
  b.constant(0.2);
  b.op(Op::multiply);
  b.op(Op::subtract);
  const auto f = Function::compiled({"x", "y", "z"}, b.finish());
  EXPECT_TRUE(f->vectorised());
  for (int seed = 0; seed < 100; ++seed) {
    const NativeLanes lanes(seed, {});
    const std::size_t count = 1 + seed % 8;
    double out[8];
    f->call_lanes(lanes.pointers.data(), count, out);
    for (std::size_t l = 0; l < count; ++l)
      EXPECT_EQ(out[l], f->call(lanes.point(static_cast<int>(l)).data())) << "lane " << l;
  }
  // A native without a lane entry still goes lane by lane.
  EXPECT_FALSE(internal_function(25)->vectorised());  // f_helix1
}

}  // namespace
}  // namespace snell::function
