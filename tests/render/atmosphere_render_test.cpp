// Fog, media and area lights through the Whitted integrator, against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.hpp"
#include "snell/accel/accelerator.hpp"
#include "snell/render/whitted.hpp"

namespace snell::render {
namespace {

using math::Color;
using math::Vec3;

Color trace(const scene::Scene& s, const math::Ray& ray) {
  const auto accel = accel::make_accelerator("none", s);
  WhittedIntegrator w(s, *accel);
  TraceContext ctx;
  return w.trace_camera_ray(ray, ctx);
}

/// A white floor at y = 0 lit by diffuse 1 only, so its brightness is the light reaching it times N.L.
scene::Scene white_floor() {
  scene::Scene s;
  material::Finish f;
  f.ambient = Color(0);
  f.diffuse = 1;
  s.objects.push_back(
      test::object(std::make_shared<geometry::Plane>(Vec3(0, 1, 0), 0), test::texture({Color(1)}, f)));
  return s;
}

TEST(AtmosphereRenderTest, FogMixesTheSurfaceWithTheFogColour) {
  scene::Scene s;
  material::Finish glow;
  glow.ambient = Color(1);  // the wall shows its own colour, 1 x ambient_light 1
  s.objects.push_back(test::object(std::make_shared<geometry::Plane>(Vec3(0, 0, -1), -10),
                                   test::texture({Color(1, 0, 0)}, glow)));
  scene::Fog fog;
  fog.distance = 10;
  fog.color.rgb = Color(0, 0, 1);
  s.fogs.push_back(fog);
  const Color c = trace(s, {{0, 0, 0}, {0, 0, 1}});
  const double t = std::exp(-1.0);  // 10 units through fog of distance 10
  EXPECT_NEAR(c.r, t, 1e-9);
  EXPECT_NEAR(c.b, 1 - t, 1e-9);
}

TEST(AtmosphereRenderTest, CameraInsideASolidThatIsNotHollowSeesNoFog) {
  // POV-Ray starts camera rays inside the objects around the camera; fog applies only along rays inside
  // hollow ones. A clear sphere around the camera, then a glowing wall 10 away through fog of distance 10.
  auto make = [](bool hollow) {
    scene::Scene s;
    material::Finish glow;
    glow.ambient = Color(1);
    s.objects.push_back(test::object(std::make_shared<geometry::Plane>(Vec3(0, 0, -1), -10),
                                     test::texture({Color(1, 0, 0)}, glow)));
    auto shell = test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 100.0),
                              test::texture({Color(1), 0.0, 1.0}));
    shell->flags.hollow = hollow;
    s.objects.push_back(shell);
    scene::Fog fog;
    fog.distance = 10;
    s.fogs.push_back(fog);
    s.camera.location = {0, 0, 0};
    return s;
  };
  EXPECT_NEAR(trace(make(true), {{0, 0, 0}, {0, 0, 1}}).r, std::exp(-1.0), 1e-9);
  EXPECT_NEAR(trace(make(false), {{0, 0, 0}, {0, 0, 1}}).r, 1.0, 1e-9);
}

TEST(AtmosphereRenderTest, MediaAttenuationDimsLightThroughFog) {
  // Black fog of distance 10; the light 10 above the lit point reaches it thinned by exp(-1) only with
  // media_attenuation; the camera ray, sqrt(2) long, is thinned by exp(-sqrt(2) / 10) either way.
  scene::Scene s = white_floor();
  s.lights.push_back(test::point_light({0, 10, 0}));
  scene::Fog fog;
  fog.distance = 10;
  s.fogs.push_back(fog);
  const math::Ray ray{{0, 1, -1}, normalize(Vec3(0, -1, 1))};
  const double camera_fog = std::exp(-std::sqrt(2.0) / 10);
  EXPECT_NEAR(trace(s, ray).r, camera_fog, 1e-9);
  s.lights[0].media_attenuation = true;
  EXPECT_NEAR(trace(s, ray).r, std::exp(-1.0) * camera_fog, 1e-9);
}

TEST(AtmosphereRenderTest, ProjectedThroughLightsOnlyWhereItsRayCrossesTheObject) {
  scene::Scene s = white_floor();
  scene::Light light = test::point_light({0, 10, 0});
  // A small disc-like sphere 5 above the origin: the floor under it is lit, the floor 4 units aside is not.
  light.projected_through.push_back(
      test::object(std::make_shared<geometry::Sphere>(Vec3(0, 5, 0), 0.5), test::texture({Color(1)})));
  s.lights.push_back(light);
  EXPECT_NEAR(trace(s, {{0, 1, -1}, normalize(Vec3(0, -1, 1))}).r, 1.0, 1e-9);
  EXPECT_EQ(trace(s, {{4, 1, -1}, normalize(Vec3(0, -1, 1))}).r, 0.0);
}

TEST(AtmosphereRenderTest, EmittingMediaGlowsOnlyInsideHollowObjects) {
  // A clear sphere of radius 1 filled with emission 0.25: a ray through its centre gains 0.25 x 2.
  auto make = [](bool hollow) {
    scene::Scene s;
    material::Finish none;
    none.ambient = Color(0);
    none.diffuse = 0;
    auto sphere = test::object(std::make_shared<geometry::Sphere>(Vec3(0, 0, 0), 1.0),
                               test::texture({Color(1), 0.0, 1.0}, none));
    auto interior = std::make_shared<material::Interior>();
    material::Media m;
    m.emission = Color(0.25);
    interior->media.push_back(m);
    sphere->interior = interior;
    sphere->flags.hollow = hollow;
    s.objects.push_back(sphere);
    return s;
  };
  EXPECT_NEAR(trace(make(true), {{0, 0, -5}, {0, 0, 1}}).r, 0.5, 1e-6);
  EXPECT_NEAR(trace(make(false), {{0, 0, -5}, {0, 0, 1}}).r, 0.0, 1e-9);
}

TEST(AtmosphereRenderTest, AreaLightHalfHiddenByAnEdgeLightsHalf) {
  // A 9 x 9 area light 2 units wide, 10 above a point on the floor; an occluder's edge straight above the
  // point, halfway up, hides the grid columns with x < 0. Fully subdivided, POV-Ray's grid mean is the
  // trapezoid rule over the columns: 4.5 of 8 intervals lit.
  scene::Scene s = white_floor();
  // A huge sphere whose side, nearly flat there, passes just left of x = 0 at height 5.
  s.objects.push_back(test::object(std::make_shared<geometry::Sphere>(Vec3(-1000.0, 5, 0), 1000.0 - 1e-3),
                                   test::texture({Color(1)})));
  scene::Light light = test::point_light({0, 10, 0});
  light.area = true;
  light.axis1 = {2, 0, 0};
  light.axis2 = {0, 0, 2};
  light.size1 = light.size2 = 9;
  light.adaptive = 4;
  s.lights.push_back(light);
  const Color lit = trace(s, {{0, 1, -1}, normalize(Vec3(0, -1, 1))});
  s.objects.pop_back();
  const Color full = trace(s, {{0, 1, -1}, normalize(Vec3(0, -1, 1))});
  EXPECT_GT(full.r, 0.05);
  EXPECT_NEAR(lit.r / full.r, 4.5 / 8, 1e-9);
}

}  // namespace
}  // namespace snell::render
