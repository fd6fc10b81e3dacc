// Parsing of area lights, fog, media, density and sky_sphere identifiers (POV-Ray 3.7 reference,
// "Area Lights", "Fog", "Media", "Density").
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sdl_test_util.hpp"

namespace snell::sdl {
namespace {

TEST(SdlAtmosphere, AreaLightCommasAreOptional) {
  const auto with = test::parse("light_source { <0,10,0> rgb 1 area_light <8,0,0>, <0,8,0>, 3, 5 jitter }");
  const auto without =
      test::parse("light_source { <0,10,0> rgb 1 area_light <8,0,0> <0,8,0> 3 5 adaptive 2 }");
  for (const auto* s : {&with, &without}) {
    ASSERT_EQ(s->lights.size(), 1u);
    EXPECT_TRUE(s->lights[0].area);
    EXPECT_EQ(s->lights[0].size1, 3);
    EXPECT_EQ(s->lights[0].size2, 5);
    EXPECT_DOUBLE_EQ(s->lights[0].axis2.y, 8);
  }
  EXPECT_TRUE(with.lights[0].jitter);
  EXPECT_EQ(without.lights[0].adaptive, 2);
}

TEST(SdlAtmosphere, AreaLightFlagsAndErrors) {
  const auto s = test::parse(
      "light_source { <0,10,0> rgb 1 area_light x, z, 4, 4 circular orient area_illumination on }");
  EXPECT_TRUE(s.lights[0].circular);
  EXPECT_TRUE(s.lights[0].orient);
  EXPECT_TRUE(s.lights[0].area_illumination);
  EXPECT_NE(test::error_of("light_source { 0 rgb 1 area_light x, z, 1, 4 circular }").find("circular"),
            std::string::npos);
  EXPECT_NE(test::error_of("light_source { 0 rgb 1 area_light x, z, 0, 4 }").find("at least 1"),
            std::string::npos);
}

TEST(SdlAtmosphere, LooksLikeObjectSitsAtTheLightAndCastsNoShadow) {
  const auto s = test::parse(
      "#declare Bulb = sphere { 0, 0.5 pigment { rgb 1 } }\n"
      "light_source { <0, 5, 0> rgb 1 looks_like { Bulb scale 2 } translate <1, 0, 0> }");
  ASSERT_EQ(s.lights.size(), 1u);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_TRUE(s.objects[0]->flags.no_shadow);
  const math::Bounds3 b = s.objects[0]->world_bounds();
  // POV-Ray moves the object to the light's centre first, then applies its modifiers (parser.cpp,
  // Parse_Light_Source), so `scale 2` also doubles that offset: radius 1 around (0, 10, 0), then x + 1.
  EXPECT_NEAR(b.lo.x, 0, 1e-9);
  EXPECT_NEAR(b.hi.y, 11, 1e-9);
  EXPECT_NEAR(s.lights[0].position.x, 1, 1e-12);
  EXPECT_NE(test::error_of("light_source { 0 rgb 1 looks_like { 1 } }").find("expected an object"),
            std::string::npos);
}

TEST(SdlAtmosphere, ProjectedThroughObjectMovesWithTheLightAndIsNotDrawn) {
  const auto s = test::parse(
      "#declare Mask = box { -1, 1 }\n"
      "light_source { <0, 5, 0> rgb 1 projected_through { Mask } translate <2, 0, 0> }");
  EXPECT_TRUE(s.objects.empty());
  ASSERT_EQ(s.lights.size(), 1u);
  ASSERT_EQ(s.lights[0].projected_through.size(), 1u);
  EXPECT_NEAR(s.lights[0].projected_through[0]->world_bounds().lo.x, 1, 1e-9);
}

TEST(SdlAtmosphere, FogBlock) {
  const auto s = test::parse(
      "fog { fog_type 2 distance 150 colour rgbft <0.3, 0.5, 0.2, 0.1, 0.2> fog_offset 25 fog_alt 4 "
      "turbulence 0.5 up <0, 2, 0> }");
  ASSERT_EQ(s.fogs.size(), 1u);
  const scene::Fog& f = s.fogs[0];
  EXPECT_EQ(f.type, scene::Fog::Type::ground);
  EXPECT_DOUBLE_EQ(f.distance, 150);
  EXPECT_DOUBLE_EQ(f.color.rgb.g, 0.5);
  EXPECT_DOUBLE_EQ(f.color.transmit, 0.2);
  EXPECT_DOUBLE_EQ(f.offset, 25);
  EXPECT_DOUBLE_EQ(f.altitude, 4);
  EXPECT_DOUBLE_EQ(f.up.y, 1);  // normalised
  ASSERT_TRUE(f.turbulence.has_value());
  EXPECT_DOUBLE_EQ(f.turbulence->amount.x, 0.5);
}

TEST(SdlAtmosphere, AtmosphericMediaAndDefaults) {
  const auto s = test::parse("media { scattering { 1, rgb 0.03 } intervals 1 samples 5 method 3 }");
  ASSERT_EQ(s.atmosphere.size(), 1u);
  const material::Media& m = s.atmosphere[0];
  EXPECT_DOUBLE_EQ(m.scattering.r, 0.03);
  EXPECT_EQ(m.min_samples, 5);
  EXPECT_EQ(m.max_samples, 5);
  EXPECT_EQ(m.method, 3);
  // POV-Ray 3.5+ defaults: method 3, one interval, ten samples.
  const auto d = test::parse("media { emission 1 }");
  EXPECT_EQ(d.atmosphere[0].method, 3);
  EXPECT_EQ(d.atmosphere[0].intervals, 1);
  EXPECT_EQ(d.atmosphere[0].min_samples, 10);
}

TEST(SdlAtmosphere, DeclaredMediaAndDensityInsideAnInterior) {
  const auto s = test::parse(
      "#declare D = density { spherical density_map { [0 rgb 0] [1 rgb 2] } }\n"
      "#declare M = media { emission 0.5 density { D scale 2 } }\n"
      "sphere { 0, 1 pigment { rgbt 1 } hollow interior { media { M } media { absorption 0.1 } } }");
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_TRUE(s.objects[0]->interior);
  const auto& media = s.objects[0]->interior->media;
  ASSERT_EQ(media.size(), 2u);
  EXPECT_DOUBLE_EQ(media[0].emission.r, 0.5);
  ASSERT_EQ(media[0].densities.size(), 1u);
  // spherical is 1 - |p| inside the unit sphere; scaled by 2, at radius 1 it is 0.5: density 1 by the map.
  EXPECT_NEAR(media[0].density_at({1, 0, 0}).r, 1.0, 1e-9);
  EXPECT_TRUE(s.objects[0]->flags.hollow);
}

TEST(SdlAtmosphere, DensityPatternWithoutMapRunsFromZeroToOne) {
  const auto s = test::parse("media { emission 1 density { gradient x } }");
  EXPECT_NEAR(s.atmosphere[0].density_at({0.25, 0, 0}).r, 0.25, 1e-9);
}

TEST(SdlAtmosphere, DensityMapEntriesMayBeDensities) {
  // media5.pov's form: `density_map { [v DeclaredDensity] }`, here two constant densities blended.
  const auto s = test::parse(
      "#declare A = density { rgb 0 }\n#declare B = density { rgb 1 }\n"
      "media { emission 1 density { gradient x density_map { [0 A] [1 B] } } }");
  EXPECT_NEAR(s.atmosphere[0].density_at({0.25, 0, 0}).g, 0.25, 1e-9);
}

TEST(SdlAtmosphere, UnsupportedDensityPatternDropsTheMediaWithAWarning) {
  std::vector<std::string> messages;
  const auto s = test::parse(
      "media { emission 1 density { pavement } }\n"
      "sphere { 0, 1 hollow interior { media { emission 1 density { tiling 6 } } } }",
      &messages);
  EXPECT_TRUE(s.atmosphere.empty());
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_TRUE(s.objects[0]->interior->media.empty());
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages[0].find("the media is ignored"), std::string::npos);
}

TEST(SdlAtmosphere, MediaMovesWithItsObject) {
  const auto s = test::parse(
      "sphere { 0, 1 hollow interior { media { emission 1 density { gradient x } } } translate <0.5, 0, 0> "
      "}");
  // The density's x = 0.25 is now at world x = 0.75.
  EXPECT_NEAR(s.objects[0]->interior->media[0].density_at({0.75, 0, 0}).r, 0.25, 1e-9);
}

TEST(SdlAtmosphere, SkySphereIdentifier) {
  const auto s = test::parse("#declare S = sky_sphere { pigment { rgb <0.1, 0.2, 0.3> } }\nsky_sphere { S }");
  ASSERT_TRUE(s.sky_sphere.has_value());
  EXPECT_DOUBLE_EQ(s.miss_color({0, 1, 0}).g, 0.2);
}

TEST(SdlAtmosphere, BadMediaIsAnError) {
  EXPECT_NE(test::error_of("media { method 4 }").find("test.pov:1:"), std::string::npos);
  EXPECT_NE(test::error_of("media { scattering { 1, rgb 1 eccentricity 0.5 } }").find("eccentricity"),
            std::string::npos);
  EXPECT_NE(test::error_of("media { samples 0 }").find("at least one sample"), std::string::npos);
  EXPECT_NE(test::error_of("fog { bogus 1 }").find("unknown fog keyword"), std::string::npos);
}

}  // namespace
}  // namespace snell::sdl
