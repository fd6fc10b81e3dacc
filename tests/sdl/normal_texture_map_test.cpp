// normal {}, texture_map and the newer patterns as parsed from scene text (POV-Ray 3.7 reference,
// "Normal", "Texture Maps", "crackle", "mandel").
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"
#include "snell/material/texture.hpp"

using namespace snell;

namespace {

const material::Texture& texture_of(const scene::Scene& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return *s.objects.front()->texture;
}

}  // namespace

TEST(SdlNormal, GradientNormalTiltsByBumpSize) {
  // `gradient x 1` bends +y toward -x by 5 * 0.02 * 4/3 (POV-Ray's finite-difference rule).
  const scene::Scene s = sdl::test::parse("plane { y, 0 normal { gradient x 1 } }");
  const math::Vec3 n = texture_of(s).shading_normal({0.3, 0, 0.2}, {0, 1, 0}, {});
  const math::Vec3 expected = normalize(math::Vec3{-0.1 * 4 / 3, 1, 0});
  EXPECT_NEAR(n.x, expected.x, 1e-6);
  EXPECT_NEAR(n.y, expected.y, 1e-6);
}

TEST(SdlNormal, DeclaredNormalsTextureNormalsAndMapsParse) {
  const scene::Scene s = sdl::test::parse(R"(
    #declare N = normal { bumps 0.4 scale 0.2 }
    sphere { 0, 1 texture { pigment { rgb 1 } normal { N } }
                  normal { gradient y slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } accuracy 0.01 } }
    )");
  const math::Vec3 n =
      texture_of(s).shading_normal({0.3, 0.9, 0.2}, normalize(math::Vec3{0.3, 0.9, 0.2}), {});
  EXPECT_NEAR(length(n), 1.0, 1e-12);
  const scene::Scene m = sdl::test::parse(
      "plane { y, 0 normal { gradient x normal_map { [0 bumps 1] [1 ripples 0.5 frequency 3] } } }");
  EXPECT_NEAR(length(texture_of(m).shading_normal({0.5, 0, 0.5}, {0, 1, 0}, {})), 1.0, 1e-12);
}

TEST(SdlNormal, TexturesWithoutNormalKeepTheGeometricNormal) {
  const scene::Scene s = sdl::test::parse("plane { y, 0 pigment { rgb 1 } }");
  const math::Vec3 n = texture_of(s).shading_normal({0.3, 0, 0.2}, {0, 1, 0}, {});
  EXPECT_DOUBLE_EQ(n.y, 1.0);
}

TEST(SdlTextureMap, GradientTextureMapBlendsEntryPigmentsAndPicksFinish) {
  const scene::Scene s = sdl::test::parse(R"(
    plane { y, 0 texture { gradient x texture_map {
        [0 pigment { rgb <1, 0, 0> } finish { diffuse 0.2 }]
        [1 pigment { rgb <0, 0, 1> } finish { diffuse 0.8 }] } } })");
  const material::Texture& t = texture_of(s);
  const material::Rgbft c = t.pigment_at({0.25, 0, 0}, {0, 1, 0}, {});
  EXPECT_NEAR(c.rgb.r, 0.75, 1e-9);
  EXPECT_NEAR(c.rgb.b, 0.25, 1e-9);
  EXPECT_DOUBLE_EQ(t.finish_at({0.25, 0, 0}).diffuse, 0.2);
  EXPECT_DOUBLE_EQ(t.finish_at({0.75, 0, 0}).diffuse, 0.8);
}

TEST(SdlTextureMap, CheckerOfTexturesAlternates) {
  const scene::Scene s = sdl::test::parse(R"(
    plane { y, 0 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } scale 2 } })");
  const material::Texture& t = texture_of(s);
  EXPECT_NEAR(t.pigment_at({1, 0.5, 1}, {0, 1, 0}, {}).rgb.r, 1.0, 1e-12);
  EXPECT_NEAR(t.pigment_at({3, 0.5, 1}, {0, 1, 0}, {}).rgb.r, 0.0, 1e-12);
}

