// POV-Ray's focal-blur lens grids (tracepixel.cpp HexGrid2/3/4): with no jitter (0.5, 0.5) the points are
// POV-Ray's, and its first batch of 7 for 37 samples is the centre and the outer corners
// (0.433013, 0), (0.216506, +-0.375), ...; the 19-point grid reaches 0.384900, the 7-point one 0.288675.
#include "snell/scene/hex_lens_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace snell::scene {
namespace {

double radius(const math::Vec2& p) {
  return std::hypot(p.u, p.v);
}

TEST(HexLensGrid, FirstBatchIsPovraysCoarseHexagon) {
  const math::Vec2 centre = *hex_lens_sample(0, 37, 0.5, 0.5);
  EXPECT_NEAR(radius(centre), 0, 1e-12);
  for (int i = 1; i < 7; ++i) {
    const math::Vec2 p = *hex_lens_sample(i, 37, 0.5, 0.5);
    EXPECT_NEAR(radius(p), 0.433013, 1e-6) << i;
    // A corner on the u axis, the others at 60 degree steps: |v| is 0 or 0.375.
    EXPECT_TRUE(std::fabs(std::fabs(p.v) - 0.375) < 1e-6 || std::fabs(p.v) < 1e-9) << i;
  }
}

TEST(HexLensGrid, GridsHavePovraysSizeAndDistinctPoints) {
  for (const auto& [count, outer] : {std::pair{7, 0.288675}, {19, 0.384900}, {37, 0.433013}}) {
    std::vector<math::Vec2> points;
    double farthest = 0;
    for (int i = 0; i < count; ++i) {
      points.push_back(*hex_lens_sample(i, count, 0.5, 0.5));
      farthest = std::max(farthest, radius(points.back()));
    }
    EXPECT_NEAR(farthest, outer, 1e-6) << count;
    for (size_t a = 0; a < points.size(); ++a)
      for (size_t b = a + 1; b < points.size(); ++b)
        EXPECT_GT(std::hypot(points[a].u - points[b].u, points[a].v - points[b].v), 0.1) << count;
    EXPECT_FALSE(hex_lens_sample(count, count, 0.5, 0.5)) << count;
  }
  EXPECT_FALSE(hex_lens_sample(0, 20, 0.5, 0.5));
}

TEST(HexLensGrid, JitterStaysWithinHalfTheSpacing) {
  // POV-Ray's HexJitter4 = 0.0721688: half of the 37-point grid's spacing.
  const math::Vec2 low = *hex_lens_sample(0, 37, 0, 0), high = *hex_lens_sample(0, 37, 0.999999, 0.999999);
  EXPECT_NEAR(low.u, -0.0721688, 1e-6);
  EXPECT_NEAR(high.v, 0.0721688, 1e-6);
}

}  // namespace
}  // namespace snell::scene
