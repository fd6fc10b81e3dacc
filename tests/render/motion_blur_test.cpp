// Motion blur and the sampling modes through the whole renderer: a moving sphere's pixel against its
// analytic time-averaged coverage, shadow rays at the camera ray's time, and bit-identical images for 1 and
// 2 threads in every sampling mode.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "snell/accel/accelerator.hpp"
#include "snell/math/constants.hpp"
#include "snell/render/renderer.hpp"
#include "snell/sdl/parse.hpp"

namespace snell::render {
namespace {

scene::Scene parse(const std::string& text) {
  return sdl::parse_scene_string(text, "motion.pov", {});
}

RenderResult render(const scene::Scene& s, RenderOptions o, const char* accel = "bvh") {
  const auto a = accel::make_accelerator(accel, s);
  return Renderer(s, *a, std::move(o)).render();
}

/// Area of the part of the disc (centre (c, 0), radius r) with x >= a.
double disc_area_beyond(double c, double r, double a) {
  const double d = a - c;
  if (d <= -r) return math::kPi * r * r;
  if (d >= r) return 0;
  return r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d);
}

// One pixel seeing the square [-1,1]^2 through an orthographic camera; a flat white disc of radius 0.5
// crosses it during the shutter, its centre moving from x = -1.5 to x = 0.5.
constexpr const char* kCrossing = R"(
  camera { orthographic location <0,0,-5> look_at <0,0,0> right <2,0,0> up <0,2,0>
           shutter { open 0 close 1 samples 1024 } }
  sphere { <0,0,0>, 0.5 pigment { rgb 1 } finish { ambient 1 diffuse 0 }
           translate <-1.5,0,0> motion { translate <2,0,0> } }
)";

double expected_crossing_coverage() {
  // Time average of the disc's area inside the pixel, over the pixel's area 4 (midpoint rule).
  const int steps = 100000;
  double sum = 0;
  for (int i = 0; i < steps; ++i) {
    const double c = -1.5 + 2 * (i + 0.5) / steps;
    sum += disc_area_beyond(c, 0.5, -1) - disc_area_beyond(c, 0.5, 1);
  }
  return sum / steps / 4;
}

TEST(MotionBlur, MovingSphereCoversThePixelAsTheAnalyticAverage) {
  const scene::Scene s = parse(kCrossing);
  const double expected = expected_crossing_coverage();  // 0.1473...
  RenderOptions o;
  o.width = o.height = 1;
  for (const char* accel : {"none", "bvh", "grid", "octree"}) {
    const double got = render(s, o, accel).image.at(0, 0).r;
    EXPECT_NEAR(got, expected, 0.01) << accel;
  }
  // The same with --spp and each sampler (the shutter's own sample count is then unused).
  for (const char* sampler : {"sobol", "halton", "stratified"}) {
    o.samples_per_pixel = 4096;
    o.sampler = sampler;
    EXPECT_NEAR(render(s, o).image.at(0, 0).r, expected, 0.01) << sampler;
  }
  // A still sphere at its start position covers nothing: the blur comes from the motion.
  scene::Scene still = s;
  still.camera.shutter_close = 0;
  EXPECT_EQ(render(still, o).image.at(0, 0).r, 0.0);
}

TEST(MotionBlur, ShadowRaysSeeTheSceneAtTheCameraRaysTime) {
  // A blocker slides between the light and the floor point seen by the pixel only at time 1.
  const scene::Scene s = parse(R"(
    camera { orthographic location <0,5,0> look_at <0,0,0> right <0.01,0,0> up <0,0,0.01> }
    light_source { <0,10,0> rgb 1 }
    plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
    box { -0.5, 0.5 translate <-3,2,0> motion { translate <3,0,0> } }
  )");
  RenderOptions o;
  o.width = o.height = 1;
  o.time = 0;
  EXPECT_GT(render(s, o).image.at(0, 0).r, 0.5);
  o.time = 1;  // the camera ray and its shadow ray at time 1: the box is at the origin, above the point
  EXPECT_EQ(render(s, o).image.at(0, 0).r, 0.0);
}

TEST(MotionBlur, TextureMovesWithTheObject) {
  // A checker on a sliding plane-facing box: at time 1 the pattern seen through the pixel is the one that
  // was one unit to the left at time 0.
  const scene::Scene s = parse(R"(
    camera { orthographic location <0.5,0.5,-5> look_at <0.5,0.5,0> right <0.01,0,0> up <0,0.01,0> }
    box { <-5,-5,0>, <5,5,1> pigment { checker rgb 0, rgb 1 } finish { ambient 1 diffuse 0 }
          motion { translate <1,0,0> } }
  )");
  RenderOptions o;
  o.width = o.height = 1;
  const double at0 = render(s, o).image.at(0, 0).r;
  o.time = 1;
  const double at1 = render(s, o).image.at(0, 0).r;
  EXPECT_NE(at0, at1);
  EXPECT_EQ(at0 + at1, 1.0);
}