TEST(SdlPatterns, CrackleQuiltedSpiralMandelParseWithTheirModifiers) {
  for (const char* pigment :
       {"crackle form <1, 0, 0> metric 1 offset 0.1", "crackle solid", "cells", "wrinkles", "dents",
        "quilted control0 0.5 control1 0.8", "spiral1 3", "spiral2 5", "mandel 50 exterior 1, 1",
        "julia <0.35, 0.4>, 30 interior 1, 1", "ripples frequency 2", "waves phase 0.3"}) {
    const std::string scene = std::string("sphere { 0, 1 pigment { ") + pigment + " } }";
    EXPECT_EQ(sdl::test::error_of(scene), "") << pigment;
  }
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 pigment { onion metric 2 } }").find("crackle"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 texture { gradient x } }").find("texture_map"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 pigment { image_map { png \"no-such.png\" } } }")
                .find("cannot find file"),
            std::string::npos);
}

TEST(SdlPatterns, MandelIsOneInsideTheSetAndLowFarOutside) {
  // Default colouring: interior type 0 (value 1), exterior type 1 (iterations / n).
  const scene::Scene s = sdl::test::parse("plane { z, 0 pigment { mandel 100 } }");
  const auto& p = *texture_of(s).pigment;
  material::PatternPoint inside, outside;
  inside.p = {-0.2, 0.1, 0};
  outside.p = {1.5, 1.5, 0};
  EXPECT_NEAR(p.at(inside).rgb.r, 1.0, 1e-4);   // through the default grey ramp (folded at 1.00001)
  EXPECT_NEAR(p.at(outside).rgb.r, 0.0, 1e-9);  // escapes on the first iteration
}

TEST(SdlPatterns, UvMappingLooksUpThePatternAtTheSurfaceUv) {
  const scene::Scene s = sdl::test::parse("sphere { 0, 1 pigment { uv_mapping gradient x } }");
  const material::Texture& t = texture_of(s);
  // The point in space is ignored; u = 0.25 gives a quarter of the default grey ramp.
  EXPECT_NEAR(t.pigment_at({0.9, 0.1, 0}, {1, 0, 0}, {0.25, 0.6}).rgb.r, 0.25, 1e-9);
  EXPECT_NEAR(t.pigment_at({0.1, 0.9, 0}, {0, 1, 0}, {0.75, 0.1}).rgb.r, 0.75, 1e-9);
}

TEST(SdlTextureMap, TilesWithTile2IsACheckerOfTextures) {
  const scene::Scene s = sdl::test::parse(R"(
    plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } tile2 texture { pigment { rgb 0 } } } } })");
  const material::Texture& t = texture_of(s);
  // POV-Ray's Parse_Tiles: the first texture on odd cells, tile2 on even ones (tiles_texture_test.cpp).
  EXPECT_NEAR(t.pigment_at({0.5, 0.5, 0.5}, {0, 1, 0}, {}).rgb.r, 0.0, 1e-12);
  EXPECT_NEAR(t.pigment_at({1.5, 0.5, 0.5}, {0, 1, 0}, {}).rgb.r, 1.0, 1e-12);
}

TEST(SdlPatterns, SlopeWithAltitudeWrapsAndUsesTheUnitAltitude) {
  // POV-Ray 3.7 (pattern.cpp slope_pattern, parstxtr.cpp): weights 0.8/2.8 and 2/2.8 from the vectors'
  // lengths, the height measured along the unit altitude direction, the blend wrapped into [0,1).
  const scene::Scene s = sdl::test::parse("plane { z, 0 pigment { slope { -z * 0.8 altitude z * 2 } } }");
  const material::Texture& t = texture_of(s);
  const math::Vec3 up{0, 0, 1}, down_ray{0, 0, -1};
  // Facing +z: asin(-1) -> slope 0; at height 0.9: 0.9 * 2/2.8 (the unnormalised 1.8 * 2/2.8 wraps to 0.29).
  EXPECT_NEAR(t.pigment_at({0, 0, 0.9}, up, {}, down_ray).rgb.r, 0.9 * 2 / 2.8, 1e-9);
  // Below zero the blend wraps to the top of the map: height -0.18 gives -0.1286 -> 0.8714.
  EXPECT_NEAR(t.pigment_at({0, 0, -0.18}, up, {}, down_ray).rgb.r, 1 - 0.18 * 2 / 2.8, 1e-9);
}

