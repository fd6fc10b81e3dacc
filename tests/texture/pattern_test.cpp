#include <gtest/gtest.h>

#include "snell/texture/color_map.hpp"
#include "snell/texture/pattern.hpp"
#include "snell/texture/pattern_pigment.hpp"
#include "snell/texture/value_patterns.hpp"
#include "snell/texture/wave.hpp"

using namespace snell;
using namespace snell::texture;

TEST(CheckerPatternTest, AlternatesBetweenUnitCubes) {
  const CheckerPattern checker;
  EXPECT_EQ(checker.block({0.5, 0.5, 0.5}), 0);
  EXPECT_EQ(checker.block({1.5, 0.5, 0.5}), 1);
  EXPECT_EQ(checker.block({1.5, 1.5, 0.5}), 0);
  EXPECT_EQ(checker.block({-0.5, 0.5, 0.5}), 1);
  EXPECT_EQ(checker.block({-0.5, -0.5, -0.5}), 1);
}

TEST(CheckerPatternTest, PlaneThroughIntegerCoordinateIsStable) {
  // Points on y = 0 computed with rounding error just below zero still fall in the y in [0,1) layer.
  const CheckerPattern checker;
  EXPECT_EQ(checker.block({0.5, -1e-12, 0.5}), checker.block({0.5, 1e-12, 0.5}));
}

TEST(GradientPatternTest, RampRepeatsEveryUnitAlongDirection) {
  const GradientPattern gradient({0, 1, 0});
  const WaveShaping ramp;
  EXPECT_DOUBLE_EQ(ramp.apply(gradient.value({7, 0.25, 3})), 0.25);
  EXPECT_DOUBLE_EQ(ramp.apply(gradient.value({7, 2.25, 3})), 0.25);
  EXPECT_DOUBLE_EQ(ramp.apply(gradient.value({7, -0.25, 3})), 0.75);
}

TEST(WaveTest, ShapesMatchPovRayDefinitions) {
  WaveShaping w;
  w.wave = Wave::triangle;
  EXPECT_DOUBLE_EQ(w.apply(0.25), 0.5);
  EXPECT_DOUBLE_EQ(w.apply(0.75), 0.5);
  w.wave = Wave::sine;
  EXPECT_NEAR(w.apply(0.25), 1.0, 1e-12);
  w.wave = Wave::cubic;
  EXPECT_DOUBLE_EQ(w.apply(0.5), 0.5);
  w.wave = Wave::ramp;
  w.frequency = 2;
  w.phase = 0.1;
  EXPECT_NEAR(w.apply(0.3), 0.7, 1e-12);
}

TEST(ColorMapTest, InterpolatesLinearlyAndClampsOutside) {
  const ColorMap map({{0.5, {math::Color(1, 0, 0), 0, 0}}, {0.0, {math::Color(0, 0, 1), 0, 1}}});
  EXPECT_EQ(map.at(-1).rgb, math::Color(0, 0, 1));
  EXPECT_EQ(map.at(2).rgb, math::Color(1, 0, 0));
  const auto mid = map.at(0.25);
  EXPECT_DOUBLE_EQ(mid.rgb.r, 0.5);
  EXPECT_DOUBLE_EQ(mid.rgb.b, 0.5);
  EXPECT_DOUBLE_EQ(mid.transmit, 0.5);
}

TEST(BlockPigmentTest, CheckerPicksSubPigments) {
  auto red = std::make_shared<material::SolidPigment>(material::Rgbft{math::Color(1, 0, 0)});
  auto blue = std::make_shared<material::SolidPigment>(material::Rgbft{math::Color(0, 0, 1)});
  PatternSpec spec;
  spec.block_pattern = std::make_shared<CheckerPattern>();
  spec.block_entries = {red, blue};
  const PatternPigment pigment(spec);
  EXPECT_EQ(pigment.at({{0.5, 0.5, 0.5}, {}, {}}).rgb, math::Color(1, 0, 0));
  EXPECT_EQ(pigment.at({{1.5, 0.5, 0.5}, {}, {}}).rgb, math::Color(0, 0, 1));
}
