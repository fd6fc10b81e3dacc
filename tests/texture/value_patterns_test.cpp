// Value patterns at points where POV-Ray's documented definitions (POV-Ray 3.7 reference, "Patterns")
// give the value by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "snell/texture/value_patterns.hpp"
#include "snell/texture/wave.hpp"

using namespace snell::texture;

namespace {
const WaveShaping kRamp;
}

TEST(GradientPatternTest, ValueOneStaysOneAndHigherValuesWrap) {
  // A point exactly on a band edge keeps the last map entry (POV-Ray folds with period 1.00001).
  const GradientPattern gradient({1, 0, 0});
  EXPECT_DOUBLE_EQ(kRamp.apply(gradient.value({1, 0, 0})), 1.0);
  EXPECT_NEAR(kRamp.apply(gradient.value({2.3, 5, 5})), 0.3, 1e-12);
  EXPECT_NEAR(kRamp.apply(gradient.value({-0.3, 0, 0})), 0.7, 1e-12);
}

TEST(OnionPatternTest, ConcentricShellsOfUnitThickness) {
  const OnionPattern onion;
  EXPECT_NEAR(onion.value({0.3, 0.4, 0}), 0.5, 1e-12);  // distance 0.5
  EXPECT_NEAR(onion.value({0, 3, 4}), 0.0, 1e-12);      // distance 5
  EXPECT_NEAR(onion.value({0, 0, -2.25}), 0.25, 1e-12);
}

TEST(SphericalPatternTest, OneAtCentreFallingToZeroAtUnitDistance) {
  const SphericalPattern spherical;
  EXPECT_DOUBLE_EQ(spherical.value({0, 0, 0}), 1.0);
  EXPECT_NEAR(spherical.value({0, 0.3, 0.4}), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(spherical.value({2, 0, 0}), 0.0);
  // Through the default ramp wave the centre keeps value 1 (the last colour of the map).
  EXPECT_DOUBLE_EQ(kRamp.apply(spherical.value({0, 0, 0})), 1.0);
}

TEST(CylindricalPatternTest, IgnoresHeightAlongY) {
  const CylindricalPattern cylindrical;
  EXPECT_NEAR(cylindrical.value({0.3, 100, 0.4}), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(cylindrical.value({0, -7, 0}), 1.0);
  EXPECT_DOUBLE_EQ(cylindrical.value({3, 0, 0}), 0.0);
}

TEST(PlanarPatternTest, DependsOnlyOnDistanceFromXzPlane) {
  const PlanarPattern planar;
  EXPECT_NEAR(planar.value({5, 0.25, -9}), 0.75, 1e-12);
  EXPECT_NEAR(planar.value({5, -0.25, 9}), 0.75, 1e-12);
  EXPECT_DOUBLE_EQ(planar.value({0, 1.5, 0}), 0.0);
}

TEST(BoxedPatternTest, UsesLargestCoordinate) {
  const BoxedPattern boxed;
  EXPECT_NEAR(boxed.value({0.1, -0.6, 0.2}), 0.4, 1e-12);
  EXPECT_DOUBLE_EQ(boxed.value({0, 0, 0}), 1.0);
  EXPECT_DOUBLE_EQ(boxed.value({0.5, 0.5, 1.2}), 0.0);
}

TEST(RadialPatternTest, QuarterTurnsAroundY) {
  const RadialPattern radial;
  auto folded = [&](const snell::math::Vec3& p) { return kRamp.apply(radial.value(p)); };
  // Raw values above 1 fold with POV-Ray's period of 1.00001, hence the 1e-4 tolerance.
  EXPECT_NEAR(folded({0, 0, -1}), 0.25, 1e-4);
  EXPECT_NEAR(folded({-1, 0, 0}), 0.5, 1e-4);
  EXPECT_NEAR(folded({0, 0, 1}), 0.75, 1e-4);
  EXPECT_NEAR(folded({1, 0, 1}), 0.875, 1e-9);
  // Independent of height and radius.
  EXPECT_NEAR(folded({0, 5, -3}), 0.25, 1e-4);
}

TEST(LeopardPatternTest, SquaredMeanOfSines) {
  const LeopardPattern leopard;
  const double h = 3.14159265358979323846 / 2;
  EXPECT_NEAR(leopard.value({h, h, h}), 1.0, 1e-12);
  EXPECT_NEAR(leopard.value({0, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(leopard.value({h, 0, 0}), 1.0 / 9, 1e-12);
}

TEST(BozoPatternTest, StaysInUnitRangeAndIsPovRaysNoise) {
  const BozoPattern bozo;
  EXPECT_NEAR(bozo.value({3, -2, 7}), 0.417469580551, 1e-11);  // POV-Ray 3.7.0's f_noise3d(3, -2, 7)
  for (int i = 0; i < 200; ++i) {
    const double v = bozo.value({i * 0.37, i * 0.11 - 4, i * 0.05});
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
}

TEST(WaveTest, FrequencyRepeatsAndNegativeValuesWrap) {
  WaveShaping w;
  w.frequency = 3;
  EXPECT_NEAR(w.apply(0.1), w.apply(0.1 + 1.0 / 3), 1e-4);  // period 1.00001, as POV-Ray
  w.frequency = -1;
  EXPECT_NEAR(w.apply(0.25), 0.75, 1e-12);
  w = WaveShaping{};
  w.wave = Wave::scallop;
  EXPECT_NEAR(w.apply(0.5), 1.0, 1e-12);
  w.wave = Wave::poly;
  w.exponent = 2;
  EXPECT_NEAR(w.apply(0.5), 0.25, 1e-12);
  w = WaveShaping{};
  w.frequency = 0;  // no folding at all
  EXPECT_DOUBLE_EQ(w.apply(1.7), 1.7);
}
