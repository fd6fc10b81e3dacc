// The patterns added for issue 5 as parsed from scene text: magnet, mandel/julia exponents and shading
// types, potential (against the blob's and the isosurface's own formulas), facets, bump_map, average of
// textures, and the errors for misuse (POV-Ray 3.7 reference, "Patterns").
#include <gtest/gtest.h>

#include <cmath>

#include "sdl_test_util.hpp"

using namespace snell;

namespace {

/// The grey level of the only object's pigment at texture-space point p.
double grey_at(const std::string& scene_text, const math::Vec3& p) {
  const scene::Scene s = sdl::test::parse(scene_text);
  EXPECT_EQ(s.objects.size(), 1u);
  material::PatternPoint point;
  point.p = s.objects.front()->texture->transform.inverse_point(p);
  return s.objects.front()->texture->pigment->at(point).rgb.r;
}

std::string ramp_pigment(const std::string& pattern) {
  return "plane { z, 0 pigment { " + pattern + " color_map { [0 rgb 0] [1 rgb 1] } } }";
}

}  // namespace

TEST(SdlMorePatterns, MagnetMatchesPovRay) {
  // Values POV-Ray 3.7.0 printed for the same pigments (tests/texture/fractal_patterns_test.cpp).
  EXPECT_NEAR(grey_at(ramp_pigment("magnet 1 mandel 30"), {2.3, 1.1, 0}), 0.366666675, 1e-6);
  EXPECT_NEAR(grey_at(ramp_pigment("magnet 2 julia <1.2, -0.3>, 30 interior 1, 0.1"), {0.3, 0.7, 0}),
              0.009478340, 1e-6);
}

TEST(SdlMorePatterns, MandelAndJuliaExponentsAndTypes) {
  EXPECT_NEAR(grey_at(ramp_pigment("mandel 40 exponent 5 exterior 6, 0.1"), {0.3, 0.7, 0}), 0.771622539,
              1e-4);
  EXPECT_NEAR(grey_at(ramp_pigment("julia <0.3, 0.5>, 40 exponent 4 exterior 4, 0.05"), {1.5, -0.8, 0}),
              0.411242515, 1e-4);  // modulus types: see fractal_patterns_test.cpp
  std::vector<std::string> messages;
  sdl::test::parse(ramp_pigment("mandel 10 exponent 40"), &messages);
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("exponents are 2 to 33"), std::string::npos);
  EXPECT_NE(sdl::test::error_of(ramp_pigment("mandel 10 exterior 9, 1")).find("exterior types are 0 to 8"),
            std::string::npos);
}

TEST(SdlMorePatterns, PotentialOfABlobIsItsSummedField) {
  // strength (1 - r^2/R^2)^2 per component, in the blob's own space (translated by 0.1 in x):
  // at local (0.2, 0.2, 0): 0.96^2 + 0.7 * (1 - 0.13/0.64)^2 = 1.3661068359375.
  const std::string blob =
      "blob { threshold 0.5 sphere { <0.2, 0, 0>, 1, 1 } sphere { <0, 0.5, 0>, 0.8, 0.7 } translate <0.1, 0, "
      "0> }";
  EXPECT_NEAR(grey_at(ramp_pigment("potential { " + blob + " } threshold on"), {0.3, 0.2, 0}),
              1.3661068359375 - 0.5, 1e-9);
  const std::string iso = "isosurface { function { x * x + 0.5 * y * y + z } threshold 0.1 }";
  EXPECT_NEAR(grey_at(ramp_pigment("potential { " + iso + " }"), {0.3, 0.2, 0.4}), 0.51, 1e-9);
  EXPECT_NEAR(grey_at(ramp_pigment("potential { " + iso + " } threshold on"), {0.3, 0.2, 0.4}), 0.41, 1e-9);
  EXPECT_NE(sdl::test::error_of(ramp_pigment("potential { sphere { 0, 1 } }")).find("blob or an isosurface"),
            std::string::npos);
}

TEST(SdlMorePatterns, FacetsIsForNormalsOnly) {
  EXPECT_EQ(sdl::test::error_of("sphere { 0, 1 normal { facets size 0.2 coords 0.5 metric 2 } }"), "");
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 pigment { facets } }").find("only be used in a normal"),
            std::string::npos);
  EXPECT_NE(sdl::test::error_of("sphere { 0, 1 normal { facets metric 0 } }").find("metric must be positive"),
            std::string::npos);
}

TEST(SdlMorePatterns, AverageTextureMeansThePigments) {
  const scene::Scene s = sdl::test::parse(
      "plane { z, 0 texture { average texture_map { [1 pigment { rgb <1, 0, 0> } finish { phong 0.3 }]"
      " [3 pigment { rgb <0, 0, 1> } finish { phong 0.9 }] } } }");
  ASSERT_EQ(s.objects.size(), 1u);
  const auto& texture = *s.objects.front()->texture;
  const material::Rgbft c = texture.pigment_at({0.2, 0.3, 0}, {0, 0, -1}, {});
  EXPECT_NEAR(c.rgb.r, 0.25, 1e-12);
  EXPECT_NEAR(c.rgb.b, 0.75, 1e-12);
  EXPECT_NEAR(texture.finish.phong, 0.9, 1e-12);  // the heaviest entry's finish
}

TEST(SdlMorePatterns, RemainingPatternsAreNamedInTheError) {
  for (const char* pattern : {"tiling 6", "pavement"})
    EXPECT_NE(sdl::test::error_of(ramp_pigment(pattern)).find("is not supported yet"), std::string::npos)
        << pattern;
}

TEST(SdlMorePatterns, PigmentMapEntriesSeeThePointAsTheOuterWarpsLeaveIt) {
  // POV-Ray evaluates a pigment map's entries where the outer pigment's warps and transforms took the point
  // (pigment.cpp, Compute_Pigment). POV-Ray 3.7.0.10 prints these with #debug vstr(3, F(x, y, z), ...)
  // for F = function { pigment { <the same pigment> } } (float colours: equal to about 1e-7).
  const std::string scene =
      "plane { z, 0 pigment { gradient x pigment_map { [0 granite color_map { [0 rgb 0] [1 rgb 1] } "
      "scale 0.1] [1 bozo color_map { [0 rgb 0] [1 rgb <0,0,1>] } ] } warp { turbulence 0.3 } "
      "rotate 30*z scale 0.5 } }";
  EXPECT_NEAR(grey_at(scene, {0.3, 0.7, 0.2}), 0.388222813606, 1e-6);
  EXPECT_NEAR(grey_at(scene, {-1.25, 2.5, 3.75}), 0.312124460936, 1e-6);
  EXPECT_NEAR(grey_at(scene, {10.1, -7.3, 0.45}), 0.229761600494, 1e-6);
}
