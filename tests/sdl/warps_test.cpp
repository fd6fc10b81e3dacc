// `warp {}` blocks (POV-Ray 3.7 reference, "Warps") as the pattern sees them: repeat tiles a slab, flip
// mirrors odd slabs, black_hole moves points only inside its radius, cylindrical maps (x, y, z) to
// (angle/2pi, y, distance from the y axis).
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"

using namespace snell;

namespace {

/// The red channel of `pigment { gradient <axis> <warp> color_map {[0 rgb 0][1 rgb 1]} }` at p: the
/// pattern's value after the warp.
double value_at(const std::string& pattern_and_warp, const math::Vec3& p) {
  const scene::Scene s = sdl::test::parse("plane { y, 0 pigment { " + pattern_and_warp +
                                          " color_map { [0 rgb 0] [1 rgb 1] } } }");
  material::PatternPoint point;
  point.p = p;
  return s.objects.front()->texture->pigment->at(point).rgb.r;
}

}  // namespace

TEST(Warps, RepeatShowsTheFirstSlabInEveryOther) {
  EXPECT_NEAR(value_at("gradient x warp { repeat x * 0.5 }", {1.2, 0, 0}), 0.2, 1e-9);
  EXPECT_NEAR(value_at("gradient x warp { repeat x * 0.5 }", {-0.3, 0, 0}), 0.2, 1e-9);
}

TEST(Warps, RepeatFlipMirrorsOddSlabs) {
  // Slab 1 of width 0.5 mirrored along x: x = 0.6 shows what x = 0.4 of slab 0 shows.
  EXPECT_NEAR(value_at("gradient x warp { repeat x * 0.5 flip x }", {0.6, 0, 0}), 0.4, 1e-9);
}

TEST(Warps, RepeatOffsetShiftsEachSlab) {
  EXPECT_NEAR(value_at("gradient y warp { repeat x offset <0, 0.25, 0> }", {1.5, 0.1, 0}), 0.35, 1e-9);
}

TEST(Warps, BlackHoleMovesOnlyPointsInsideItsRadius) {
  const std::string hole = "gradient x warp { black_hole <0, 0, 0>, 0.5 }";
  EXPECT_NEAR(value_at(hole, {0.7, 0, 0}), 0.7, 1e-9);
  // Halfway to the rim: pulled by ((0.5 - 0.25) / 0.5)^2 = 0.25 of the offset from the centre.
  EXPECT_NEAR(value_at(hole, {0.25, 0, 0}), 0.25 * 1.25, 1e-9);
}

TEST(Warps, CylindricalReadsAngleAndDistance) {
  // (0, 0, 1) lies a quarter turn from +x toward +z; its distance from the y axis is 1.
  EXPECT_NEAR(value_at("gradient x warp { cylindrical }", {0, 0, 1}), 0.25, 1e-9);
  EXPECT_NEAR(value_at("gradient z warp { cylindrical }", {0.3, 0, 0.4}), 0.5, 1e-9);
}

TEST(Warps, PlanarFlattensOntoItsOffset) {
  EXPECT_NEAR(value_at("gradient z warp { planar z, 0.3 }", {0.2, 0.1, 0.9}), 0.3, 1e-9);
}

TEST(Warps, UnknownWarpIsALocatedError) {
  const std::string e = sdl::test::error_of("plane { y, 0 pigment { bozo warp { twist 2 } } }");
  EXPECT_NE(e.find("test.pov:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("twist"), std::string::npos) << e;
}
