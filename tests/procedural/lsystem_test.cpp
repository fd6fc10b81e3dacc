// L-system rewriting and the turtle against ../shared/reference-values.md section 4 (string lengths and end
// points of the Koch curve, Koch snowflake and Mariano's bush; ABoP 1990 ch. 1) and hand-derived cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "snell/procedural/lsystem.hpp"
#include "snell/procedural/turtle.hpp"

namespace snell::procedural {
namespace {

ModuleString grow(const std::string& axiom, std::vector<LSystemRule> rules, int n, std::uint64_t seed = 0) {
  LSystemSettings s;
  s.axiom = axiom;
  s.rules = std::move(rules);
  s.iterations = n;
  s.seed = seed;
  return generate_lsystem(s);
}

std::size_t count_f(const ModuleString& m) {
  return static_cast<std::size_t>(std::ranges::count(m.symbols(), 'F'));
}

const LSystemRule kKoch{"F", "FLFRRFLF"};
const LSystemRule kBush{"F", "FF-[-F+F+F]+[+F-F-F]"};

TurtleSettings koch_turtle() {
  TurtleSettings t;
  t.angle_degrees = 60;
  t.aliases = {{'L', '+'}, {'R', '-'}};
  return t;
}

TEST(LSystem, KochLengthsAndStrings) {
  const std::size_t lengths[] = {1, 8, 36, 148, 596, 2388}, fs[] = {1, 4, 16, 64, 256, 1024};
  for (int n = 0; n <= 5; ++n) {
    const ModuleString m = grow("F", {kKoch}, n);
    EXPECT_EQ(m.size(), lengths[n]) << n;
    EXPECT_EQ(count_f(m), fs[n]) << n;
    EXPECT_EQ(m.size(), (7 * (std::size_t(1) << (2 * n)) - 4) / 3) << "closed form";
  }
  EXPECT_EQ(grow("F", {kKoch}, 1).symbols(), "FLFRRFLF");
  EXPECT_EQ(grow("F", {kKoch}, 2).symbols(), "FLFRRFLFLFLFRRFLFRRFLFRRFLFLFLFRRFLF");
}

TEST(LSystem, SnowflakeAndBushLengths) {
  const std::size_t snow[] = {7, 28, 112, 448, 1792}, snow_f[] = {3, 12, 48, 192, 768};
  for (int n = 0; n <= 4; ++n) {
    const ModuleString m = grow("FRRFRRF", {kKoch}, n);
    EXPECT_EQ(m.size(), snow[n]);
    EXPECT_EQ(count_f(m), snow_f[n]);
  }
  const std::size_t bush[] = {1, 20, 172, 1388, 11116, 88940}, bush_f[] = {1, 8, 64, 512, 4096, 32768};
  for (int n = 0; n <= 5; ++n) {
    const ModuleString m = grow("F", {kBush}, n);
    EXPECT_EQ(m.size(), bush[n]);
    EXPECT_EQ(count_f(m), bush_f[n]);
    EXPECT_EQ(grow("++++F", {kBush}, n).size(), bush[n] + 4);
  }
}

TEST(Turtle, KochCurveEndsAtThreeToTheNWithItsPeak) {
  for (int n = 0; n <= 5; ++n) {
    const TurtleResult r = interpret(grow("F", {kKoch}, n), koch_turtle());
    const double span = std::pow(3.0, n);
    EXPECT_NEAR(r.end.position.x, span, 1e-9 * span);
    EXPECT_NEAR(r.end.position.y, 0, 1e-9 * span);
    EXPECT_NEAR(r.end.heading.x, 1, 1e-12);
    if (n > 0) {  // n = 0 is a straight line
      EXPECT_NEAR(r.hi.y, span * std::sqrt(3.0) / 6, 1e-9 * span) << n;
    }
    EXPECT_EQ(r.segments.size(), std::size_t(1) << (2 * n));
  }
  EXPECT_NEAR(interpret(grow("F", {kKoch}, 1), koch_turtle()).hi.y, 0.866025404, 1e-9);
}

TEST(Turtle, SnowflakeCloses) {
  for (int n = 0; n <= 4; ++n) {
    const TurtleResult r = interpret(grow("FRRFRRF", {kKoch}, n), koch_turtle());
    EXPECT_NEAR(length(r.end.position), 0, 1e-9 * std::pow(3.0, n)) << n;
  }
}

TEST(Turtle, BushBracketsRestoreTheState) {
  TurtleSettings t;
  t.angle_degrees = 22.5;
  const TurtleResult r = interpret(grow("++++F", {kBush}, 1), t);
  EXPECT_NEAR(r.end.position.x, 0, 1e-12);
  EXPECT_NEAR(r.end.position.y, 2, 1e-12);
  EXPECT_NEAR(r.end.heading.y, 1, 1e-12);  // heading 90 degrees
  EXPECT_EQ(r.segments.size(), 8u);
}

TEST(Turtle, FractintAngleDivisionsAndTurnDirections) {
  TurtleSettings t;
  t.angle_degrees = 360.0 / 16;  // Fractint `angle 16` (bush) = 22.5 degrees
  const TurtleResult r = interpret(parse_modules("++++F"), t);
  EXPECT_NEAR(r.end.position.y, 1, 1e-12);
  // `+` turns H toward L, `&` pitches H away from U, `|` reverses H, `\`/`/` keep H.
  t.angle_degrees = 90;
  EXPECT_NEAR(interpret(parse_modules("+F"), t).end.position.y, 1, 1e-12);
  EXPECT_NEAR(interpret(parse_modules("-F"), t).end.position.y, -1, 1e-12);
  EXPECT_NEAR(interpret(parse_modules("&F"), t).end.position.z, -1, 1e-12);
  EXPECT_NEAR(interpret(parse_modules("^F"), t).end.position.z, 1, 1e-12);
  EXPECT_NEAR(interpret(parse_modules("|F"), t).end.position.x, -1, 1e-12);
  const TurtleResult rolled = interpret(parse_modules("\\+F"), t);  // roll, then turn toward the new L
  EXPECT_NEAR(rolled.end.position.x, 0, 1e-12);
  EXPECT_NEAR(std::abs(rolled.end.position.z), 1, 1e-12);
  // Every turtle frame stays orthonormal with H x L = U.
  const TurtleFrame e = interpret(parse_modules("+(17)&(23)\\(41)^(7)/(3)"), t).end;
  EXPECT_NEAR(length(cross(e.heading, e.left) - e.up), 0, 1e-12);
}

TEST(Turtle, WidthTaperAndCones) {
  TurtleSettings t;
  t.width = 1;
  t.taper = 0.5;
  // The trunk's first segment narrows to the second's width; the branch starts at half width.
  const TurtleResult r = interpret(parse_modules("F[+F]!F"), t);
  ASSERT_EQ(r.segments.size(), 3u);
  EXPECT_FLOAT_EQ(r.segments[0].r0, 0.5f);
  EXPECT_FLOAT_EQ(r.segments[0].r1, 0.25f);
  EXPECT_FLOAT_EQ(r.segments[1].r0, 0.25f);
  EXPECT_FLOAT_EQ(r.segments[2].r0, 0.25f);
  const TurtleResult set = interpret(parse_modules("!(0.2)F'F~"), t);
  EXPECT_FLOAT_EQ(set.segments[0].r0, 0.1f);
  EXPECT_EQ(set.segments[1].colour, 1);
  ASSERT_EQ(set.leaves.size(), 1u);
  EXPECT_NEAR(set.leaves[0].position.x, 2, 1e-12);
}

TEST(LSystem, ParametricRulesWithConditions) {
  // A(s) with s <= 4 grows F(s) and doubles: F(1) F(2) F(4) A(8), after which the condition fails.
  const ModuleString m = grow("A(1)", {{"A(s) : s <= 4", "F(s)A(s*2)"}}, 6);
  EXPECT_EQ(m.symbols(), "FFFA");
  EXPECT_EQ(m.parameters(3)[0], 8);
  EXPECT_NEAR(interpret(m, {}).end.position.x, 7, 1e-12);
  // ABoP 1.10's example shape: several parameters, arithmetic and a turn with its own angle.
  const ModuleString b = grow("B(2, 3)", {{"B(x,y) : x + y >= 5 && !(x > 2)", "+(x*45)F(y^2/9)"}}, 1);
  const TurtleResult r = interpret(b, {});
  EXPECT_NEAR(r.end.position.y, 1, 1e-12);  // turned 90 degrees, stepped 1
}

TEST(LSystem, StochasticRulesFollowTheirProbabilitiesAndTheSeed) {
  const std::vector<LSystemRule> rules{{"A", "B", 1}, {"A", "C", 3}};
  const std::string axiom(20000, 'A');
  const ModuleString m = grow(axiom, rules, 1, 7);
  const double share_b = static_cast<double>(std::ranges::count(m.symbols(), 'B')) / 20000;
  EXPECT_NEAR(share_b, 0.25, 0.015);  // 5 sigma of a binomial(20000, 0.25) share is 0.015
  EXPECT_EQ(grow(axiom, rules, 1, 7).symbols(), m.symbols());
  EXPECT_NE(grow(axiom, rules, 1, 8).symbols(), m.symbols());
}

TEST(LSystem, ExpressionsEvaluate) {
  const std::vector<std::string> names{"a", "b"};
  const double ab[] = {2, 3};
  EXPECT_DOUBLE_EQ(Expression("2 + 3 * 4 ^ 2", {}).evaluate({}), 50);
  EXPECT_DOUBLE_EQ(Expression("-2^2", {}).evaluate({}), -4);
  EXPECT_DOUBLE_EQ(Expression("(a + b) / 2 - max(a, b) * min(1, sqrt(4))", names).evaluate(ab), -0.5);
  EXPECT_DOUBLE_EQ(Expression("a < b && b <= 3 || 0", names).evaluate(ab), 1);
  EXPECT_DOUBLE_EQ(Expression("a == 3", names).evaluate(ab), 0);
  EXPECT_THROW(Expression("a + c", names), LSystemError);
  EXPECT_THROW(Expression("(a + 1", names), LSystemError);
  EXPECT_THROW(Expression("a +", names), LSystemError);
}

TEST(LSystem, ErrorsAndTheLengthLimit) {
  LSystemSettings s;
  s.axiom = "F";
  s.rules = {kBush};
  s.iterations = 12;  // would be 35 billion modules
  s.max_length = 1'000'000;
  try {
    generate_lsystem(s);
    FAIL() << "no error";
  } catch (const LSystemError& e) {
    EXPECT_NE(std::string(e.what()).find("max_length"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("iteration 7"), std::string::npos);
  }
  EXPECT_THROW(interpret(parse_modules("F]"), {}), LSystemError);
  // A string that stops growing still has bounded work, and parameters count against the limit too.
  s.axiom = std::string(1000, 'F');
  s.rules = {{"F", "F"}};
  s.iterations = 1000;
  s.max_length = 10000;
  EXPECT_THROW(generate_lsystem(s), LSystemError);
  s.axiom = "A";
  s.rules = {{"A", "AA(1,2,3,4,5,6,7,8,9,10)A"}};  // 10 parameters per added module
  s.iterations = 20;
  s.max_length = 100000;
  EXPECT_THROW(generate_lsystem(s), LSystemError);
  EXPECT_THROW(grow("F", {{"FG", "F"}}, 1), LSystemError);
  EXPECT_THROW(grow("F", {{"F", "F(1"}}, 1), LSystemError);
  EXPECT_THROW(grow("F", {{"F", "F", 0}}, 1), LSystemError);
}

}  // namespace
}  // namespace snell::procedural
