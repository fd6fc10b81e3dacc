// mandel/julia exponents and shading types and the magnet fractals (texture/fractal_patterns.hpp) against
// values POV-Ray 3.7.0 itself printed: Debian 12 `povray`, an 8x8 render of a scene declaring
// F = function { pigment { PATTERN color_map {[0 rgb 0][1 rgb 1]} } } and printing
// `#debug str(F(x, y, 0).red, 0, 9)` (stored by POV-Ray in single precision, hence 1e-6).
#include <gtest/gtest.h>

#include <cmath>

#include "snell/texture/fractal_patterns.hpp"

using namespace snell::texture;
using snell::math::Vec3;

namespace {

const Vec3 kPoints[6] = {{0.3, 0.7, 0},   {-1.2, 0.4, 0}, {1.5, -0.8, 0},
                         {0.05, 0.95, 0}, {2.3, 1.1, 0},  {-0.4, -0.3, 0}};

FractalShading iterations(int n) {
  FractalShading s;
  s.max_iterations = n;
  return s;
}

/// POV-Ray's colour map sees values above 1 through its default ramp wave (the fractional part), so the
/// raw values are compared that way. The modulus types (exterior 4 and 6 after z^4, z^5) magnify rounding
/// differences in the power over the iterations: there POV-Ray agrees to about 1e-5 only.
void expect_values(const ValuePattern& pattern, const double (&expected)[6], const char* name,
                   double tolerance = 1e-6) {
  for (int i = 0; i < 6; ++i) {
    const double v = pattern.value(kPoints[i]);
    EXPECT_NEAR(v > 1 ? v - std::floor(v) : v, expected[i], tolerance) << name << " at point " << i;
  }
}

}  // namespace

TEST(MagnetPatternTest, MandelFormsMatchPovRay) {
  // magnet 1 mandel 30 and magnet 2 mandel 30.
  MagnetParams one;
  one.type = 1;
  const double one_expected[6] = {1, 0.100000001, 1, 1, 0.366666675, 0.233333334};
  expect_values(MagnetPattern(one, iterations(30)), one_expected, "magnet 1 mandel");
  MagnetParams two;
  two.type = 2;
  const double two_expected[6] = {1, 0.033333335, 0.033333335, 1, 0.100000001, 0.100000001};
  expect_values(MagnetPattern(two, iterations(30)), two_expected, "magnet 2 mandel");
}

TEST(MagnetPatternTest, JuliaFormWithInteriorType1MatchesPovRay) {
  // magnet 2 julia <1.2, -0.3>, 30 interior 1, 0.1.
  MagnetParams p;
  p.type = 2;
  p.julia = true;
  p.c_real = 1.2;
  p.c_imaginary = -0.3;
  FractalShading s = iterations(30);
  s.interior_type = 1;
  s.interior_factor = 0.1;
  const double expected[6] = {0.009478340, 0.015161817, 0.066666670, 0.005487383, 0.100000001, 0.008606256};
  expect_values(MagnetPattern(p, s), expected, "magnet 2 julia");
}

TEST(FractalPatternTest, MandelExponentsMatchPovRay) {
  // mandel 40 exponent 3 (default shading), and mandel 40 exponent 5 exterior 6, 0.1 (the modulus).
  FractalShading cubic = iterations(40);
  cubic.exponent = 3;
  const double cubic_expected[6] = {1, 0, 0, 1, 0, 1};
  expect_values(MandelPattern(cubic), cubic_expected, "mandel exponent 3");
  FractalShading fifth = iterations(40);
  fifth.exponent = 5;
  fifth.exterior_type = 6;
  fifth.exterior_factor = 0.1;
  const double fifth_expected[6] = {0.771622539, 0.379203379, 0.364463985, 0.584629118, 0.720423639, 1};
  expect_values(MandelPattern(fifth), fifth_expected, "mandel exponent 5", 1e-4);
}

TEST(FractalPatternTest, JuliaExponentAndBandedExteriorMatchPovRay) {
  // julia <0.3, 0.5>, 40 exponent 4 exterior 4, 0.05 and julia <-0.7, 0.27>, 50 exterior 7, 10.
  FractalShading quartic = iterations(40);
  quartic.exponent = 4;
  quartic.exterior_type = 4;
  quartic.exterior_factor = 0.05;
  const double quartic_expected[6] = {1, 0.051694114, 0.411242515, 0.049380984, 0.747325599, 1};
  expect_values(JuliaPattern(0.3, 0.5, quartic), quartic_expected, "julia exponent 4", 1e-4);
  FractalShading banded = iterations(50);
  banded.exterior_type = 7;
  banded.exterior_factor = 10;
  const double banded_expected[6] = {0.2, 0.3, 0, 0.2, 0, 0.6};
  expect_values(JuliaPattern(-0.7, 0.27, banded), banded_expected, "julia exterior 7");
}

TEST(FractalPatternTest, ExteriorType1IgnoresItsFactorAsPovRayDoes) {
  FractalShading s = iterations(10);
  s.exterior_factor = 5;
  EXPECT_DOUBLE_EQ(fractal_exterior(s, 3, 0, 0), 0.3);
  // Interior type 6 is re^2 + im^2 * factor in POV-Ray 3.7.
  s.interior_type = 6;
  s.interior_factor = 2;
  EXPECT_DOUBLE_EQ(fractal_interior(s, 0.5, 0.5, 0), 0.25 + 0.5);
}
