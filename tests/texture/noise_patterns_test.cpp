// Noise-based patterns: the parts of POV-Ray's definitions that do not depend on the noise itself.
#include <gtest/gtest.h>

#include <cmath>

#include "snell/texture/noise_patterns.hpp"

using namespace snell::texture;

TEST(MarblePatternTest, WithoutTurbulenceIsTheXCoordinate) {
  const MarblePattern marble(std::nullopt, NoiseChoice{});
  EXPECT_DOUBLE_EQ(marble.value({0.3, 7, -2}), 0.3);
}

TEST(WoodPatternTest, WithoutTurbulenceIsDistanceFromZAxis) {
  const WoodPattern wood(std::nullopt);
  EXPECT_DOUBLE_EQ(wood.value({3, 4, 100}), 5.0);
}

TEST(AgatePatternTest, StaysInUnitRange) {
  const AgatePattern agate(TurbulenceParams{}, 1.0, NoiseChoice{});
  for (int i = 0; i < 100; ++i) {
    const double v = agate.value({i * 0.13, -i * 0.07, i * 0.29});
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
}

TEST(GranitePatternTest, MatchesPovRayAndBoundedByOctaveSum) {
  // POV-Ray 3.7.0: #debug str(F(x, y, z).red, 0, 12) with
  // F = function { pigment { granite color_map {[0 rgb 0][1 rgb 1]} } } (single-precision colours).
  const GranitePattern granite;
  EXPECT_NEAR(granite.value({0.3, 0.7, 1.1}), 0.244587063789, 1e-7);
  EXPECT_NEAR(granite.value({1, 2, -3}), 0.254131048918, 1e-7);
  for (int i = 0; i < 100; ++i) {
    const double v = granite.value({i * 0.031, i * 0.017, -i * 0.023});
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);  // 0.5 * (1 + 1/2 + ... + 1/32) < 1
  }
}
