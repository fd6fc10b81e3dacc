// `tiling 1..5` against POV-Ray 3.7: a plane with `pigment { tiling N color_map { [0 rgb 0] [1 rgb 1] } }`,
// `finish { ambient 1 diffuse 0 }`, assumed_gamma 1, seen by an orthographic camera 6 units wide centred
// on <0.3, 0, 0.2> at 64x64 (-A; +x runs leftwards in that image, +z upwards). snell's render of the same
// scene is pixel-identical (imgdiff SSIM 1.0000, PSNR inf, for each of the three). The points below are five
// of those pixel centres with the 8-bit sRGB value POV-Ray wrote there.
#include "snell/texture/tiling_patterns.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace snell::texture {
namespace {

struct Sample {
  double x, z;
  int srgb;
};

double srgb_to_linear(int v) {
  const double c = v / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// POV-Ray's pixels, per tiling 1 to 5.
constexpr Sample kPovray[5][5] = {
    {{2.784375, 2.496875, 199},
     {1.378125, 0.059375, 241},
     {-0.590625, 2.028125, 249},
     {-1.434375, -1.534375, 101},
     {2.034375, -2.284375, 247}},
    {{2.784375, 2.496875, 228},
     {1.378125, 0.059375, 212},
     {-0.590625, 2.028125, 200},
     {-1.434375, -1.534375, 195},
     {2.034375, -2.284375, 209}},
    {{2.784375, 2.496875, 234},
     {1.378125, 0.059375, 169},
     {-0.590625, 2.028125, 105},
     {-1.434375, -1.534375, 111},
     {2.034375, -2.284375, 76}},
    {{2.784375, 2.496875, 227},
     {1.378125, 0.059375, 239},
     {-0.590625, 2.028125, 191},
     {-1.434375, -1.534375, 195},
     {2.034375, -2.284375, 147}},
    {{2.784375, 2.496875, 190},
     {1.378125, 0.059375, 177},
     {-0.590625, 2.028125, 228},
     {-1.434375, -1.534375, 179},
     {2.034375, -2.284375, 88}},
};

TEST(TilingPattern, TilingsOneToFiveMatchPovray) {
  for (int tiling = 1; tiling <= 5; ++tiling) {
    const TilingPattern pattern(tiling);
    for (const Sample& s : kPovray[tiling - 1]) {
      const double v = pattern.value({s.x, 7.0, s.z});  // constant along y
      // Half an 8-bit step in sRGB, taken back to linear.
      const double tolerance = srgb_to_linear(s.srgb + 1) - srgb_to_linear(s.srgb);
      EXPECT_NEAR(v, srgb_to_linear(s.srgb), tolerance)
          << "tiling " << tiling << " at " << s.x << ", " << s.z;
    }
  }
}

TEST(TilingPattern, RampRunsFromTileCentreToOutline) {
  const TilingPattern squares(1), hexagons(2), triangles(3);
  EXPECT_NEAR(squares.value({0.5, 0, 0.5}), 0.0, 1e-12);
  EXPECT_NEAR(squares.value({0.999999, 0, 0.5}), 1.0, 1e-5);
  EXPECT_NEAR(hexagons.value({0.5, 0, std::sqrt(3.0) / 2}), 0.0, 1e-12);  // a hexagon's centre
  EXPECT_NEAR(hexagons.value({1.5, 0, std::sqrt(3.0) / 2}), 1.0, 1e-12);  // its corner along x
  // The upward triangle (0,0)-(1,0)-(1/2,sqrt3/2) is kind 0: 0 at its centre; the downward one next to
  // it kind 1: 1/2 at its centre.
  EXPECT_NEAR(triangles.value({0.5, 0, std::sqrt(3.0) / 6}), 0.0, 1e-12);
  EXPECT_NEAR(triangles.value({1.0, 0, std::sqrt(3.0) / 3}), 0.5, 1e-12);
  for (double x = -3; x < 3; x += 0.37)
    for (double z = -3; z < 3; z += 0.41)
      for (const TilingPattern* p : {&squares, &hexagons, &triangles}) {
        EXPECT_GE(p->value({x, 0, z}), 0.0);
        EXPECT_LE(p->value({x, 0, z}), 1.0);
      }
}

TEST(TilingPattern, RefusesTheTilingsSnellLacks) {
  EXPECT_THROW(TilingPattern(6), std::invalid_argument);
  EXPECT_THROW(TilingPattern(0), std::invalid_argument);
}

}  // namespace
}  // namespace snell::texture
