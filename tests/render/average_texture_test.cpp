// `average texture_map` lights every entry with its own finish and averages the colours (POV-Ray 3.7
// trace.cpp, ComputeAverageTextureColours). POV-Ray 3.7 renders the plane below (+W3 +H3 -A
// File_Gamma=1.0) with the centre pixel (64, 0, 96): red 0.25 = weight 1/4 of the first entry's ambient 1,
// blue 0.375 = weight 3/4 of the second entry's diffuse 0.5 under a head-on light. Blending the pigments
// under the heavier entry's finish gave red 0.125.
#include <gtest/gtest.h>

#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/render/whitted.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::render {
namespace {

math::Color centre_of(const std::string& texture, const std::string& object_modifiers = "") {
  const scene::Scene s = sdl::parse_scene_string(R"(
    #version 3.7;
    global_settings { assumed_gamma 1 }
    camera { location <0, 0, -3> look_at 0 }
    light_source { <0, 0, -1000> rgb 1 }
    plane { z, 0 texture { )" + texture + " } " + object_modifiers +
                                                     R"( }
  )",
                                                 "average.pov", {});
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext context;
  return w.trace_camera_ray({{0, 0, -3}, {0, 0, 1}}, context);
}

TEST(AverageTexture, EachEntryIsLitWithItsOwnFinish) {
  const math::Color c = centre_of(R"(average texture_map {
      [1 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 }]
      [3 pigment { rgb <0, 0, 1> } finish { ambient 0 diffuse 0.5 }] })");
  EXPECT_NEAR(c.r, 64.0 / 255, 0.5 / 255);
  EXPECT_NEAR(c.r, 0.25, 1e-9);
  EXPECT_NEAR(c.g, 0.0, 1e-9);
  EXPECT_NEAR(c.b, 0.375, 1e-9);
}

TEST(AverageTexture, EntriesMoveWithTheTexture) {
  // A gradient entry shifted by the whole texture's translate reads frac(-0.25) = 0.75 at x = 0, weighted
  // 1/3: 0.25 (an entry left unmoved would read 0; the blended stand-in under the heavier entry's diffuse
  // 0.5 would give 0.125); the same when the object carrying the texture is moved.
  const char* average = R"(average texture_map {
      [1 pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 }]
      [2 pigment { rgb 0 } finish { ambient 0 diffuse 0.5 }] })";
  EXPECT_NEAR(centre_of(std::string(average) + " translate x * 0.25").g, 0.25, 1e-9);
  EXPECT_NEAR(centre_of(average, "translate x * 0.25").g, 0.25, 1e-9);
  EXPECT_NEAR(centre_of(average).g, 0.0, 1e-9);
}

}  // namespace
}  // namespace snell::render
