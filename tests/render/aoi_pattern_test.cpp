// The `aoi` pattern sees the ray that met the surface (POV-Ray 3.7 pattern.cpp, AOIPattern: acos of the
// angle between the ray and the normal turned towards it, over pi). POV-Ray 3.7 renders this plane, seen
// at 60 degrees from its normal (camera at <-sqrt(3), 0, -1>, +W3 +H3 -A), with the centre pixel 213 of
// 255: sRGB of 2/3 = acos(-0.5)/pi. Head-on the value is 1 (POV-Ray gives 254-255 at a sphere's centre).
#include <gtest/gtest.h>

#include <cmath>

#include "snell/accel/accelerator.hpp"
#include "snell/render/whitted.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::render {
namespace {

math::Color seen(const math::Vec3& from) {
  const scene::Scene s = sdl::parse_scene_string(R"(
    #version 3.7;
    global_settings { assumed_gamma 1 }
    camera { location <0, 0, -3> look_at 0 }
    plane { z, 0 pigment { aoi color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } }
  )",
                                                 "aoi.pov", {});
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext context;
  return w.trace_camera_ray({from, normalize(-from)}, context);
}

TEST(AoiPattern, IsTheAngleOfIncidenceOverPi) {
  EXPECT_NEAR(seen({0, 0, -3}).r, 1.0, 1e-9);
  // POV-Ray's 213/255 back to linear: ((213/255 + 0.055) / 1.055)^2.4 = 0.6673.
  const double povray_linear = std::pow((213.0 / 255 + 0.055) / 1.055, 2.4);
  EXPECT_NEAR(seen({-std::sqrt(3.0), 0, -1}).r, 2.0 / 3.0, 1e-9);
  EXPECT_NEAR(seen({-std::sqrt(3.0), 0, -1}).r, povray_linear, 0.002);
  // From behind the plane the normal is turned to the ray as well: the same value.
  EXPECT_NEAR(seen({std::sqrt(3.0), 0, 1}).g, 2.0 / 3.0, 1e-9);
  EXPECT_NEAR(seen({-1, 0, -1}).b, 0.75, 1e-9);
}

}  // namespace
}  // namespace snell::render
