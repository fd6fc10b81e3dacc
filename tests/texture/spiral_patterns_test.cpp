// spiral1, spiral2, quilted, wrinkles, dents, ripples and waves: ranges and periodicity from their
// definitions (POV-Ray 3.7 reference, "Patterns").
#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/pcg32.hpp"
#include "snell/texture/noise_patterns.hpp"
#include "snell/texture/ripple_patterns.hpp"
#include "snell/texture/spiral_patterns.hpp"

using namespace snell::texture;
using snell::math::Vec3;

TEST(Spiral1PatternTest, RisesByOneAlongZAndByArmsOverOneTurn) {
  const Spiral1Pattern spiral(3);
  const Vec3 p{0.6, -0.2, 0.1};
  EXPECT_NEAR(spiral.value(p + Vec3{0, 0, 1}), spiral.value(p) + 1, 1e-12);
  // On the -y axis the angle is 0, on +x a quarter turn (3 arms: 3/4 more), radius 1 both.
  EXPECT_NEAR(spiral.value({0, -1, 0}), 1.0, 1e-12);
  EXPECT_NEAR(spiral.value({1, 0, 0}), 1.0 + 0.75, 1e-12);
}

TEST(Spiral2PatternTest, PeriodicAlongZAndWithinZeroToTwo) {
  const Spiral2Pattern spiral(2);
  snell::math::Pcg32 rng(5);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p{rng.next_double() * 4 - 2, rng.next_double() * 4 - 2, rng.next_double() * 4 - 2};
    const double v = spiral.value(p);
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 2.0);
    EXPECT_NEAR(spiral.value(p + Vec3{0, 0, 1}), v, 1e-9);
  }
}

TEST(QuiltedPatternTest, PeriodOneZeroAtCubeCentresAndBounded) {
  const QuiltedPattern quilted;  // control0 = control1 = 1
  EXPECT_NEAR(quilted.value({0.5, 0.5, 0.5}), 0.0, 1e-12);
  const Vec3 p{0.2, 0.9, 0.35};
  EXPECT_NEAR(quilted.value(p + Vec3{3, -2, 1}), quilted.value(p), 1e-12);
  // At a cube corner the offset is (0.5,0.5,0.5), t = sqrt(0.75): curve = t^3 + 3t(1-t)^2 + 3t^2(1-t).
  const double t = std::sqrt(0.75);
  const double curve = t * t * t + 3 * t * (1 - t) * (1 - t) + 3 * t * t * (1 - t);
  EXPECT_NEAR(quilted.value({0, 0, 0}), 0.5 * curve, 1e-12);
}

TEST(NoiseValuePatternsTest, WrinklesDentsRipplesWavesInRange) {
  const WrinklesPattern wrinkles;
  const DentsPattern dents;
  const RipplesPattern ripples;
  const WavesPattern waves;
  snell::math::Pcg32 rng(9);
  double wrinkles_sum = 0;
  for (int i = 0; i < 500; ++i) {
    const Vec3 p{rng.next_double() * 10, rng.next_double() * 10, rng.next_double() * 10};
    const double w = wrinkles.value(p);
    EXPECT_GE(w, 0.0);
    EXPECT_LE(w, 1.0);  // sum of 10 octaves of [0,1] weighted 1, 1/2, ... halved: below 1
    wrinkles_sum += w;
    EXPECT_GE(dents.value(p), 0.0);
    EXPECT_LE(dents.value(p), 1.0);
    EXPECT_GE(ripples.value(p), 0.0);
    EXPECT_LE(ripples.value(p), 1.0);
  }
  EXPECT_NEAR(wrinkles_sum / 500, 0.5, 0.1);  // noise centred on 0.5 through weights summing to ~2, halved
  // Ripples: every centre at the same distance gives the same phase; far away the rings have period
  // 1/frequency along any ray, so the value at p and p moved by one wavelength agree closely.
  const RipplesPattern dense(1, 0);
  const Vec3 far{1000, 0, 0};
  EXPECT_NEAR(dense.value(far), dense.value(far + Vec3{1, 0, 0}), 0.02);
}

TEST(NoiseValuePatternsTest, RipplesMatchPovRay) {
  // POV-Ray 3.7.0: #debug str(F(x, y, z).red, 0, 12) with
  // F = function { pigment { ripples color_map {[0 rgb 0][1 rgb 1]} } } (single-precision colours).
  const RipplesPattern ripples;
  EXPECT_NEAR(ripples.value({0.3, 0.7, 1.1}), 0.704303383827, 1e-7);
  EXPECT_NEAR(ripples.value({1.5, -2.25, 0.125}), 0.550564885139, 1e-7);
}
