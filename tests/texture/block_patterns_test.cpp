// Hexagon and brick block patterns against their documented geometry (POV-Ray 3.7 reference,
// "hexagon", "brick").
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "snell/texture/pattern.hpp"

using namespace snell::texture;
using snell::math::Vec3;

TEST(HexagonPatternTest, OriginHexagonIsEntryZeroWithDifferentNeighbours) {
  const HexagonPattern hexagon;
  const double r3 = std::sqrt(3.0);
  // Hexagons of side 1 with centres on a lattice spaced sqrt(3) apart: the origin's hexagon and its six
  // neighbours. Entry 0 at the origin; the six neighbours alternate between the other two entries.
  EXPECT_EQ(hexagon.block({0.01, 0, 0.01}), 0);
  EXPECT_EQ(hexagon.block({0.8, 0, 0.3}), 0);  // inside the origin hexagon (|x| < 1 near z = 0)
  int neighbours[6];
  for (int k = 0; k < 6; ++k) {
    const double a = (30 + 60 * k) * 3.14159265358979323846 / 180;
    neighbours[k] = hexagon.block({r3 * std::cos(a), 0, r3 * std::sin(a)});
    EXPECT_NE(neighbours[k], 0) << "neighbour " << k;
  }
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(neighbours[k], neighbours[(k + 2) % 6]);
    EXPECT_NE(neighbours[k], neighbours[(k + 1) % 6]);
  }
}

TEST(HexagonPatternTest, ConstantAlongYAndUsesAllThreeEntries) {
  const HexagonPattern hexagon;
  std::set<int> seen;
  for (int i = 0; i < 50; ++i) {
    const Vec3 p{i * 0.173 - 4, 0, i * 0.311 - 7};
    EXPECT_EQ(hexagon.block(p), hexagon.block(p + Vec3{0, 123.4, 0}));
    seen.insert(hexagon.block(p));
  }
  EXPECT_EQ(seen.size(), 3u);
}

TEST(BrickPatternTest, MortarLayersAndStaggeredJoints) {
  const BrickPattern brick;  // bricks 8 x 3 x 4.5, mortar 0.5
  // Horizontal mortar: the bottom 0.5 of every 3-unit course (shifted by the mortar width).
  EXPECT_EQ(brick.block({2, -0.25, 1}), 0);
  EXPECT_EQ(brick.block({2, 1.5, 1}), 1);
  // Vertical joints every 8 units in x, offset by 4 in the next course.
  EXPECT_EQ(brick.block({-0.25, 1.5, 1}), 0);
  EXPECT_EQ(brick.block({3.75, 1.5, 1}), 1);
  EXPECT_EQ(brick.block({3.75, 4.5, 1}), 0);
  EXPECT_EQ(brick.block({-0.25, 4.5, 1}), 1);
}

TEST(BrickPatternTest, RejectsNonPositiveSize) {
  EXPECT_THROW(BrickPattern({0, 1, 1}, 0.1), std::invalid_argument);
  EXPECT_THROW(BrickPattern({1, 1, 1}, -0.1), std::invalid_argument);
}
