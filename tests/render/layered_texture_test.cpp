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

}  // namespace
}  // namespace snell::render
