// Julia fractal slices against cases with known answers: c = 0 under z <- z^2 is the unit ball (|z| < 1
// stays bounded, |z| > 1 escapes), whatever the algebra's product, as long as it keeps |z^2| = |z|^2.
#include "snell/geometry/julia_fractal.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/constants.hpp"

namespace snell::geometry {
namespace {

JuliaFractal::Settings unit_ball(int iterations) {
  JuliaFractal::Settings s;
  s.max_iteration = iterations;
  s.precision = 100;
  return s;
}

TEST(JuliaFractalTest, ZeroParameterQuaternionSetIsTheUnitBall) {
  const JuliaFractal j(unit_ball(30));
  EXPECT_TRUE(j.inside({0.5, 0.3, -0.2}));
  EXPECT_FALSE(j.inside({0.9, 0.5, 0}));
  LocalHit hit;
  ASSERT_TRUE(j.intersect({{0, 0, -5}, {0, 0, 1}, 0}, 1e-9, math::kInfinity, hit));
  // With finite iterations the set is slightly bigger than the ball: points just outside escape late.
  EXPECT_NEAR(hit.t, 4, 0.02);
  EXPECT_LT(normalize(hit.normal).z, -0.99);
}

TEST(JuliaFractalTest, SliceMovesTheCrossSection) {
  // Slicing the 4D unit ball at w = 0.8 leaves a ball of radius 0.6.
  JuliaFractal::Settings s = unit_ball(30);
  s.slice_distance = 0.8;
  const JuliaFractal j(s);
  EXPECT_TRUE(j.inside({0.55, 0, 0}));
  EXPECT_FALSE(j.inside({0.65, 0, 0}));
}

TEST(JuliaFractalTest, HypercomplexSquareKeepsTheRealLine) {
  // On the real axis both algebras reduce to real arithmetic: c = -1 keeps 0 bounded (0, -1, 0, ...)
  // and sends 1.7 away (1.7^2 - 1 = 1.89, then 2.57 > 2).
  JuliaFractal::Settings s;
  s.c = {-1, 0, 0, 0};
  s.algebra = JuliaFractal::Algebra::hypercomplex;
  const JuliaFractal j(s);
  EXPECT_TRUE(j.inside({0, 0, 0}));
  EXPECT_FALSE(j.inside({1.7, 0, 0}));
}

}  // namespace
}  // namespace snell::geometry