TEST(SdlPatterns, SlopeTakesTheNormalTurnedToTheRay) {
  // POV-Ray evaluates slope with the normal that faces the ray (trace.cpp sets PNormal after the flip):
  // a surface whose normal points down but is seen from above slopes as if it faced up.
  const scene::Scene s = sdl::test::parse("plane { z, 0 pigment { slope z } }");
  const material::Texture& t = texture_of(s);
  EXPECT_NEAR(t.pigment_at({0, 0, 0}, {0, 0, -1}, {}, {0, 0, -1}).rgb.r, 1.0, 1e-6);
  EXPECT_NEAR(t.pigment_at({0, 0, 0}, {0, 0, -1}, {}, {0, 0, 1}).rgb.r, 0.0, 1e-6);
}

TEST(SdlTextureMap, SlopeMapPicksFinishAndLightsEachEntry) {
  // A slope map needs the normal for its finish as for its colour: facing up the second entry's finish.
  const scene::Scene s = sdl::test::parse(R"(
    plane { z, 0 texture { slope z texture_map {
      [0.0 pigment { rgb 1 } finish { diffuse 0.1 }] [0.5 pigment { rgb 1 } finish { diffuse 0.1 }]
      [0.5 pigment { rgb 1 } finish { diffuse 0.9 }] [1.0 pigment { rgb 1 } finish { diffuse 0.9 }] } } })");
  const material::Texture& t = texture_of(s);
  const math::Vec3 up{0, 0, 1};
  EXPECT_DOUBLE_EQ(t.finish_at({0, 0, 0}, up, {0, 0, -1}).diffuse, 0.9);
  EXPECT_DOUBLE_EQ(t.finish_at({0, 0, 0}, -up, {0, 0, 1}).diffuse, 0.1);
  // Between two entries each comes with its own finish and weight, to be lit on its own.
  const scene::Scene g = sdl::test::parse(R"(
    plane { z, 0 texture { gradient x texture_map {
      [0 pigment { rgb 1 } finish { diffuse 0.2 }] [1 pigment { rgb 0 } finish { diffuse 0.8 }] } } })");
  material::Texture::MapEntry entries[2];
  ASSERT_TRUE(texture_of(g).map_entries_at({0.25, 0, 0}, up, up, {}, {0, 0, -1}, entries));
  EXPECT_DOUBLE_EQ(entries[0].finish->diffuse, 0.2);
  EXPECT_DOUBLE_EQ(entries[1].finish->diffuse, 0.8);
  EXPECT_NEAR(entries[0].weight, 0.75, 1e-12);
  EXPECT_NEAR(entries[1].weight, 0.25, 1e-12);
  EXPECT_NEAR(entries[0].pigment.rgb.r, 1, 1e-12);
  EXPECT_NEAR(entries[1].pigment.rgb.r, 0, 1e-12);
}

TEST(SdlPatterns, SlopeFollowsTheSurfaceNormal) {
  // slope y: asin(n . y) from [-pi/2, pi/2] onto [0, 1]: facing up ~1, sideways 0.5, 30 degrees up 2/3.
  const scene::Scene s = sdl::test::parse("sphere { 0, 1 pigment { slope y } }");
  const material::Texture& t = texture_of(s);
  EXPECT_NEAR(t.pigment_at({1, 0, 0}, {1, 0, 0}, {}).rgb.r, 0.5, 1e-9);
  EXPECT_NEAR(t.pigment_at({0, 0, 0}, normalize(math::Vec3{std::sqrt(3.0), 1, 0}), {}).rgb.r, 2.0 / 3, 1e-9);
  EXPECT_NEAR(t.pigment_at({0, 1, 0}, {0, 1, 0}, {}).rgb.r, 1.0, 1e-6);
  EXPECT_EQ(sdl::test::error_of("sphere { 0, 1 texture { slope { -z * 0.8 altitude z } texture_map { "
                                "[0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }"),
            "");
}
