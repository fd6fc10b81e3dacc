// `tiles { texture {A} tile2 texture {B} }`, POV-Ray's old checker of textures. POV-Ray's Parse_Tiles puts
// the first texture on the checker's odd cells and tile2 on the even ones: rendering
//   box { <-32,-1,-32> <32,0,32> texture { tiles { texture { pigment { rgb 1 } } tile2
//         texture { pigment { rgb 0 } } } scale <8,1,8> } }
// with povray 3.7 shows the near corner cell (x in [24,32], z in [-32,-24], top face y = 0) white, i.e.
// floor(3)+floor(0)+floor(-4) = -1 is odd and gets the first texture (advanced/chess2.pov's board).
#include <gtest/gtest.h>

#include "sdl_test_util.hpp"
#include "snell/material/texture.hpp"

using namespace snell;

namespace {

double red_at(const scene::Scene& s, math::Vec3 p) {
  const material::Texture& t = *s.objects.front()->texture;
  material::PatternPoint point;
  point.p = p;
  const auto choice = t.selector->at(point);
  return choice.first->pigment->at(point).rgb.r;
}

}  // namespace

TEST(TilesTexture, FirstTextureLiesOnOddCells) {
  const scene::Scene s = sdl::test::parse(
      "plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { rgb 0 } } } } "
      "}");
  EXPECT_DOUBLE_EQ(red_at(s, {0.5, 0, 0.5}), 0.0);   // 0+0+0 even: tile2
  EXPECT_DOUBLE_EQ(red_at(s, {1.5, 0, 0.5}), 1.0);   // 1+0+0 odd: first texture
  EXPECT_DOUBLE_EQ(red_at(s, {3.5, 0, -3.5}), 1.0);  // 3+0-4 odd: first texture
  EXPECT_DOUBLE_EQ(red_at(s, {-0.5, 0, 0.5}), 1.0);
}
