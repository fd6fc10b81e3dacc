// Layered textures are lit layer by layer with each layer's own finish (POV-Ray 3.7 trace.cpp,
// ComputeLightedTexture), and `texture { T finish {..} }` on a declared layered T changes only its top layer.
// The scene below, rendered by povray 3.7 (+W40 +H30, assumed_gamma 2.2, so 8-bit values are linear),
// gives the centre pixel (89, 0, 128): red 0.35 = (ambient 0.1 + diffuse 0.6) of the bottom layer's
// default finish seen through the top layer's transmit 0.5; blue 0.5 = the top layer's ambient 1 times its
// opacity 0.5. Lighting the stack with the top finish gave red 0.5 instead.
#include <gtest/gtest.h>

#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/render/whitted.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::render {
namespace {

TEST(LayeredTexture, EachLayerIsLitWithItsOwnFinish) {
  const scene::Scene s = sdl::parse_scene_string(R"(
    #version 3.7;
    global_settings { assumed_gamma 1 }
    camera { location <0, 0, -3> look_at 0 }
    light_source { <0, 0, -10> rgb 1 }
    #declare T = texture { pigment { rgb <1, 0, 0> } } texture { pigment { rgbt <0, 0, 1, 0.5> } }
    plane { z, 0 texture { T finish { ambient 1 diffuse 0 } } }
  )",
                                                 "layers.pov", {});
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext context;
  const math::Color c = w.trace_camera_ray({{0, 0, -3}, {0, 0, 1}}, context);
  EXPECT_NEAR(c.r, 0.35, 1e-9);
  EXPECT_NEAR(c.g, 0.0, 1e-9);
  EXPECT_NEAR(c.b, 0.5, 1e-9);
}

// POV-Ray tests each light's shadow once per shaded point, however many layers or texture entries are lit
// there (trace.cpp: lightColorCache, one level per ComputeTextureColour): the primary ray below hits a
// three-layer plane lit by two lights, so it traces two shadow rays, not six, and a reflection shades a
// second point with its own two.
TEST(LayeredTexture, EachLightIsShadowTestedOncePerPoint) {
  const auto shadow_rays = [](const std::string& texture) {
    const scene::Scene s = sdl::parse_scene_string(R"(
      #version 3.7;
      global_settings { assumed_gamma 1 }
      camera { location <0, 0, -3> look_at 0 }
      light_source { <0, 0, -10> rgb 1 }
      light_source { <3, 2, -10> rgb 1 }
      plane { z, 0 texture { )" + texture + R"( } }
      sphere { <0, 0, -20>, 1 pigment { rgb 1 } }
    )",
                                                   "lit_once.pov", {});
    const auto accel = accel::make_accelerator("none", s);
    WhittedIntegrator w(s, *accel);
    TraceContext context;
    w.trace_camera_ray({{0, 0, -3}, {0, 0, 1}}, context);
    return context.counters.shadow;
  };
  EXPECT_EQ(shadow_rays("pigment { rgb 1 }"), 2u);
  // Layers listed bottom first: both upper ones let the lower ones show.
  EXPECT_EQ(shadow_rays("pigment { rgb 1 } } texture { pigment { rgbt <0, 1, 0, 0.5> } } "
                        "texture { pigment { rgbt <1, 0, 0, 0.5> }"),
            2u);
  // Halfway between two map entries, each lit with its own finish.
  EXPECT_EQ(shadow_rays("gradient x texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0.5 } "
                        "finish { phong 1 }] } translate -0.5*x"),
            2u);
  EXPECT_EQ(shadow_rays("average texture_map { [1 pigment { rgb 1 }] [1 pigment { rgb 0.5 }] }"), 2u);
  // The mirror sees the sphere behind the camera: a second point, its own two shadow rays.
  EXPECT_EQ(shadow_rays("pigment { rgb 1 } finish { reflection 1 } } texture { pigment { rgbt 0.5 }"), 4u);
}

}  // namespace
}  // namespace snell::render
