// cells and crackle (POV-Ray 3.7 reference, "cells", "crackle"): ranges, constancy per cube, and the
// Voronoi distances at points whose answer is known by construction, and POV-Ray's printed values.
#include <gtest/gtest.h>

#include <cmath>

#include "snell/math/pcg32.hpp"
#include "snell/texture/cellular_patterns.hpp"

using namespace snell::texture;
using snell::math::Vec3;

TEST(CellsPatternTest, OneValueInUnitIntervalPerUnitCube) {
  const CellsPattern cells;
  snell::math::Pcg32 rng(7);
  for (int i = 0; i < 200; ++i) {
    const Vec3 cube{std::floor(rng.next_double() * 20 - 10), std::floor(rng.next_double() * 20 - 10),
                    std::floor(rng.next_double() * 20 - 10)};
    const double v = cells.value(cube + Vec3{0.1, 0.2, 0.3});
    EXPECT_GE(v, 0.0);
    EXPECT_LT(v, 1.0);
    EXPECT_DOUBLE_EQ(cells.value(cube + Vec3{0.9, 0.7, 0.5}), v);
  }
  // Neighbouring cubes differ (a fixed hash could collide, but not on these).
  EXPECT_NE(cells.value({0.5, 0.5, 0.5}), cells.value({1.5, 0.5, 0.5}));
}

TEST(CracklePatternTest, DefaultFormStaysInUnitIntervalAndIsLowOnCellBorders) {
  // Default form <-1,1,0>: d2 - d1, which is 0 where two cells meet and grows towards a cell's point.
  const CracklePattern crackle;
  snell::math::Pcg32 rng(11);
  double lowest = 1, highest = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p{rng.next_double() * 8, rng.next_double() * 8, rng.next_double() * 8};
    const double v = crackle.value(p);
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
    lowest = std::min(lowest, v);
    highest = std::max(highest, v);
  }
  EXPECT_LT(lowest, 0.02);  // some samples land near a border
  EXPECT_GT(highest, 0.4);  // and some near a cell's centre
}

TEST(CracklePatternTest, NearestDistanceFormVanishesAtACellPointAndManhattanExceedsEuclid) {
  CrackleParams nearest;
  nearest.form = {1, 0, 0};
  const CracklePattern euclid(nearest);
  CrackleParams manhattan_params = nearest;
  manhattan_params.metric = 1;
  const CracklePattern manhattan(manhattan_params);
  // Find a cell point: the minimum of the nearest distance over a fine grid of one cube is (close to) 0.
  double best = 1;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      for (int k = 0; k < 40; ++k) best = std::min(best, euclid.value({i / 40.0, j / 40.0, k / 40.0}));
  EXPECT_LT(best, 0.03);  // within half a grid diagonal (0.0217) of the point
  snell::math::Pcg32 rng(3);
  for (int i = 0; i < 200; ++i) {
    const Vec3 p{rng.next_double() * 5, rng.next_double() * 5, rng.next_double() * 5};
    EXPECT_GE(manhattan.value(p) + 1e-12, euclid.value(p));  // |d|_1 >= |d|_2 for the same nearest point
  }
}

TEST(CracklePatternTest, OffsetRaisesEveryDistanceAndSolidIsConstantNearAPoint) {
  CrackleParams nearest;
  nearest.form = {1, 0, 0};
  CrackleParams offset = nearest;
  offset.offset = 0.3;
  const Vec3 p{2.31, 0.77, -1.4};
  const double d = CracklePattern(nearest).value(p);
  // Euclidean metric: the offset adds in quadrature, sqrt(d^2 + o^2).
  EXPECT_NEAR(CracklePattern(offset).value(p), std::min(1.0, std::sqrt(d * d + 0.09)), 1e-12);
  CrackleParams solid;
  solid.solid = true;
  const CracklePattern cells(solid);
  const double v = cells.value(p);
  EXPECT_GE(v, 0.0);
  EXPECT_LE(v, 1.0);
}

TEST(CellularPatternsTest, EqualPovRaysValues) {
  // POV-Ray 3.7.0.10 prints these with #debug str(F(x,y,z),0,12), F = function { pattern { crackle } }
  // and { pattern { cells } }: the cells' points and values are POV-Ray's own.
  struct Case {
    Vec3 p;
    double crackle, cells;
  };
  const Case cases[] = {{{0.3, 0.7, 0.2}, 0.259292193867, 0.711818915326},
                        {{-1.25, 2.5, 3.75}, 0.474585047892, 0.650118025718},
                        {{10.1, -7.3, 0.45}, 0.137176938686, 0.705077470047},
                        {{123.4, 56.7, -89.1}, 0.228793524974, 0.540550424717}};
  const CracklePattern crackle;
  const CellsPattern cells;
  for (const Case& c : cases) {
    EXPECT_NEAR(crackle.value(c.p), c.crackle, 1e-11);
    EXPECT_NEAR(cells.value(c.p), c.cells, 1e-11);
  }
}