constexpr const char* kBusy = R"(
  camera { location <0,1,-4> look_at <0,0,0> SHUTTER FOCAL }
  light_source { <3,5,-4> rgb 1 }
  plane { y, -0.7 pigment { checker rgb 0.2, rgb 0.9 } }
  sphere { 0, 0.6 pigment { rgb <0.9,0.2,0.1> } finish { phong 0.8 reflection 0.2 }
           motion { key 0 translate -x*0.6 key 0.5 rotate y*60 key 1 translate x*0.6 } }
  box { -0.4, 0.4 pigment { rgb <0.2,0.8,0.3> } rotate y*30 motion { rotate y*90 } translate <1.2,0,1> }
)";

std::string busy(const std::string& shutter, const std::string& focal) {
  std::string text = kBusy;
  text.replace(text.find("SHUTTER"), 7, shutter);
  text.replace(text.find("FOCAL"), 5, focal);
  return text;
}

void expect_same_for_one_and_two_threads(const scene::Scene& s, RenderOptions o, const std::string& mode) {
  o.width = 40;
  o.height = 30;
  o.seed = 7;
  o.threads = 1;
  const RenderResult one = render(s, o);
  o.threads = 2;
  const RenderResult two = render(s, o);
  EXPECT_TRUE(one.image.rgb == two.image.rgb) << mode;
}

TEST(MotionBlur, ImagesAreIdenticalForOneAndTwoThreadsInEverySamplingMode) {
  const scene::Scene still = parse(busy("", ""));
  const scene::Scene moving = parse(busy("shutter { open 0 close 1 samples 6 }", ""));
  const scene::Scene both =
      parse(busy("shutter { open 0 close 1 }", "aperture 0.3 blur_samples 8 focal_point <0,0,0>"));
  const scene::Scene focal = parse(busy("", "aperture 0.3 blur_samples 8 focal_point <0,0,0>"));
  RenderOptions o;
  for (const char* sampler : {"sobol", "halton", "stratified"})
    for (const char* filter : {"box", "mitchell"}) {
      RenderOptions spp = o;
      spp.samples_per_pixel = 4;
      spp.sampler = sampler;
      spp.filter = filter;
      expect_same_for_one_and_two_threads(moving, spp, std::string("--spp ") + sampler + " " + filter);
    }
  RenderOptions am1 = o;
  am1.antialias = true;
  am1.jitter = true;
  expect_same_for_one_and_two_threads(still, am1, "+AM1 +J");
  RenderOptions am2 = am1;
  am2.aa_method = 2;
  expect_same_for_one_and_two_threads(still, am2, "+AM2 +J");
  expect_same_for_one_and_two_threads(moving, o, "motion blur");
  expect_same_for_one_and_two_threads(focal, o, "focal blur");
  expect_same_for_one_and_two_threads(both, o, "focal and motion blur");
}

TEST(MotionBlur, AdaptiveAntialiasingRefinesOnlyEdges) {
  // +AM2 on a flat background stays exactly the background; at an edge it mixes the two colours.
  const scene::Scene s = parse(R"(
    camera { orthographic location <0,0,-5> look_at <0,0,0> right <4,0,0> up <0,4,0> }
    background { rgb <0,0,1> }
    box { <-0.37,-5,0>, <5,5,1> pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }
  )");
  RenderOptions o;
  o.width = o.height = 4;
  o.antialias = true;
  o.aa_method = 2;
  o.aa_depth = 4;  // 3 levels: the edge pixel's coverage is found to 1/8 of a pixel
  const io::Image image = render(s, o).image;
  EXPECT_EQ(image.at(0, 0).b, 1.0);  // wholly background
  EXPECT_EQ(image.at(3, 0).r, 1.0);  // wholly box
  // Pixel 1 spans x in [-1, 0]: the box covers 0.37 of it.
  EXPECT_NEAR(image.at(1, 0).r, 0.37, 1.0 / 8);
  EXPECT_NEAR(image.at(1, 0).r + image.at(1, 0).b, 1.0, 1e-6);
}

TEST(MotionBlur, BadBlocksAreReportedWithTheirPlace) {
  const std::pair<const char*, const char*> cases[] = {
      {"sphere { 0, 1 motion { key 1 key 0.5 } }", "motion.pov:1:30: error: motion: key times must increase"},
      {"sphere { 0, 1 motion { } }", "motion.pov:1:15: error: motion needs a transform or at least one key"},
      {"sphere { 0, 1 motion { pigment { rgb 1 } } }",
       "motion.pov:1:24: error: unexpected 'pigment' in motion"},
      {"sphere { 0, 1 motion { translate x key 1 } }", "motion.pov:1:36: error: motion: 'key' cannot follow"},
      {"camera { shutter { open 1 close 0 } }",
       "motion.pov:1:10: error: shutter: close must not come before open"},
      {"camera { shutter { samples 0 } }", "motion.pov:1:"},
      {"camera { shutter { speed 2 } }", "motion.pov:1:20: error: unexpected 'speed' in shutter"},
  };
  for (const auto& [text, message] : cases) {
    try {
      parse(text);
      ADD_FAILURE() << "no error for " << text;
    } catch (const sdl::ParseError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace snell::render
