// square, triangular and cubic (texture/polygon_block_patterns.hpp) against the entries POV-Ray 3.7.0
// itself gives (Debian 12 `povray`: #debug of 10 * P(x, y, z).red for
// `function { pigment { square rgb 0, rgb 0.1, rgb 0.2, rgb 0.3 } }` and likewise with six entries).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "snell/texture/polygon_block_patterns.hpp"

using namespace snell::texture;
using snell::math::Vec3;

namespace {

struct Sample {
  Vec3 p;
  int square, triangular, cubic;
};

const std::array<Sample, 8> kPovray = {{
    {{0.3, 0.7, 1.1}, 1, 4, 2},
    {{-2.25, 0.4, 3.6}, 2, 0, 2},
    {{5.1, -1.3, 0.2}, 3, 5, 0},
    {{1.7, 0, -0.4}, 2, 1, 0},
    {{-0.6, 2, -2.9}, 2, 2, 5},
    {{2.45, 0, 1.2}, 1, 3, 0},
    {{0.9, -3, 0.3}, 0, 3, 4},
    {{-1.2, 0.5, -0.5}, 1, 0, 3},
}};

}  // namespace

TEST(PolygonBlockPatterns, EntriesMatchPovray) {
  const auto square = make_polygon_block_pattern("square");
  const auto triangular = make_polygon_block_pattern("triangular");
  const auto cubic = make_polygon_block_pattern("cubic");
  ASSERT_TRUE(square && triangular && cubic);
  EXPECT_EQ(make_polygon_block_pattern("hexagon"), nullptr);
  EXPECT_EQ(square->block_count(), 4);
  EXPECT_EQ(triangular->block_count(), 6);
  for (const Sample& s : kPovray) {
    EXPECT_EQ(square->block(s.p), s.square) << s.p.x << " " << s.p.z;
    EXPECT_EQ(triangular->block(s.p), s.triangular) << s.p.x << " " << s.p.z;
    EXPECT_EQ(cubic->block(s.p), s.cubic) << s.p.x << " " << s.p.y << " " << s.p.z;
  }
}

TEST(PolygonBlockPatterns, SixDifferentTrianglesMeetAtEachCorner) {
  const TriangularPattern triangular;
  const double h = std::sqrt(3.0) / 2;
  // Corners of the tiling: (i + j/2, j h). Around each, six triangles at angles 30 + 60 k degrees.
  for (int i = -3; i <= 3; ++i)
    for (int j = -2; j <= 2; ++j) {
      std::set<int> entries;
      for (int k = 0; k < 6; ++k) {
        const double a = (30 + 60 * k) * 3.14159265358979323846 / 180;
        entries.insert(triangular.block({i + 0.5 * j + 0.3 * std::cos(a), 0, j * h + 0.3 * std::sin(a)}));
      }
      EXPECT_EQ(entries.size(), 6u) << "corner " << i << " " << j;
    }
}

TEST(PolygonBlockPatterns, PatternsRepeatWithTheirPeriod) {
  const SquarePattern square;
  const TriangularPattern triangular;
  const double h = std::sqrt(3.0) / 2;
  for (double x = -2.9; x < 3; x += 0.37)
    for (double z = -2.9; z < 3; z += 0.41) {
      EXPECT_EQ(square.block({x, 0, z}), square.block({x + 2, 5, z - 2}));
      EXPECT_EQ(triangular.block({x, 0, z}), triangular.block({x + 3, -1, z + 2 * h}));
    }
}
