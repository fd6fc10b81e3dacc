// `material_map` (POV-Ray 3.7 reference, "Material Maps"): a palette image's index picks the texture.
// The indices expected are those of POV-Ray's own povmap.png (in the include folder) as Pillow reads
// them: pixel (10,10) has index 1, (60,150) 2, (160,100) 3 and (200,30) 0.
#include <gtest/gtest.h>

#include <string>

#include "sdl_test_util.hpp"
#include "snell/material/texture.hpp"

using namespace snell;

namespace {

/// The red of the texture the object's material_map picks at the centre of image pixel (x, y)
/// (povmap.png is 320 x 200, laid on the unit square of the x-y plane, row 0 at the top).
double picked_red(const scene::Scene& s, int x, int y) {
  const material::Texture& t = *s.objects.front()->texture;
  material::PatternPoint point;
  point.p = {(x + 0.5) / 320.0, 1 - (y + 0.5) / 200.0, 0};
  const auto choice = t.selector->at(point);
  EXPECT_EQ(choice.second, nullptr);
  return choice.first->pigment->at(point).rgb.r;
}

std::string scene_with(const std::string& textures, const std::string& modifiers = "") {
  return "plane { z, 0 texture { material_map { png \"povmap.png\" " + modifiers + textures + " } } }";
}

const std::string kFourTextures =
    "texture { pigment { rgb 0.1 } } texture { pigment { rgb 0.2 } } "
    "texture { pigment { rgb 0.3 } } texture { pigment { rgb 0.4 } }";

}  // namespace

TEST(MaterialMap, PaletteIndexPicksTheTexture) {
  const scene::Scene s = sdl::test::parse(scene_with(kFourTextures));
  EXPECT_DOUBLE_EQ(picked_red(s, 200, 30), 0.1);
  EXPECT_DOUBLE_EQ(picked_red(s, 10, 10), 0.2);
  EXPECT_DOUBLE_EQ(picked_red(s, 60, 150), 0.3);
  EXPECT_DOUBLE_EQ(picked_red(s, 160, 100), 0.4);
}

TEST(MaterialMap, IndicesPastTheListWrapAround) {
  // Index 3 with three textures is texture 0 again (POV-Ray takes the index modulo the count).
  const scene::Scene s = sdl::test::parse(scene_with(
      "texture { pigment { rgb 0.1 } } texture { pigment { rgb 0.2 } } texture { pigment { rgb 0.3 } }",
      "map_type 0 interpolate 2 "));
  EXPECT_DOUBLE_EQ(picked_red(s, 160, 100), 0.1);
  EXPECT_DOUBLE_EQ(picked_red(s, 60, 150), 0.3);
}

TEST(MaterialMap, OnceShowsTheFirstTextureOutsideTheImage) {
  const scene::Scene s = sdl::test::parse(scene_with(kFourTextures, "once "));
  material::PatternPoint point;
  point.p = {1.5 + 160.5 / 320.0, 1 - 100.5 / 200.0, 0};  // one image width right of pixel (160, 100)
  const auto choice = s.objects.front()->texture->selector->at(point);
  EXPECT_DOUBLE_EQ(choice.first->pigment->at(point).rgb.r, 0.1);
}

TEST(MaterialMap, BadInputIsAnError) {
  EXPECT_NE(sdl::test::error_of(scene_with("")).find("material_map needs at least one texture"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("plane { z, 0 texture { material_map { png \"no-such.png\" texture { } } } }")
                .find("cannot find file"),
            std::string::npos);
}
